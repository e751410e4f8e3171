#include "Proxy/CandidateCache.h"

#include "Geometry/SweptSphere.h"

#include <algorithm>
#include <cmath>

namespace proxima
{

void CandidateCache::rebuild(const CollisionScene& scene, const Vec3& center, double reach,
                             SphereTreeScratch& scratch, QueryStats& stats)
{
  m_valid = false;
  m_count = 0;
  for (std::uint32_t objectIndex = 0; objectIndex < scene.objects.size(); ++objectIndex)
  {
    const CollisionObject& object = scene.objects[objectIndex];
    // Leaf-sphere candidates, a superset of the triangles within reach: every query on the cache
    // makes its own exact test, so the rebuild needs none.
    const auto room = static_cast<std::uint32_t>(kCapacity - m_count);
    const std::uint32_t found =
      object.tree.candidatesWithin(center, reach, m_triangle + m_count, room, scratch, &stats);
    if (found > room)
    {
      return; // too crowded to help: the trees answer everything
    }
    for (std::uint32_t i = 0; i < found; ++i)
    {
      const TriangleCorners& c = object.mesh.corners(m_triangle[m_count]);
      const Vec3 centroid = (c.a + c.b + c.c) / 3.0;
      const double radius = std::sqrt(std::max({squaredDistance(centroid, c.a),
                                                squaredDistance(centroid, c.b),
                                                squaredDistance(centroid, c.c)}));
      m_sphereX[m_count] = centroid.x;
      m_sphereY[m_count] = centroid.y;
      m_sphereZ[m_count] = centroid.z;
      // A hair larger, so that the double rounding of the rejection test never drops a
      // triangle that touches exactly.
      m_sphereRadius[m_count] = radius * (1.0 + 1e-12) + 1e-300;
      m_object[m_count] = objectIndex;
      ++m_count;
    }
  }
  m_center = center;
  m_reach = reach;
  m_valid = true;
}

std::uint32_t CandidateCache::gatherWithin(const CollisionScene& scene, const Vec3& point,
                                           double maxDistance, NearbyTriangle* out,
                                           std::uint32_t* outObjects, std::uint32_t capacity,
                                           QueryStats& stats) const
{
  std::uint32_t found = 0;
  const double maxDistanceSquared = maxDistance * maxDistance;
  for (int i = 0; i < m_count; ++i)
  {
    const double dx = m_sphereX[i] - point.x;
    const double dy = m_sphereY[i] - point.y;
    const double dz = m_sphereZ[i] - point.z;
    const double reach = m_sphereRadius[i] + maxDistance;
    if (dx * dx + dy * dy + dz * dz > reach * reach)
    {
      continue;
    }
    ++stats.trianglesTested;
    const TriangleCorners& c = scene.objects[m_object[i]].mesh.corners(m_triangle[i]);
    const ClosestPointResult closest = closestPointOnTriangle(point, c.a, c.b, c.c);
    if (closest.squaredDistance <= maxDistanceSquared)
    {
      if (found < capacity)
      {
        out[found] = NearbyTriangle{m_triangle[i], closest};
        outObjects[found] = m_object[i];
      }
      ++found;
    }
  }
  return found;
}

SweepContact CandidateCache::firstContact(const CollisionScene& scene, const SweepQuery& query,
                                          QueryStats& stats) const
{
  SweepContact best;
  const Vec3 motion = query.end - query.start;
  const double motionSquared = dot(motion, motion);
  const double beyond = query.radius + query.skin;
  for (int i = 0; i < m_count; ++i)
  {
    // Distance from the triangle's sphere centre to the part of the path before the best contact.
    const Vec3 toCenter = Vec3{m_sphereX[i], m_sphereY[i], m_sphereZ[i]} - query.start;
    const double limit = best.t;
    double s = motionSquared > 0.0 ? dot(toCenter, motion) / motionSquared : 0.0;
    s = s < 0.0 ? 0.0 : (s > limit ? limit : s);
    const double reach = m_sphereRadius[i] + beyond;
    if (squaredDistance(toCenter, motion * s) > reach * reach)
    {
      continue;
    }
    ++stats.trianglesTested;
    const TriangleCorners& c = scene.objects[m_object[i]].mesh.corners(m_triangle[i]);
    const SweepResult hit = sweepSphereTriangleWithSkin(query.start, motion, query.radius,
                                                        query.skin, c);
    if (hit.hit && (!best.hit || hit.t < best.t))
    {
      best.hit = true;
      best.t = hit.t;
      best.triangle = m_triangle[i];
    }
  }
  return best;
}

} // namespace proxima
