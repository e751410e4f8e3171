// The defects of a part drawn on it (the inspector's window, Documentation/CadInspector.md):
// boundary edges (the holes' rims) in red, non-manifold edges in magenta, misoriented edges in
// yellow, self-intersecting and folded triangles in orange, and where the tool cannot reach in translucent
// blue. Every defect the inspection listed is drawn (the window asks it to list them all).
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/MeshInspection/MeshInspection.h"
#include "IO/MeshInspection/ToolReach.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace proxima::inspector
{

class DefectOverlay
{
public:
  explicit DefectOverlay(vtkRenderer* renderer);
  ~DefectOverlay();
  DefectOverlay(const DefectOverlay&) = delete;
  DefectOverlay& operator=(const DefectOverlay&) = delete;

  /// Draws `inspection`'s listed defects on `soup`.
  void showDefects(const TriangleSoup& soup, const MeshInspection& inspection);
  /// Draws the triangles a tool cannot reach (replacing those of another radius).
  void showReach(const TriangleSoup& soup, const ToolReach& reach);
  void setDefectsVisible(bool visible);
  void setReachVisible(bool visible);

  /// What is drawn, for the tests: lines per kind of edge, triangles per kind.
  struct Drawn
  {
    long long boundaryEdges = 0;
    long long nonManifoldEdges = 0;
    long long misorientedEdges = 0;
    long long selfIntersectingTriangles = 0;
    long long unreachableTriangles = 0;
  };
  Drawn drawn() const;

private:
  vtkRenderer* m_renderer;
  vtkSmartPointer<vtkActor> m_boundary;
  vtkSmartPointer<vtkActor> m_nonManifold;
  vtkSmartPointer<vtkActor> m_misoriented;
  vtkSmartPointer<vtkActor> m_selfIntersecting;
  vtkSmartPointer<vtkActor> m_unreachable;
  bool m_defectsVisible = true;
  bool m_reachVisible = true;
};

} // namespace proxima::inspector
