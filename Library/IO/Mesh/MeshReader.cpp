#include "IO/Mesh/MeshReader.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/PolyDataToSoup.h"
#include "IO/Mesh/Private/FormatSignatures.h"
#include "IO/Mesh/Private/GltfChecks.h"
#include "IO/Mesh/Private/ObjReader.h"
#include "IO/Mesh/Private/OffReader.h"
#include "IO/Mesh/Private/PlyReader.h"
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtpChecks.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

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

  vtkSmartPointer<vtkPolyData> data;
  switch (*format)
  {
    case MeshFileFormat::Off: data = detail::readOffWithOpenMesh(path); break;
    case MeshFileFormat::Ply: data = detail::readPly(path, fileSize); break;
    case MeshFileFormat::Obj: data = detail::readObj(path); break;
    case MeshFileFormat::Vtp:
      // vtkXMLPolyDataReader leaks its points on a Points array without three components.
      detail::checkVtpPoints(path);
      data = detail::readWithVtk(path, *format);
      break;
    case MeshFileFormat::Gltf:
    {
      // VTK's loader trusts the file's lengths and indices (a SEGV on a fuzzed GLB): ours first,
      // and then VTK reads the checked document's geometry, not the file itself.
      const detail::GltfGeometryFile geometry = detail::checkGltfAndCopyGeometry(path, fileSize);
      data = detail::readGltfWithVtk(geometry.path(), path);
      break;
    }
    default: data = detail::readWithVtk(path, *format); break;
  }
  return polyDataToSoup(data, path, scale);
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
