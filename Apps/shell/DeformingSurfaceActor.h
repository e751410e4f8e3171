// A tissue's surface drawn as it deforms (Documentation/Tissue.md): one object's triangles, as
// the scene's surface actor draws them, whose points a window moves to where the solid's newest
// step left them, in place, without building the actor again.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionScene.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

class vtkPolyData;

namespace proxima::shell
{

/// Object `object` of a scene, drawn in the scene surface's colour and shading, with points that
/// move.
class DeformingSurfaceActor
{
public:
  /// The object as `scene` has it (at rest).
  DeformingSurfaceActor(const CollisionScene& scene, std::uint32_t object);
  /// The scene object drawn.
  std::uint32_t object() const { return m_object; }
  /// The actor to add to a renderer.
  vtkActor* actor() const { return m_actor; }
  /// Moves the surface's points to `points` (the object mesh's points, in order, in the scene's
  /// frame; another count is ignored and returns false). Its normals follow at the next render.
  bool movePoints(const std::vector<Vec3>& points);

private:
  std::uint32_t m_object;
  vtkSmartPointer<vtkPolyData> m_surface;
  vtkSmartPointer<vtkActor> m_actor;
};

} // namespace proxima::shell
