// Temporal coherence for the proxy: the triangles within radius + margin of a centre, gathered
// from the sphere trees once and reused while the proxy stays near that centre. A query whose
// reach lies inside the cached ball is answered from this short list exactly as the trees would
// answer it (same triangles, same first contact, ties broken by the same rule); any other query
// goes to the trees.
//
// A proxy resting on a surface is within reach of every triangle's bounding sphere for a
// proxy radius around it, so the sphere test alone let hundreds of triangles through to the exact
// test when the proxy is large against the triangles (r = 2 mm on 0.5 mm edges). A triangle's
// points lie in its plane, so the distance from a point at height h above that plane to the
// triangle is at least sqrt(h^2 + l^2), where l is the distance in the plane to the triangle's
// bounding circle: a triangle under a proxy sliding along its neighbours (h ~ r) is reached only
// where the proxy passes right over it.
#pragma once

#include "Geometry/SphereTree.h"
#include "Geometry/SweptSphere.h"
#include "Proxy/CollisionScene.h"

#include <cstdint>

namespace proxima
{

/// The first contact of a sweep among the objects of a scene. Ties in t go to the lowest object
/// index, then the lowest triangle index: the trees' rule (SphereTree::firstContact within an
/// object, ProxySolver's loop over the objects in order), whatever order the triangles are tested.
struct SceneContact
{
  /// True when the sweep meets a triangle.
  bool hit = false;
  /// Fraction of the sweep travelled at first contact (1 without a hit).
  double t = 1.0;
  /// Index of the object met, in CollisionScene::objects; 0 without a hit.
  std::uint32_t object = 0;
  /// Index of the triangle met, in that object's mesh; 0 without a hit.
  std::uint32_t triangle = 0;
};

/// The triangles of a scene within a ball around the proxy, gathered once from the sphere trees
/// and reused while the proxy's queries stay inside the ball, with the same answers as the trees.
/// One per solver: its const queries update mutable hints, so no two threads may share one.
class CandidateCache
{
public:
  /// The most triangles the cache holds; a ball that reaches more leaves it invalid.
  static constexpr int kCapacity = 512;

  /// Forgets the cached ball (after a scene change).
  void invalidate() { m_valid = false; }
  /// True when the cache holds every triangle within reach() of center().
  bool valid() const { return m_valid; }
  /// Centre of the cached ball (m), in the scene's frame.
  const Vec3& center() const { return m_center; }
  /// The radius of the cached ball.
  double reach() const { return m_reach; }
  /// Number of triangles cached by the last rebuild() (all of them only when valid()).
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

  /// Forgets the closest points and separating planes that gatherWithin keeps for later queries
  /// (the geometry may have moved since: the solver calls it when its planes are invalid).
  void forgetClosestPoints() const;

  /// Every cached triangle within `maxDistance` of `point`; returns the count, writes at most
  /// `capacity`. Call only when coversBall(point, maxDistance). The closest points it finds are
  /// kept until the next gather elsewhere, forgetClosestPoints or rebuild: a sweep from `point`
  /// (the update stage gathers the contact planes where the move stage's sweep starts) takes
  /// them instead of asking again, with the same answer bit for bit. Each closest point also
  /// gives a plane that separates its triangle from the point (through the closest point, normal
  /// toward the point), kept until forgetClosestPoints or rebuild: a point's height over it is a
  /// lower bound on the point's distance to the triangle, so a later gather or sweep that the
  /// plane keeps beyond reach needs no exact test of that triangle.
  std::uint32_t gatherWithin(const CollisionScene& scene, const Vec3& point, double maxDistance,
                             NearbyTriangle* out, std::uint32_t* outObjects, std::uint32_t capacity,
                             QueryStats& stats) const;

  /// How much of the sweep from `start` to `end` (as a fraction of it, 0 to 1) stays within the
  /// cache's cover with `distance` around it; 0 when the start is not covered.
  double coveredFraction(const Vec3& start, const Vec3& end, double distance) const;

