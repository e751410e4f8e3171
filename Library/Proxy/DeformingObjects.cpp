#include "Proxy/DeformingObjects.h"

#include <algorithm>

namespace proxima
{
namespace
{
// A tenth of the mesh's median edge: small against the triangles, large against the motion of
// one simulation step of a tissue (micrometres to a few tenths of a millimetre).
double refitMarginOf(const TriangleMesh& mesh)
{
  std::vector<double> edges;
  edges.reserve(mesh.numTriangles());
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    edges.push_back(distance(mesh.corners(t).a, mesh.corners(t).b));
  }
  if (edges.empty())
  {
    return 0.0;
  }
  auto middle = edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2);
  std::nth_element(edges.begin(), middle, edges.end());
  return 0.1 * *middle;
}
} // namespace

std::unique_ptr<DeformingObjectSet> makeDeformingObjects(const CollisionScene& scene,
                                                         const std::vector<std::uint32_t>& objects)
{
  auto set = std::make_unique<DeformingObjectSet>();
  set->indexOfObject.assign(scene.objects.size(), -1);
  for (const std::uint32_t object : objects)
  {
    if (object >= scene.objects.size() || set->indexOfObject[object] >= 0)
    {
      continue;
    }
    set->indexOfObject[object] = static_cast<int>(set->entries.size());
    DeformingObjectSet::Entry entry;
    entry.object = object;
    entry.current.mesh = scene.objects[object].mesh;
    entry.current.material = scene.objects[object].material;
    SphereTreeOptions options;
    options.leafSizeFactor = 0.0;
    entry.current.buildQueries(options);
    entry.pending = entry.current.mesh.points();
    entry.refitMargin = refitMarginOf(entry.current.mesh);
    set->entries.push_back(std::move(entry));
  }
  return set;
}
} // namespace proxima
