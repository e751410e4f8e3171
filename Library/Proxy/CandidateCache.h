// Temporal coherence for the proxy: the triangles within radius + margin of a centre, gathered
// from the sphere trees once and reused while the proxy stays near that centre. A query whose
// reach lies inside the cached ball is answered from this short list exactly as the trees would
// answer it (same triangles, same first contact); any other query goes to the trees.
#pragma once

#include "Geometry/SphereTree.h"
#include "Proxy/CollisionScene.h"

#include <cstdint>

namespace proxima
{

class CandidateCache
{
public:
  static constexpr int kCapacity = 512;

  /// Forgets the cached ball (after a scene change).
  void invalidate() { m_valid = false; }
  bool valid() const { return m_valid; }
  const Vec3& center() const { return m_center; }
  int size() const { return m_count; }

  /// Takes every triangle within `reach` of `center` from the scene's trees (those whose leaf
  /// spheres reach that far: a superset). Leaves the cache invalid if more than kCapacity do.
  void rebuild(const CollisionScene& scene, const Vec3& center, double reach,
               SphereTreeScratch& scratch, QueryStats& stats);

  /// True if every triangle within `distance` of `point` is in the cache.
  bool coversBall(const Vec3& point, double distance) const
  {
    return m_valid && norm(point - m_center) + distance <= m_reach;
  }

  /// Every cached triangle within `maxDistance` of `point`; returns the count, writes at most
  /// `capacity`. Call only when coversBall(point, maxDistance).
  std::uint32_t gatherWithin(const CollisionScene& scene, const Vec3& point, double maxDistance,
                             NearbyTriangle* out, std::uint32_t* outObjects,
                             std::uint32_t capacity, QueryStats& stats) const;

  /// First contact of the sweep among cached triangles. Call only when both ends of the sweep
  /// are covered with the sweep's radius + skin.
  SweepContact firstContact(const CollisionScene& scene, const SweepQuery& query,
                            QueryStats& stats) const;

private:
  bool m_valid = false;
  Vec3 m_center;
  double m_reach = 0.0;
  int m_count = 0;
  // Structure of arrays: the rejection test reads only the spheres.
  double m_sphereX[kCapacity];
  double m_sphereY[kCapacity];
  double m_sphereZ[kCapacity];
  double m_sphereRadius[kCapacity];
  std::uint32_t m_object[kCapacity];
  std::uint32_t m_triangle[kCapacity];
};

} // namespace proxima
