#include "IO/TissueMeshing/TetMeshFile.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputError.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <string>

namespace proxima
{

void writeTetMeshFile(const std::string& path, const TetMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble(); // the solver's coordinates, unrounded
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    const Vec3& p = mesh.points[i];
    points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(mesh.tets.size()));
  for (const auto& tet : mesh.tets)
  {
    const vtkIdType corners[4] = {tet[0], tet[1], tet[2], tet[3]};
    grid->InsertNextCell(VTK_TETRA, 4, corners);
  }
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  // Into memory, then through AtomicOutputFile: never a half-written file under the target name.
  writer->WriteToOutputStringOn();
  if (writer->Write() != 1)
  {
    throw OutputError::cannotWrite(path, "VTK could not encode the tetrahedra");
  }
  AtomicOutputFile file(path);
  file.write(writer->GetOutputString());
  file.commit();
}

TetMesh readTetMeshFile(const std::string& path)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
  {
    throw InputError(path, "cannot open the file (no such regular file)");
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  if (reader->CanReadFile(path.c_str()) == 0)
  {
    throw InputError(path, "not a VTK XML unstructured grid (.vtu) file");
  }
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (grid == nullptr || grid->GetNumberOfCells() == 0)
  {
    throw InputError(path, "the file has no tetrahedra");
  }
  TetMesh mesh;
  mesh.points.reserve(static_cast<std::size_t>(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    const Vec3 point{p[0], p[1], p[2]};
    if (!isFinite(point))
    {
      throw InputError(path, "point " + std::to_string(i) + " is not finite");
    }
    mesh.points.push_back(point);
  }
  vtkNew<vtkIdList> corners;
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell)
  {
    if (grid->GetCellType(cell) != VTK_TETRA)
    {
      throw InputError(path, "cell " + std::to_string(cell) +
                               " is not a tetrahedron (only VTK_TETRA cells are read)");
    }
    grid->GetCellPoints(cell, corners);
    mesh.tets.push_back({static_cast<std::uint32_t>(corners->GetId(0)),
                         static_cast<std::uint32_t>(corners->GetId(1)),
                         static_cast<std::uint32_t>(corners->GetId(2)),
                         static_cast<std::uint32_t>(corners->GetId(3))});
  }
  return mesh;
}

} // namespace proxima
