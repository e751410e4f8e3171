#include "ProxyCamera.h"

#include <vtkCamera.h>

namespace proxima::shell
{

namespace
{
Aabb sceneBox(const CollisionScene& scene)
{
  Aabb box;
  for (const CollisionObject& object : scene.objects)
  {
    box.expand(object.mesh.bounds().lower);
    box.expand(object.mesh.bounds().upper);
  }
  return box;
}
} // namespace

Vec3 startAboveScene(const CollisionScene& scene, double radius)
{
  const Aabb box = sceneBox(scene);
  const Vec3 centre = (box.lower + box.upper) * 0.5;
  return {centre.x, centre.y, box.upper.z + 2.0 * radius};
}

Vec3 startFacingCamera(const CollisionScene& scene, vtkCamera* camera, double radius)
{
  const Aabb box = sceneBox(scene);
  const Vec3 centre = (box.lower + box.upper) * 0.5;
  double position[3];
  double focus[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focus);
  Vec3 towardCamera{position[0] - focus[0], position[1] - focus[1], position[2] - focus[2]};
  towardCamera = towardCamera / norm(towardCamera);
  return centre + towardCamera * (0.5 * norm(box.upper - box.lower) + 2.0 * radius);
}

void followProxy(vtkCamera* camera, const Vec3& proxy)
{
  double focus[3];
  double position[3];
  camera->GetFocalPoint(focus);
  camera->GetPosition(position);
  constexpr double kEase = 0.25;
  const Vec3 shift = (proxy - Vec3{focus[0], focus[1], focus[2]}) * kEase;
  camera->SetFocalPoint(focus[0] + shift.x, focus[1] + shift.y, focus[2] + shift.z);
  camera->SetPosition(position[0] + shift.x, position[1] + shift.y, position[2] + shift.z);
}

} // namespace proxima::shell
