#include "Overlay/ProbeOverlay.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <vector>

namespace proxima::inspector
{
namespace
{
vtkSmartPointer<vtkPolyData> ballsAt(const std::vector<Vec3>& centres, double radius)
{
  vtkNew<vtkAppendPolyData> balls;
  vtkNew<vtkPolyData> none;
  balls->AddInputData(none);
  for (const Vec3& centre : centres)
  {
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(centre.x, centre.y, centre.z);
    ball->SetRadius(radius);
    ball->SetThetaResolution(16);
    ball->SetPhiResolution(12);
    ball->Update();
    balls->AddInputData(ball->GetOutput());
  }
  balls->Update();
  return balls->GetOutput();
}

vtkSmartPointer<vtkPolyData> polyline(const std::vector<Vec3>& points, bool joined)
{
  vtkNew<vtkPoints> at;
  vtkNew<vtkCellArray> lines;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    at->InsertNextPoint(points[i].x, points[i].y, points[i].z);
    if (i > 0 && (joined || i % 2 == 1))
    {
      const vtkIdType ends[2] = {static_cast<vtkIdType>(i - 1), static_cast<vtkIdType>(i)};
      lines->InsertNextCell(2, ends);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(at);
  data->SetLines(lines);
  return data;
}

void replace(vtkRenderer* renderer, vtkSmartPointer<vtkActor>& actor, vtkPolyData* data, double r,
             double g, double b)
{
  if (actor)
  {
    renderer->RemoveActor(actor);
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetLineWidth(3.0);
  renderer->AddActor(actor);
}
} // namespace

ProbeOverlay::ProbeOverlay(vtkRenderer* renderer, double markerRadius)
  : m_renderer(renderer)
  , m_markerRadius(markerRadius)
{}

ProbeOverlay::~ProbeOverlay()
{
  for (vtkActor* actor : {m_markers.Get(), m_distances.Get(), m_stops.Get(), m_gap.Get()})
  {
    if (actor != nullptr)
    {
      m_renderer->RemoveActor(actor);
    }
  }
}

void ProbeOverlay::setMarkerRadius(double radius)
{
  m_markerRadius = radius;
  m_markersDrawn = ~std::size_t{0};
  m_stopsDrawn = ~std::size_t{0};
}

void ProbeOverlay::update(const ProbeMeasurements& measurements)
{
  if (measurements.markers.size() != m_markersDrawn)
  {
    std::vector<Vec3> points;
    for (const ProbeMarker& marker : measurements.markers)
    {
      points.push_back(marker.point);
    }
    replace(m_renderer, m_markers, ballsAt(points, m_markerRadius), 0.2, 0.9, 0.3);
    replace(m_renderer, m_distances, polyline(points, true), 1.0, 1.0, 1.0);
    m_markersDrawn = measurements.markers.size();
  }
  if (measurements.stops.size() != m_stopsDrawn)
  {
    std::vector<Vec3> points;
    for (const ProbeStop& stop : measurements.stops)
    {
      points.push_back(stop.proxy);
    }
    replace(m_renderer, m_stops, ballsAt(points, 0.5 * m_markerRadius), 0.95, 0.2, 0.15);
    m_stopsDrawn = measurements.stops.size();
  }
  const double gap = measurements.narrowestGap ? measurements.narrowestGap->width : 0.0;
  if (gap != m_gapDrawn)
  {
    std::vector<Vec3> ends;
    if (measurements.narrowestGap)
    {
      ends = {measurements.narrowestGap->wall, measurements.narrowestGap->across};
    }
    replace(m_renderer, m_gap, polyline(ends, false), 0.2, 0.9, 0.95);
    m_gapDrawn = gap;
  }
}

} // namespace proxima::inspector
