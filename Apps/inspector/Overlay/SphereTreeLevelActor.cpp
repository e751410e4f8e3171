#include "Overlay/SphereTreeLevelActor.h"

#include <vtkActor.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3D.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include <algorithm>

namespace proxima::inspector
{

vtkSmartPointer<vtkActor> makeSphereTreeLevelActor(const CollisionScene& scene, std::uint32_t level,
                                                   std::size_t& spheres)
{
  vtkNew<vtkPoints> centres;
  vtkNew<vtkDoubleArray> diameters;
  diameters->SetName("diameter");
  for (const CollisionObject& object : scene.objects)
  {
    for (const Sphere& sphere : object.tree.spheresAtLevel(level))
    {
      centres->InsertNextPoint(sphere.center.x, sphere.center.y, sphere.center.z);
      diameters->InsertNextValue(2.0 * sphere.radius);
    }
  }
  spheres = static_cast<std::size_t>(centres->GetNumberOfPoints());
  vtkNew<vtkPolyData> at;
  at->SetPoints(centres);
  at->GetPointData()->SetScalars(diameters);
  // A unit-diameter ball scaled by each sphere's diameter.
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.5);
  ball->SetThetaResolution(12);
  ball->SetPhiResolution(8);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(at);
  glyphs->SetSourceConnection(ball->GetOutputPort());
  glyphs->SetScaleModeToScaleByScalar();
  glyphs->SetScaleFactor(1.0);
  glyphs->SetColorModeToColorByScale();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToWireframe();
  actor->GetProperty()->SetColor(0.95, 0.8, 0.3);
  actor->GetProperty()->SetOpacity(0.35);
  actor->GetProperty()->LightingOff();
  return actor;
}

std::uint32_t sphereTreeDepth(const CollisionScene& scene)
{
  std::uint32_t depth = 0;
  for (const CollisionObject& object : scene.objects)
  {
    depth = std::max(depth, object.tree.depth());
  }
  return depth;
}

} // namespace proxima::inspector
