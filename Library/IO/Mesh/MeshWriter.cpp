#include "IO/Mesh/MeshWriter.h"

#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/Private/VtkMessageCapture.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
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

template <class Writer>
void runWriter(Writer* writer, vtkPolyData* data, const std::string& path)
{
  detail::VtkMessageCapture capture;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  const int ok = writer->Write();
  if (ok != 1 || writer->GetErrorCode() != 0 || capture.hasErrors())
  {
    throw InputError(path, "cannot write the file (" +
                             (capture.bestMessage().empty() ? std::string("VTK writer failed")
                                                            : capture.bestMessage()) +
                             ")");
  }
}
} // namespace

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
  const std::optional<MeshFileFormat> format = meshFileFormatFromPath(path);
  if (!format || *format == MeshFileFormat::Gltf || *format == MeshFileFormat::Off)
  {
    throw InputError(path, "cannot write this format (write .obj, .stl, .ply or .vtp)");
  }
  {
    // Ask the system first: VTK's writers say little more than "cannot open".
    std::ofstream probe(path, std::ios::binary | std::ios::app);
    if (!probe)
    {
      throw InputError(path, std::string("cannot write the file (") + std::strerror(errno) + ")");
    }
  }
  vtkSmartPointer<vtkPolyData> data = toPolyData(soup);
  switch (*format)
  {
    case MeshFileFormat::Obj:
    {
      vtkNew<vtkOBJWriter> writer;
      runWriter(writer.Get(), data, path);
      return;
    }
    case MeshFileFormat::Stl:
    {
      vtkNew<vtkSTLWriter> writer;
      writer->SetFileTypeToBinary();
      runWriter(writer.Get(), data, path);
      return;
    }
    case MeshFileFormat::Ply:
    {
      vtkNew<vtkPLYWriter> writer;
      writer->SetFileTypeToBinary();
      runWriter(writer.Get(), data, path);
      return;
    }
    case MeshFileFormat::Vtp:
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetDataModeToBinary();
      runWriter(writer.Get(), data, path);
      return;
    }
    case MeshFileFormat::Gltf:
    case MeshFileFormat::Off: break;
  }
}

} // namespace proxima