  /// First contact of the sweep among cached triangles at a fraction t <= `covered` of the sweep,
  /// which must be covered up to there with the sweep's radius + skin (coveredFraction): then the
  /// trees would find this contact too, and no earlier one. No hit means none up to `covered`.
  /// The triangle that stopped the last sweep is tested first: a proxy creeping along a surface
  /// is stopped by the same triangle sweep after sweep, and once its contact bounds the sweep,
  /// the filters reject the triangles beyond it without their exact test; the order changes no
  /// answer, as ties follow SceneContact's rule.
  SceneContact firstContact(const CollisionScene& scene, const SweepQuery& query, double covered,
                            QueryStats& stats) const;

private:
  /// A new generation of closest points (a gather elsewhere); the separating planes stay.
  void startClosestPoints() const;
  /// Forgets cached triangle `i`'s separating plane.
  void forgetSeparatingPlane(int i) const;
  /// Keeps the plane that separates cached triangle `i` from `point`, whose closest point on it
  /// is `closest`, at that squared distance.
  void keepSeparatingPlane(int i, const Vec3& point, const Vec3& closest,
                           double squaredDistance) const;
  /// The height of `point` over cached triangle `i`'s separating plane: at most its distance to
  /// the triangle (minus infinity without a plane).
  double separatingHeight(int i, const Vec3& point) const;
  /// True when the segment from `start` along `motion` provably stays farther than `reach` from
  /// cached triangle `i` up to the fraction `bound` of it, by its separating plane.
  bool clearUntil(int i, const Vec3& start, const Vec3& motion, double reach, double bound) const;
  /// Whether cached triangle `i` can come within `reach` of the segment from `start` along
  /// `motion` (of squared length `motionSquared`): its bounding sphere, then its plane and its
  /// bounding circle in that plane. Never false for a triangle the exact test would find. A
  /// point is the segment with zero motion.
  bool mayReachSegment(int i, const Vec3& start, const Vec3& motion, double motionSquared,
                       double reach) const;
  /// The cached triangles that mayReachSegment accepts for the point `point` (zero motion), into
  /// `out`; returns how many. The gather's filter: all of mayReachSegment's tests in the one pass.
  int trianglesNearPoint(const Vec3& point, double reach, int* out) const;
  /// The cached triangles that mayReachSegment accepts for the segment from `start` along
  /// `motion`, into `out`; returns how many. The sweep's filter, as trianglesNearPoint.
  int trianglesNearSegment(const Vec3& start, const Vec3& motion, double reach, int* out) const;
  /// Keeps those of the `count` cached triangles in `candidates` that the segment from `start`
  /// along `motion` (zero for a point) may come within `reach` of by their edges' half-spaces:
  /// a triangle lies inside each of the three half-spaces bounded by an edge, across the edge
  /// from the triangle, and a point within `reach` of it lies within `reach` of each. Returns
  /// how many are kept, in order. The second filter after the scans above, on their few
  /// survivors: a sliver's bounding circle is as long as the sliver, so a fan of slivers passes
  /// the circle test wherever the fan is, and this test keeps only the slivers the query is
  /// beside.
  /// Only triangles larger than `reach` are tested (a smaller one passed the sphere test only
  /// where this passes too, nearly always); their half-spaces are made the first time.
  int keepNearEdges(const CollisionScene& scene, const Vec3& start, const Vec3& motion,
                    double reach, int* candidates, int count) const;
  /// The half-spaces of cached triangle `i`'s edges, for keepNearEdges.
  void makeEdges(const CollisionScene& scene, int i) const;

  bool m_valid = false;
  Vec3 m_center;
  double m_reach = 0.0;
  int m_count = 0;
  // Structure of arrays: the rejection test reads only the spheres.
  double m_sphereX[kCapacity];
  double m_sphereY[kCapacity];
  double m_sphereZ[kCapacity];
  double m_sphereRadius[kCapacity];
  // Each triangle's plane: unit normal and offset (n . x = offset in the plane; a zero normal for
  // a triangle with no area, whose tests then fall back to the sphere), and how far rounding may
  // put a corner off that plane.
  double m_normalX[kCapacity];
  double m_normalY[kCapacity];
  double m_normalZ[kCapacity];
  double m_planeOffset[kCapacity];
  double m_planeSlack[kCapacity];
  // Each triangle's edges: the unit normal of edge k in the triangle's plane, pointing away from
  // the triangle, and its offset (m . x <= offset on the triangle), with the rounding slack of
  // the three (zero normals for a triangle without area, which then always pass). Made on first
  // use by a query (makeEdges), so mutable: they change no answer, only how fast it comes.
  mutable double m_edgeX[3][kCapacity];
  mutable double m_edgeY[3][kCapacity];
  mutable double m_edgeZ[3][kCapacity];
  mutable double m_edgeOffset[3][kCapacity];
  mutable double m_edgeSlack[kCapacity];
  mutable bool m_edgesMade[kCapacity];
  std::uint32_t m_object[kCapacity];
  std::uint32_t m_triangle[kCapacity];
  /// The cached triangle of the last sweep's contact, or -1 (a hint for the next sweep's order:
  /// mutable, as it changes no answer).
  mutable int m_lastBlocker = -1;
  // The closest point of cached triangle i to m_closestFrom where m_closestStamp[i] is
  // m_closestGeneration: what the last gather there found, for a sweep from that point. A
  // fan of slivers around a vertex puts a hundred triangles or more in contact, and each was
  // asked for its closest point twice an iteration. Mutable, as it changes no answer.
  mutable Vec3 m_closestFrom;
  mutable std::uint32_t m_closestGeneration = 1;
  mutable std::uint32_t m_closestStamp[kCapacity] = {};
  mutable KnownClosestPoint m_closestToStart[kCapacity];
  // A plane separating cached triangle i from the last point a gather measured it from: its
  // unit normal (toward that point) and offset, every point x of the triangle with
  // normal . x <= offset, so a point p lies at least normal . p - offset from the triangle
  // (none yet: a zero normal and an infinite offset). Near a sliver fan's apex nine in ten of
  // the triangles a gather tested lay a nanometre to a micrometre beyond the band; the slides
  // between gathers move nanometres, along the planes. Mutable, as they change no answer.
  mutable double m_separatingX[kCapacity];
  mutable double m_separatingY[kCapacity];
  mutable double m_separatingZ[kCapacity];
  mutable double m_separatingOffset[kCapacity];
};

} // namespace proxima
