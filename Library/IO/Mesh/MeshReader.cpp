#include "IO/Mesh/MeshReader.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/Private/FormatSignatures.h"
#include "IO/Mesh/Private/GltfChecks.h"
#include "IO/Mesh/Private/ObjReader.h"
#include "IO/Mesh/Private/OffReader.h"
#include "IO/Mesh/Private/PlyReader.h"
#include "IO/Mesh/Private/PolygonsToTriangles.h"
#include "IO/Mesh/Private/VtkOnUse.h"
#include "IO/Mesh/Private/VtpChecks.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace proxima
{

TriangleSoup readMeshFile(const std::string& path, double scale)
{
  if (!(std::isfinite(scale) && scale > 0.0))
  {
    std::ostringstream out;
    out << "mesh scale must be a positive finite number, not " << scale;
    throw std::invalid_argument(out.str());
  }
  const std::optional<MeshFileFormat> format = meshFileFormatFromPath(path);
  if (!format)
  {
    const std::string extension = std::filesystem::path(path).extension().string();
    throw InputError(path, (extension.empty() ? std::string("no file extension")
                                              : "unsupported file extension '" + extension + "'") +
                             " (mesh files: " + readableMeshExtensions() + ")");
  }
  const std::uintmax_t fileSize = detail::requireReadableFile(path);
  detail::checkSignature(path, *format, fileSize);

  // OBJ, PLY and OFF are read into plain C++ and converted here, without VTK; STL, VTP and glTF
  // are read by VTK in its module, which hands back the soup polyDataToSoup makes.
  switch (*format)
  {
    case MeshFileFormat::Off:
      return detail::polygonsToTriangles(detail::readOffWithOpenMesh(path), path, scale);
    case MeshFileFormat::Ply:
      return detail::polygonsToTriangles(detail::readPly(path, fileSize), path, scale);
    case MeshFileFormat::Obj:
      return detail::polygonsToTriangles(detail::readObj(path), path, scale);
    case MeshFileFormat::Vtp:
      // vtkXMLPolyDataReader leaks its points on a Points array without three components, and
      // allocates whatever sizes the file declares.
      detail::checkVtpPoints(path);
      detail::checkVtpDeclaredSizes(path);
      return detail::readSoupWithVtk(path, *format, scale);
    case MeshFileFormat::Gltf:
    {
      // VTK's loader trusts the file's lengths and indices (a SEGV on a fuzzed GLB): ours first,
      // and then VTK reads the checked document's geometry, not the file itself.
      const detail::GltfGeometryFile geometry = detail::checkGltfAndCopyGeometry(path, fileSize);
      return detail::readGltfSoupWithVtk(geometry.path(), path, scale);
    }
    default: return detail::readSoupWithVtk(path, *format, scale);
  }
}

TriangleMesh loadTriangleMesh(const std::string& path, double scale)
{
  return buildTriangleMesh(readMeshFile(path, scale), path);
}

TriangleMesh buildTriangleMesh(TriangleSoup soup, const std::string& path)
{
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(std::move(soup), error))
  {
    throw InputError(path, error.message);
  }
  return mesh;
}

} // namespace proxima
