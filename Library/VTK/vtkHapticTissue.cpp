#include "VTK/vtkHapticTissue.h"

#include "VTK/ScenePolyData.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <utility>

vtkStandardNewMacro(vtkHapticTissue);

vtkHapticTissue::vtkHapticTissue()
{
  this->SetNumberOfInputPorts(0);
}

vtkHapticTissue::~vtkHapticTissue() = default;

void vtkHapticTissue::SetTissue(std::shared_ptr<proxima::TissueDynamics> tissue,
                                std::shared_ptr<const proxima::CollisionScene> scene, int index)
{
  m_tissue = std::move(tissue);
  m_scene = std::move(scene);
  m_index = index;
  m_atRest = nullptr;
  m_stepDrawn = 0;
  if (m_tissue != nullptr && m_scene != nullptr)
  {
    if (index < 0 || static_cast<std::size_t>(index) >= m_tissue->numTissues() ||
        m_tissue->object(static_cast<std::size_t>(index)) >= m_scene->objects.size())
    {
      vtkErrorMacro("SetTissue: " << index << " is not one of the " << m_tissue->numTissues()
                                  << " tissues of the scene.");
      m_tissue = nullptr;
    }
    else
    {
      // The object alone, as vtkHapticScene's output draws it (its "ObjectId" kept).
      proxima::CollisionScene one;
      one.addObject(m_scene->objects.shared(m_tissue->object(static_cast<std::size_t>(index))));
      m_atRest = proxima::vtk::scenePolyData(one);
    }
  }
  this->Modified();
}

bool vtkHapticTissue::TakeNewestStep()
{
  if (m_tissue == nullptr)
  {
    return false;
  }
  m_tissue->takeSurfaces();
  if (m_tissue->latestSurfaces().steps == m_stepDrawn)
  {
    return false;
  }
  this->Modified();
  return true;
}

int vtkHapticTissue::RequestData(vtkInformation*, vtkInformationVector**,
                                 vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (m_tissue == nullptr || m_atRest == nullptr)
  {
    output->Initialize();
    return 1;
  }
  const proxima::TissueDynamics::Surfaces& surfaces = m_tissue->latestSurfaces();
  const std::vector<proxima::Vec3>& points = surfaces.points[static_cast<std::size_t>(m_index)];
  if (static_cast<vtkIdType>(points.size()) != m_atRest->GetNumberOfPoints())
  {
    vtkErrorMacro("The tissue's solid has " << points.size() << " points, its object "
                                            << m_atRest->GetNumberOfPoints() << ".");
    return 0;
  }
  // The triangles and cell data are shared with the surface at rest; the points are new, so
  // the last output (which a mapper may still hold) is never changed under it.
  output->CopyStructure(m_atRest);
  output->GetCellData()->PassData(m_atRest->GetCellData());
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    coordinates->SetTuple3(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
  }
  vtkNew<vtkPoints> moved;
  moved->SetData(coordinates);
  output->SetPoints(moved);
  m_stepDrawn = surfaces.steps;
  return 1;
}

void vtkHapticTissue::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tissue: " << (m_tissue != nullptr ? std::to_string(m_index) : "(none)") << "\n";
  os << indent << "StepDrawn: " << m_stepDrawn << "\n";
}
