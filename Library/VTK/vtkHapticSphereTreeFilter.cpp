#include "VTK/vtkHapticSphereTreeFilter.h"

#include "VTK/PolyDataCollisionObject.h"
#include "VTK/Private/SphereTessellation.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <exception>
#include <vector>

vtkStandardNewMacro(vtkHapticSphereTreeFilter);

bool vtkHapticSphereTreeFilter::TreeIsStale(vtkDataObject* input) const
{
  return !m_object || input != m_builtFromInput || input->GetMTime() != m_builtFromInputTime ||
         this->Scale != m_builtScale || this->LeafSizeFactor != m_builtLeafSizeFactor ||
         this->MaxLeafSpheresPerNode != m_builtMaxLeafSpheres;
}

int vtkHapticSphereTreeFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                           vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("No input or output poly data.");
    return 0;
  }

  // The tree build is one call into the kernel with no progress callback of its own: progress
  // moves between the stages, and an abort is honoured before the build and before drawing.
  m_treeBuildMilliseconds = 0.0;
  if (this->TreeIsStale(input))
  {
    this->UpdateProgress(0.0);
    proxima::vtk::PolyDataObjectSettings settings;
    settings.scale = this->Scale;
    settings.tree.leafSizeFactor = this->LeafSizeFactor;
    settings.tree.maxLeafSpheresPerNode = static_cast<std::uint32_t>(this->MaxLeafSpheresPerNode);
    settings.tree.numBuildThreads = this->ParallelTreeBuild ? 0u : 1u;
    proxima::vtk::PolyDataObjectReport report;
    try
    {
      m_object = std::make_shared<const proxima::CollisionObject>(
        proxima::vtk::buildCollisionObject(input, this->GetClassName(), settings, &report));
    }
    catch (const std::exception& error)
    {
      // The previous tree, if any, stays: a bad edit upstream does not take the model away.
      vtkErrorMacro("Cannot build a sphere tree: " << error.what());
      return 0;
    }
    m_builtFromInput = input;
    m_builtFromInputTime = input->GetMTime();
    m_builtScale = this->Scale;
    m_builtLeafSizeFactor = this->LeafSizeFactor;
    m_builtMaxLeafSpheres = this->MaxLeafSpheresPerNode;
    m_treeBuildMilliseconds = report.treeBuildMilliseconds;
  }
  this->UpdateProgress(0.8);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  const proxima::SphereTree& tree = m_object->tree;
  const std::vector<proxima::Sphere> spheres =
    this->DrawLeafSpheres ? tree.leafSpheresInWorld()
                          : tree.spheresAtLevel(static_cast<std::uint32_t>(this->Level));
  const auto numSpheres = static_cast<vtkIdType>(spheres.size());

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  vtkNew<vtkIdTypeArray> connectivity;
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkDoubleArray> radii;
  radii->SetName("Radius");
  const int resolution = this->SphereResolution;
  const vtkIdType numTriangles = numSpheres * proxima::vtk::detail::trianglesPerSphere(resolution);
  coordinates->SetNumberOfTuples(numSpheres * proxima::vtk::detail::pointsPerSphere(resolution));
  connectivity->SetNumberOfValues(3 * numTriangles);
  offsets->SetNumberOfValues(numTriangles + 1);
  radii->SetNumberOfValues(numTriangles);
  proxima::vtk::detail::tessellateSpheres(spheres, resolution, coordinates->GetPointer(0),
                                          connectivity->GetPointer(0), radii->GetPointer(0));
  for (vtkIdType t = 0; t <= numTriangles; ++t)
  {
    offsets->SetValue(t, 3 * t);
  }

  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->SetScalars(radii);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHapticSphereTreeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "DrawLeafSpheres: " << (this->DrawLeafSpheres ? "On" : "Off") << "\n";
  os << indent << "SphereResolution: " << this->SphereResolution << "\n";
  os << indent << "LeafSizeFactor: " << this->LeafSizeFactor << "\n";
  os << indent << "MaxLeafSpheresPerNode: " << this->MaxLeafSpheresPerNode << "\n";
  os << indent << "ParallelTreeBuild: " << (this->ParallelTreeBuild ? "On" : "Off") << "\n";
  os << indent << "Tree: ";
  if (m_object)
  {
    os << m_object->mesh.numTriangles() << " triangles, " << m_object->tree.numNodes()
       << " nodes, depth " << m_object->tree.depth() << "\n";
  }
  else
  {
    os << "(none)\n";
  }
}
