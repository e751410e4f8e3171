#include "IO/Scene/SceneTissue.h"

#include "IO/InputChecks/InputError.h"
#include "Core/Aabb.h"
#include "IO/InputChecks/ParameterRanges.h"

#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
bool insideBox(const Vec3& p, const Vec3& low, const Vec3& high)
{
  return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y && p.z >= low.z &&
         p.z <= high.z;
}

std::string objectWhere(std::uint32_t object)
{
  return "objects[" + std::to_string(object) + "].tissue";
}

std::string sceneName(const LoadedScene& loaded, std::uint32_t object)
{
  return loaded.description.path.empty() ? loaded.description.objects[object].mesh
                                         : loaded.description.path;
}
} // namespace

std::unique_ptr<TissueDynamics> buildSceneTissue(const LoadedScene& loaded, double kp, double rate)
{
  if (loaded.tissues.empty())
  {
    return nullptr;
  }
  std::vector<TissueObject> tissues;
  for (const LoadedTissue& built : loaded.tissues)
  {
    const SceneTissue& given = loaded.description.objects[built.object].tissue;
    TissueObject tissue;
    tissue.object = built.object;
    tissue.tets = built.tets;
    tissue.settings.density = given.density;
    tissue.settings.damping = given.damping;
    const ElasticMaterial base{given.youngsModulus, given.poissonRatio};
    tissue.materials.assign(built.tets.tets.size(), base);
    for (std::size_t t = 0; t < built.tets.tets.size(); ++t)
    {
      const auto& corner = built.tets.tets[t];
      const Vec3 centroid = (built.tets.points[corner[0]] + built.tets.points[corner[1]] +
                             built.tets.points[corner[2]] + built.tets.points[corner[3]]) *
                            0.25;
      for (const SceneInclusion& inclusion : given.inclusions)
      {
        if (distance(centroid, inclusion.center) <= inclusion.radius)
        {
          tissue.materials[t].youngsModulus = inclusion.youngsModulus;
        }
      }
    }
    for (std::uint32_t v = 0; v < built.tets.points.size(); ++v)
    {
      if (insideBox(built.tets.points[v], given.fixedLow, given.fixedHigh))
      {
        tissue.fixedVertices.push_back(v);
      }
    }
    if (tissue.fixedVertices.empty())
    {
      // A solid held nowhere would drift off under the finger.
      Aabb bounds;
      for (const Vec3& point : built.tets.points)
      {
        bounds.expand(point);
      }
      throw InputError(sceneName(loaded, built.object),
                       objectWhere(built.object) + ".fixed.box: holds none of the " +
                         std::to_string(built.tets.points.size()) +
                         " vertices of the tissue's tetrahedra (they span x " +
                         shortNumber(bounds.lower.x) + " to " + shortNumber(bounds.upper.x) +
                         ", y " + shortNumber(bounds.lower.y) + " to " +
                         shortNumber(bounds.upper.y) + ", z " + shortNumber(bounds.lower.z) +
                         " to " + shortNumber(bounds.upper.z) + " m, in the scene's frame)");
    }
    tissues.push_back(std::move(tissue));
  }
  try
  {
    return std::make_unique<TissueDynamics>(std::move(tissues), kp, rate);
  }
  catch (const std::invalid_argument& refused)
  {
    throw InputError(sceneName(loaded, loaded.tissues.front().object),
                     objectWhere(loaded.tissues.front().object) + ": " + refused.what());
  }
}

} // namespace proxima
