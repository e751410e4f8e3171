#include "IO/Mesh/MeshWriter.h"

#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/Private/VtkMessageCapture.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputError.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkAlgorithm.h>
#include <vtkXMLPolyDataWriter.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace proxima
{
namespace
{
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSoup& soup)
{
  const auto numPoints = static_cast<vtkIdType>(soup.points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    const Vec3& p = soup.points[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(soup.triangles.size()),
                           3 * static_cast<vtkIdType>(soup.triangles.size()));
  for (const auto& t : soup.triangles)
  {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  if (!soup.pointNormals.empty())
  {
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      const Vec3& n = soup.pointNormals[static_cast<std::size_t>(i)];
      normals->SetTuple3(i, n.x, n.y, n.z);
    }
    data->GetPointData()->SetNormals(normals);
  }
  if (!soup.texCoords.empty())
  {
    vtkNew<vtkDoubleArray> texCoords;
    texCoords->SetName("TCoords");
    texCoords->SetNumberOfComponents(2);
    texCoords->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      const TexCoord& t = soup.texCoords[static_cast<std::size_t>(i)];
      texCoords->SetTuple2(i, t.u, t.v);
    }
    data->GetPointData()->SetTCoords(texCoords);
  }
  return data;
}

/// Throws OutputError for `target` when VTK reported an error while writing.
void checkWriter(vtkAlgorithm* writer, int result, const detail::VtkMessageCapture& capture,
                 const std::string& target)
{
  if (result != 1 || writer->GetErrorCode() != 0 || capture.hasErrors())
  {
    throw OutputError::cannotWrite(target, capture.bestMessage().empty()
                                             ? std::string("VTK's writer failed")
                                             : capture.bestMessage());
  }
}

/// The bytes of a writer that can write into memory (VTK XML): nothing touches the disk
/// until they go to the target through AtomicOutputFile.
template <class Writer>
std::string writeToMemory(Writer* writer, vtkPolyData* data, const std::string& target)
{
  detail::VtkMessageCapture capture;
  writer->SetInputData(data);
  writer->WriteToOutputStringOn();
  const int result = writer->Write();
  checkWriter(writer, result, capture, target);
  return writer->GetOutputString();
}

/// A file of our own in the temporary folder, removed when this goes: VTK's OBJ, STL and PLY
/// writers only write to a named file.
class ScratchFile
{
public:
  /// `suffix` is the format's extension: VTK's PLY writer adds ".ply" to a name without it.
  ScratchFile(const std::string& target, const std::string& suffix)
  {
    std::string pattern =
      (std::filesystem::temp_directory_path() / ("proxima-mesh-XXXXXX" + suffix)).string();
    const int descriptor = ::mkostemps(pattern.data(), static_cast<int>(suffix.size()), O_CLOEXEC);
    if (descriptor < 0)
    {
      throw OutputError::cannotWrite(target, std::string("cannot make a scratch file: ") +
                                               std::strerror(errno));
    }
    ::close(descriptor);
    m_path = pattern;
  }
  ~ScratchFile() { ::unlink(m_path.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::string& path() const { return m_path; }

  std::string contents() const
  {
    std::ifstream file(m_path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
  }

  /// Why the writer stopped short: VTK's OBJ writer ignores a failed write, so ask the system by
  /// adding one byte where it stopped (a full disk says ENOSPC, a file-size limit EFBIG).
  std::string reasonForShortFile() const
  {
    const int descriptor = ::open(m_path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (descriptor < 0)
    {
      return std::strerror(errno);
    }
    const ssize_t written = ::write(descriptor, "\n", 1);
    const int error = errno;
    ::close(descriptor);
    return written < 0 ? std::strerror(error) : std::string("the writer stopped short");
  }

private:
  std::string m_path;
};

/// A complete OBJ from VTK's writer: one "v" line per point and one "f" line per triangle, the
/// last line ended. A writer that hit a full disk stops short of that and still returns success.
bool isCompleteObj(const std::string& bytes, const TriangleSoup& soup)
{
  if (bytes.empty() || bytes.back() != '\n')
  {
    return false;
  }
  std::size_t numVertexLines = 0;
  std::size_t numFaceLines = 0;
  std::size_t lineStart = 0;
  while (lineStart < bytes.size())
  {
    if (bytes.compare(lineStart, 2, "v ") == 0)
    {
      ++numVertexLines;
    }
    else if (bytes.compare(lineStart, 2, "f ") == 0)
    {
      ++numFaceLines;
    }
    lineStart = bytes.find('\n', lineStart) + 1;
  }
  return numVertexLines == soup.points.size() && numFaceLines == soup.triangles.size();
}

/// A complete binary STL: an 80-byte header, a 4-byte count, 50 bytes per triangle.
bool isCompleteBinaryStl(const std::string& bytes, const TriangleSoup& soup)
{
  return bytes.size() == 84 + 50 * soup.triangles.size();
}

std::size_t plyTypeBytes(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
  {
    return 1;
  }
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
  {
    return 2;
  }
  if (type == "double" || type == "float64")
  {
    return 8;
  }
  return 4;
}

/// A complete binary PLY of triangles: its header, then exactly the bytes its elements declare
/// (a face being a count and three indices), with one vertex per point and one face per
/// triangle.
bool isCompleteBinaryPly(const std::string& bytes, const TriangleSoup& soup)
{
  const std::string endHeader = "end_header\n";
  const std::size_t headerEnd = bytes.find(endHeader);
  if (headerEnd == std::string::npos)
  {
    return false;
  }
  std::istringstream header(bytes.substr(0, headerEnd));
  std::string line;
  std::size_t expectedBytes = headerEnd + endHeader.size();
  std::size_t elementCount = 0;
  std::size_t elementBytes = 0;
  const auto closeElement = [&] { expectedBytes += elementCount * elementBytes; };
  while (std::getline(header, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "element")
    {
      closeElement();
      std::string name;
      words >> name >> elementCount;
      elementBytes = 0;
      const std::size_t wanted = name == "vertex" ? soup.points.size()
                                 : name == "face" ? soup.triangles.size()
                                                  : elementCount;
      if (elementCount != wanted)
      {
        return false;
      }
    }
    else if (keyword == "property")
    {
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType;
        std::string itemType;
        words >> countType >> itemType;
        elementBytes += plyTypeBytes(countType) + 3 * plyTypeBytes(itemType);
      }
      else
      {
        elementBytes += plyTypeBytes(type);
      }
    }
  }
  closeElement();
  return bytes.size() == expectedBytes;
}

/// The bytes of a writer that only writes to a named file, through a scratch file, checked
/// complete by `isComplete` (never trusting the writer's success on a full disk).
template <class Writer>
std::string writeThroughScratchFile(Writer* writer, vtkPolyData* data, const std::string& target,
                                    const TriangleSoup& soup, const std::string& suffix,
                                    bool (*isComplete)(const std::string&, const TriangleSoup&))
{
  ScratchFile scratch(target, suffix);
  detail::VtkMessageCapture capture;
  writer->SetInputData(data);
  writer->SetFileName(scratch.path().c_str());
  errno = 0;
  const int result = writer->Write();
  const int writeError = errno;
  if (writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError && writeError != 0)
  {
    // VTK's STL writer sees a full disk and deletes the file, in words of its own: the
    // system's are the ones the user can act on.
    throw OutputError::cannotWrite(target, std::strerror(writeError));
  }
  checkWriter(writer, result, capture, target);
  std::string bytes = scratch.contents();
  if (!isComplete(bytes, soup))
  {
    throw OutputError::cannotWrite(target, scratch.reasonForShortFile());
  }
  return bytes;
}
} // namespace

bool isWritableMeshFormat(const std::string& path)
{
  const std::optional<MeshFileFormat> format = meshFileFormatFromPath(path);
  return format && *format != MeshFileFormat::Gltf && *format != MeshFileFormat::Off;
}

void writeMeshFile(const std::string& path, const TriangleSoup& soup)
{
  if ((!soup.pointNormals.empty() && soup.pointNormals.size() != soup.points.size()) ||
      (!soup.texCoords.empty() && soup.texCoords.size() != soup.points.size()))
  {
    throw std::invalid_argument("writeMeshFile: normals or texture coordinates do not match the "
                                "points one to one");
  }
  for (const auto& t : soup.triangles)
  {
    if (t[0] >= soup.points.size() || t[1] >= soup.points.size() || t[2] >= soup.points.size())
    {
      throw std::invalid_argument("writeMeshFile: a triangle refers to a point out of range");
    }
  }
  if (!isWritableMeshFormat(path))
  {
    throw InputError(path, kWritableMeshFormatsMessage);
  }
  const std::optional<MeshFileFormat> format = meshFileFormatFromPath(path);
  // Opened first: a missing folder or a read-only one is said before any work, in the system's
  // words, and nothing reaches the target until every byte is there.
  AtomicOutputFile file(path);
  vtkSmartPointer<vtkPolyData> data = toPolyData(soup);
  std::string bytes;
  switch (*format)
  {
    case MeshFileFormat::Obj:
    {
      vtkNew<vtkOBJWriter> writer;
      bytes = writeThroughScratchFile(writer.Get(), data, path, soup, ".obj", isCompleteObj);
      break;
    }
    case MeshFileFormat::Stl:
    {
      vtkNew<vtkSTLWriter> writer;
      writer->SetFileTypeToBinary();
      bytes = writeThroughScratchFile(writer.Get(), data, path, soup, ".stl", isCompleteBinaryStl);
      break;
    }
    case MeshFileFormat::Ply:
    {
      // VTK 9.1's PLY writer leaves its output string empty: through a file, as OBJ and STL.
      vtkNew<vtkPLYWriter> writer;
      writer->SetFileTypeToBinary();
      bytes = writeThroughScratchFile(writer.Get(), data, path, soup, ".ply", isCompleteBinaryPly);
      break;
    }
    case MeshFileFormat::Vtp:
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetDataModeToBinary();
      bytes = writeToMemory(writer.Get(), data, path);
      break;
    }
    case MeshFileFormat::Gltf:
    case MeshFileFormat::Off: break;
  }
  file.write(bytes);
  file.commit();
}

} // namespace proxima
