#include "Tissue/DeformedScene.h"

#include <memory>

namespace proxima
{

CollisionScene deformedScene(const CollisionScene& scene, const TissueDynamics& tissue)
{
  CollisionScene drawn;
  drawn.objects.reserve(scene.objects.size());
  for (std::size_t object = 0; object < scene.objects.size(); ++object)
  {
    CollisionObjectList::Pointer pointer = scene.objects.shared(object);
    for (std::size_t k = 0; k < tissue.numTissues(); ++k)
    {
      if (tissue.object(k) != object)
      {
        continue;
      }
      auto moved = std::make_shared<CollisionObject>();
      moved->mesh = scene.objects[object].mesh;
      moved->material = scene.objects[object].material;
      const std::vector<Vec3>& points = tissue.surface(k);
      if (moved->mesh.movePoints(points.data(), points.size()))
      {
        pointer = std::move(moved);
      }
      break;
    }
    drawn.addObject(std::move(pointer));
  }
  return drawn;
}

} // namespace proxima
