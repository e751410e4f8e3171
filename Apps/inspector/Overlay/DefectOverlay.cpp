#include "Overlay/DefectOverlay.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <set>
#include <vector>

namespace proxima::inspector
{
namespace
{
struct Colour
{
  double r, g, b;
};

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* data, const Colour& colour)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  // Drawn over the part's own surface, which they lie on.
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2.0, -2.0);
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-4.0, -4.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkActor> edgesActor(const DefectCount& edges, const Colour& colour)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const DefectLocation& edge : edges.first)
  {
    const vtkIdType a =
      points->InsertNextPoint(edge.edgeStart.x, edge.edgeStart.y, edge.edgeStart.z);
    const vtkIdType b = points->InsertNextPoint(edge.edgeEnd.x, edge.edgeEnd.y, edge.edgeEnd.z);
    const vtkIdType ends[2] = {a, b};
    lines->InsertNextCell(2, ends);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  auto actor = actorOf(data, colour);
  actor->GetProperty()->SetLineWidth(3.0);
  return actor;
}

vtkSmartPointer<vtkActor> trianglesActor(const TriangleSoup& soup,
                                         const std::vector<std::uint32_t>& triangles,
                                         const Colour& colour, double opacity)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (const std::uint32_t t : triangles)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& p = soup.points[soup.triangles[t][k]];
      ids[k] = points->InsertNextPoint(p.x, p.y, p.z);
    }
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(polys);
  auto actor = actorOf(data, colour);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

long long cellsOf(const vtkSmartPointer<vtkActor>& actor)
{
  if (!actor)
  {
    return 0;
  }
  return static_cast<long long>(
    vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput())->GetNumberOfCells());
}
} // namespace

DefectOverlay::DefectOverlay(vtkRenderer* renderer)
  : m_renderer(renderer)
{}

DefectOverlay::~DefectOverlay()
{
  for (vtkActor* actor : {m_boundary.Get(), m_nonManifold.Get(), m_misoriented.Get(),
                          m_selfIntersecting.Get(), m_unreachable.Get()})
  {
    if (actor != nullptr)
    {
      m_renderer->RemoveActor(actor);
    }
  }
}

void DefectOverlay::showDefects(const TriangleSoup& soup, const MeshInspection& inspection)
{
  for (vtkActor* actor :
       {m_boundary.Get(), m_nonManifold.Get(), m_misoriented.Get(), m_selfIntersecting.Get()})
  {
    if (actor != nullptr)
    {
      m_renderer->RemoveActor(actor);
    }
  }
  m_boundary = edgesActor(inspection.boundaryEdges, {0.95, 0.15, 0.1});
  m_nonManifold = edgesActor(inspection.nonManifoldEdges, {0.9, 0.2, 0.9});
  m_misoriented = edgesActor(inspection.misorientedEdges, {0.95, 0.85, 0.1});
  // Both triangles of each crossing or folded pair, once each.
  std::set<std::uint32_t> crossing;
  for (const DefectCount* pairs : {&inspection.selfIntersections, &inspection.folds})
  {
    for (const DefectLocation& pair : pairs->first)
    {
      crossing.insert(pair.triangle);
      crossing.insert(pair.other);
    }
  }
  m_selfIntersecting = trianglesActor(
    soup, std::vector<std::uint32_t>(crossing.begin(), crossing.end()), {1.0, 0.55, 0.0}, 1.0);
  for (vtkActor* actor :
       {m_boundary.Get(), m_nonManifold.Get(), m_misoriented.Get(), m_selfIntersecting.Get()})
  {
    actor->SetVisibility(m_defectsVisible);
    m_renderer->AddActor(actor);
  }
}

void DefectOverlay::showReach(const TriangleSoup& soup, const ToolReach& reach)
{
  if (m_unreachable)
  {
    m_renderer->RemoveActor(m_unreachable);
  }
  m_unreachable = trianglesActor(soup, reach.unreachableTriangles, {0.2, 0.45, 1.0}, 0.75);
  m_unreachable->SetVisibility(m_reachVisible);
  m_renderer->AddActor(m_unreachable);
}

void DefectOverlay::setDefectsVisible(bool visible)
{
  m_defectsVisible = visible;
  for (vtkActor* actor :
       {m_boundary.Get(), m_nonManifold.Get(), m_misoriented.Get(), m_selfIntersecting.Get()})
  {
    if (actor != nullptr)
    {
      actor->SetVisibility(visible);
    }
  }
}

void DefectOverlay::setReachVisible(bool visible)
{
  m_reachVisible = visible;
  if (m_unreachable)
  {
    m_unreachable->SetVisibility(visible);
  }
}

DefectOverlay::Drawn DefectOverlay::drawn() const
{
  return {cellsOf(m_boundary), cellsOf(m_nonManifold), cellsOf(m_misoriented),
          cellsOf(m_selfIntersecting), cellsOf(m_unreachable)};
}

} // namespace proxima::inspector
