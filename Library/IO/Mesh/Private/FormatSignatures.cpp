#include "IO/Mesh/Private/FormatSignatures.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/Private/AsciiStlCheck.h"

#include <algorithm>
#include <cstring>

namespace proxima::detail
{
namespace
{
void checkStl(const std::string& path, std::uintmax_t fileSize)
{
  const std::string head = readFileHead(path, 512);
  // An ASCII STL starts with "solid"; binary ones may too (in their 80-byte header), so the bytes
  // that follow decide, by the rule VTK's reader applies: its choice is what must be checked.
  if (vtkReadsStlAsAscii(head))
  {
    checkAsciiStl(path);
    return;
  }
  if (fileSize < 84)
  {
    throw InputError(path, "not an STL file: too short for a binary STL header (" +
                             std::to_string(fileSize) + " bytes, needs 84)");
  }
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, sizeof(count)); // little-endian, as the format says
  const std::uintmax_t needed = 84 + 50 * static_cast<std::uintmax_t>(count);
  if (fileSize < needed)
  {
    throw InputError(path, "not a valid binary STL file: its header announces " +
                             std::to_string(count) + " triangles (" + std::to_string(needed) +
                             " bytes) but the file has " + std::to_string(fileSize) + " bytes");
  }
  if (count == 0)
  {
    throw InputError(path, "no triangles (the binary STL header announces 0)");
  }
}
} // namespace

void checkSignature(const std::string& path, MeshFileFormat format, std::uintmax_t fileSize)
{
  switch (format)
  {
    case MeshFileFormat::Stl: checkStl(path, fileSize); return;
    case MeshFileFormat::Ply:
      if (readFileHead(path, 4).rfind("ply", 0) != 0)
      {
        throw InputError(path, "not a PLY file (it does not start with 'ply')");
      }
      return;
    case MeshFileFormat::Vtp:
    {
      const std::string head = trimmedHead(readFileHead(path, 64));
      if (head.rfind("<?xml", 0) != 0 && head.rfind("<VTKFile", 0) != 0)
      {
        throw InputError(path, "not a VTK XML file (it does not start with '<?xml' or '<VTKFile')");
      }
      return;
    }
    case MeshFileFormat::Gltf:
    {
      const std::string head = readFileHead(path, 64);
      if (head.rfind("glTF", 0) != 0 && trimmedHead(head).rfind("{", 0) != 0)
      {
        throw InputError(path, "not a glTF file (neither the binary 'glTF' magic nor JSON)");
      }
      return;
    }
    case MeshFileFormat::Obj:
    case MeshFileFormat::Off: return;
  }
}

} // namespace proxima::detail
