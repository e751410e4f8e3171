#include "Proxy/CandidateCache.h"

#include "Geometry/SweptSphere.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

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
    // The records made when the object was built (TriangleFilter.h), or made here for an object
    // built without them.
    const bool recorded = object.filters.size() == object.mesh.numTriangles();
    for (std::uint32_t i = 0; i < found; ++i)
    {
      const std::uint32_t triangle = m_triangle[m_count];
      const TriangleFilter filter =
        recorded ? object.filters[triangle] : makeTriangleFilter(object.mesh.corners(triangle));
      m_sphereX[m_count] = filter.centroid.x;
      m_sphereY[m_count] = filter.centroid.y;
      m_sphereZ[m_count] = filter.centroid.z;
      m_sphereRadius[m_count] = filter.radius;
      m_normalX[m_count] = filter.normal.x;
      m_normalY[m_count] = filter.normal.y;
      m_normalZ[m_count] = filter.normal.z;
      m_planeOffset[m_count] = filter.offset;
      m_planeSlack[m_count] = filter.planeSlack;
      // The edges' half-spaces are made when keepNearEdges first needs them.
      m_edgesMade[m_count] = false;
      forgetSeparatingPlane(m_count);
      m_object[m_count] = objectIndex;
      ++m_count;
    }
  }
  m_center = center;
  m_reach = reach;
  m_valid = true;
  m_lastBlocker = -1;
  forgetClosestPoints();
}

void CandidateCache::forgetClosestPoints() const
{
  startClosestPoints();
  for (int i = 0; i < m_count; ++i)
  {
    forgetSeparatingPlane(i);
  }
}

void CandidateCache::startClosestPoints() const
{
  if (++m_closestGeneration == 0)
  {
    // The counter wrapped (after four billion ticks): wipe the stamps so none can match.
    std::fill(m_closestStamp, m_closestStamp + kCapacity, 0u);
    m_closestGeneration = 1;
  }
}

void CandidateCache::forgetSeparatingPlane(int i) const
{
  m_separatingX[i] = 0.0;
  m_separatingY[i] = 0.0;
  m_separatingZ[i] = 0.0;
  m_separatingOffset[i] = std::numeric_limits<double>::infinity();
}

namespace
{
// The indices of the marked entries of `mask` (0 or 1 each), in order, into `out`; returns how
// many. The filters below first mark, in loops with no branch, no store that depends on an
// earlier iteration and masks as wide as the doubles they come from, which the compiler turns
// into vector code (where the build allows AVX2: Proxy/CMakeLists.txt; this file is compiled
// so that guarded square roots and divisions vectorise too); compacting the survivors is a
// second, short pass. A sphere test that compacted as it went, followed by mayReachSegment for
// each survivor, ran one triangle at a time, and the scans of the cache were half of a large
// proxy's tick (r = 2 mm on 0.5 mm edges: 400-500 cached triangles, two scans an iteration).
int compactMarked(const std::int64_t* mask, int count, int* out)
{
  int kept = 0;
  for (int i = 0; i < count; ++i)
  {
    out[kept] = i;
    kept += static_cast<int>(mask[i]);
  }
  return kept;
}
} // namespace

int CandidateCache::trianglesNearPoint(const Vec3& point, double reach, int* out) const
{
  // mayReachSegment with zero motion, term for term in the same order (so the same triangles
  // pass): the sphere; the height above the plane within the plane's reach; and the in-plane
  // distance to the bounding circle within the lateral reach left at that height.
  std::int64_t mask[kCapacity];
  const int count = m_count;
  for (int i = 0; i < count; ++i)
  {
    const double cx = m_sphereX[i] - point.x;
    const double cy = m_sphereY[i] - point.y;
    const double cz = m_sphereZ[i] - point.z;
    const double sphereReach = m_sphereRadius[i] + reach;
    const bool nearSphere = cx * cx + cy * cy + cz * cz <= sphereReach * sphereReach;
    const double nx = m_normalX[i];
    const double ny = m_normalY[i];
    const double nz = m_normalZ[i];
    const double planeReach = reach + m_planeSlack[i];
    const double height = (nx * point.x + ny * point.y + nz * point.z) - m_planeOffset[i];
    const bool nearPlane = !(height > planeReach) & !(height < -planeReach);
    const double lowest = height < 0.0 ? -height : height;
    const double lateralSquared = planeReach * planeReach - lowest * lowest;
    const double lateral = std::sqrt(lateralSquared > 0.0 ? lateralSquared : 0.0);
    const double along = nx * cx + ny * cy + nz * cz;
    const double px = cx - nx * along;
    const double py = cy - ny * along;
    const double pz = cz - nz * along;
    const double circleReach = m_sphereRadius[i] + lateral;
    const bool nearCircle = px * px + py * py + pz * pz <= circleReach * circleReach;
    mask[i] = nearSphere & nearPlane & nearCircle;
  }
  return compactMarked(mask, count, out);
}

int CandidateCache::trianglesNearSegment(const Vec3& start, const Vec3& motion, double reach,
                                         int* out) const
{
  // mayReachSegment, term for term in the same order, for every cached triangle in one pass
  // that marks a mask (see compactMarked).
  const double sx = start.x;
  const double sy = start.y;
  const double sz = start.z;
  const double mx = motion.x;
  const double my = motion.y;
  const double mz = motion.z;
  const double motionSquared = mx * mx + my * my + mz * mz;
  // Divisions under a condition are a branch the vectoriser keeps (they could trap); a zero
  // length has a zero numerator, so dividing it by 1 gives mayReachSegment's 0 unconditionally.
  const double motionDivisor = motionSquared > 0.0 ? motionSquared : 1.0;
  std::int64_t mask[kCapacity];
  const int count = m_count;
  for (int i = 0; i < count; ++i)
  {
    const double cx = m_sphereX[i] - sx;
    const double cy = m_sphereY[i] - sy;
    const double cz = m_sphereZ[i] - sz;
    const double toward = cx * mx + cy * my + cz * mz;
    double s = toward / motionDivisor;
    s = s < 0.0 ? 0.0 : s;
    s = s > 1.0 ? 1.0 : s;
    const double sphereReach = m_sphereRadius[i] + reach;
    const double ax = cx - mx * s;
    const double ay = cy - my * s;
    const double az = cz - mz * s;
    const bool nearSphere = !(ax * ax + ay * ay + az * az > sphereReach * sphereReach);
    const double nx = m_normalX[i];
    const double ny = m_normalY[i];
    const double nz = m_normalZ[i];
    const double planeReach = reach + m_planeSlack[i];
    const double startHeight = (nx * sx + ny * sy + nz * sz) - m_planeOffset[i];
    const double rise = nx * mx + ny * my + nz * mz;
    const double endHeight = startHeight + rise;
    const bool nearPlane = !((startHeight > planeReach) & (endHeight > planeReach)) &
                           !((startHeight < -planeReach) & (endHeight < -planeReach));
    const double startDepth = startHeight < 0.0 ? -startHeight : startHeight;
    const double endDepth = endHeight < 0.0 ? -endHeight : endHeight;
    const double nearer = endDepth < startDepth ? endDepth : startDepth;
    // Both heights on one side (a zero one, or a product that underflows, gives 0: the segment
    // touches the plane, as when mayReachSegment sees the sides differ).
    const double lowest = startHeight * endHeight > 0.0 ? nearer : 0.0;
    const double lateralSquared = planeReach * planeReach - lowest * lowest;
    const double lateral = std::sqrt(lateralSquared > 0.0 ? lateralSquared : 0.0);
    const double along = nx * cx + ny * cy + nz * cz;
    const double px = cx - nx * along;
    const double py = cy - ny * along;
    const double pz = cz - nz * along;
    const double qx = mx - nx * rise;
    const double qy = my - ny * rise;
    const double qz = mz - nz * rise;
    const double inPlaneSquared = qx * qx + qy * qy + qz * qz;
    double u = (px * qx + py * qy + pz * qz) / (inPlaneSquared > 0.0 ? inPlaneSquared : 1.0);
    u = u < 0.0 ? 0.0 : u;
    u = u > 1.0 ? 1.0 : u;
    const double circleReach = m_sphereRadius[i] + lateral;
    const double ex = px - qx * u;
    const double ey = py - qy * u;
    const double ez = pz - qz * u;
    const bool nearCircle = ex * ex + ey * ey + ez * ez <= circleReach * circleReach;
    mask[i] = nearSphere & nearPlane & nearCircle;
  }
  return compactMarked(mask, count, out);
}

void CandidateCache::makeEdges(const CollisionScene& scene, int i) const
{
  // Edge k runs from corner k to corner k + 1, its outward normal is (edge x normal), and the
  // offset is taken at corner k. Rounding can leave a corner a little outside its own edges'
  // half-spaces: the largest such excess is the slack. A triangle without area (a zero normal)
  // gets zero normals, which keep it whatever the query.
  const TriangleCorners& c = scene.objects[m_object[i]].mesh.corners(m_triangle[i]);
  const Vec3 normal{m_normalX[i], m_normalY[i], m_normalZ[i]};
  const Vec3 corners[3] = {c.a, c.b, c.c};
  double excess = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 outward = normalizedOrZero(cross(corners[(k + 1) % 3] - corners[k], normal));
    const double offset = dot(outward, corners[k]);
    for (const Vec3& corner : corners)
    {
      excess = std::max(excess, dot(outward, corner) - offset);
    }
    m_edgeX[k][i] = outward.x;
    m_edgeY[k][i] = outward.y;
    m_edgeZ[k][i] = outward.z;
    m_edgeOffset[k][i] = offset;
  }
  const Vec3 center{m_sphereX[i], m_sphereY[i], m_sphereZ[i]};
  m_edgeSlack[i] = 2.0 * excess + 1e-12 * (maxAbsComponent(center) + m_sphereRadius[i]);
  m_edgesMade[i] = true;
}

int CandidateCache::keepNearEdges(const CollisionScene& scene, const Vec3& start,
                                  const Vec3& motion, double reach, int* candidates,
                                  int count) const
{
  const Vec3 end = start + motion;
  int kept = 0;
  for (int k = 0; k < count; ++k)
  {
    const int i = candidates[k];
    // A triangle no larger than the reach passed the sphere test only where its edges' test
    // passes too, nearly always: the test pays only for triangles larger than the query.
    if (!(m_sphereRadius[i] > reach))
    {
      candidates[kept++] = i;
      continue;
    }
    if (!m_edgesMade[i])
    {
      makeEdges(scene, i);
    }
    // A hair over the reach: a unit normal rounded to a length a little over 1 measures a
    // little more than the distance.
    const double edgeReach = reach * (1.0 + 1e-12) + m_edgeSlack[i];
    bool near = true;
    for (int edge = 0; edge < 3; ++edge)
    {
      const Vec3 outward{m_edgeX[edge][i], m_edgeY[edge][i], m_edgeZ[edge][i]};
      // Linear along the segment: its least value is at an end.
      const double beyond =
        std::min(dot(outward, start), dot(outward, end)) - m_edgeOffset[edge][i];
      near = near && !(beyond > edgeReach);
    }
    candidates[kept] = i;
    kept += near ? 1 : 0;
  }
  return kept;
}

bool CandidateCache::mayReachSegment(int i, const Vec3& start, const Vec3& motion,
                                     double motionSquared, double reach) const
{
  TriangleFilter filter;
  filter.centroid = Vec3{m_sphereX[i], m_sphereY[i], m_sphereZ[i]};
  filter.radius = m_sphereRadius[i];
  filter.normal = Vec3{m_normalX[i], m_normalY[i], m_normalZ[i]};
  filter.offset = m_planeOffset[i];
  filter.planeSlack = m_planeSlack[i];
  return mayComeWithin(filter, start, motion, motionSquared, reach);
}

std::uint32_t CandidateCache::gatherWithin(const CollisionScene& scene, const Vec3& point,
                                           double maxDistance, NearbyTriangle* out,
                                           std::uint32_t* outObjects, std::uint32_t capacity,
                                           QueryStats& stats) const
{
  std::uint32_t found = 0;
  const double maxDistanceSquared = maxDistance * maxDistance;
  if (std::memcmp(&point, &m_closestFrom, sizeof point) != 0)
  {
    startClosestPoints();
    m_closestFrom = point;
  }
  // A separating plane must put the point beyond the reach by more than the rounding of its
  // height (1e-16 of the coordinates): 1e-12 of them.
  const double clearOfReach = maxDistance + 1e-12 * (maxAbsComponent(point) + maxDistance);
  int near[kCapacity];
  const int numNear = keepNearEdges(scene, point, Vec3{}, maxDistance, near,
                                    trianglesNearPoint(point, maxDistance, near));
  for (int k = 0; k < numNear; ++k)
  {
    const int i = near[k];
    if (separatingHeight(i, point) > clearOfReach)
    {
      continue;
    }
    ++stats.trianglesTested;
    const TriangleCorners& c = scene.objects[m_object[i]].mesh.corners(m_triangle[i]);
    const ClosestPointResult closest = closestPointOnTriangle(point, c.a, c.b, c.c);
    m_closestStamp[i] = m_closestGeneration;
    m_closestToStart[i] = KnownClosestPoint{closest.point, closest.squaredDistance};
    keepSeparatingPlane(i, point, closest.point, closest.squaredDistance);
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

double CandidateCache::coveredFraction(const Vec3& start, const Vec3& end, double distance) const
{
  // The segment's points p with |p - centre| <= reach - distance: from the start (inside) to
  // where it leaves that ball.
  const double inner = m_reach - distance;
  if (!m_valid || !(inner >= 0.0))
  {
    return 0.0;
  }
  const Vec3 from = start - m_center;
  const double startSquared = squaredNorm(from);
  if (startSquared > inner * inner)
  {
    return 0.0;
  }
  const Vec3 motion = end - start;
  if (squaredNorm(end - m_center) <= inner * inner)
  {
    return 1.0;
  }
  // Exit root of |from + t motion|^2 = inner^2 with the start inside: c <= 0, so the larger root,
  // written without cancellation.
  const double a = squaredNorm(motion);
  const double b = dot(from, motion);
  const double c = startSquared - inner * inner;
  const double root = std::sqrt(std::max(0.0, b * b - a * c));
  const double exit = b > 0.0 ? -c / (b + root) : (root - b) / a;
  // Rounded down a hair, so that the fraction never claims a point just outside the ball.
  return std::clamp(exit * (1.0 - 1e-12), 0.0, 1.0);
}

double CandidateCache::separatingHeight(int i, const Vec3& point) const
{
  return m_separatingX[i] * point.x + m_separatingY[i] * point.y + m_separatingZ[i] * point.z -
         m_separatingOffset[i];
}

void CandidateCache::keepSeparatingPlane(int i, const Vec3& point, const Vec3& closest,
                                         double squaredDistance) const
{
  // The triangle lies behind the plane through its closest point to `point`, normal to the
  // way between them (the Voronoi characterisation of the closest point of a convex set). The
  // normal's rounding (about 1e-16 of the coordinates over the distance) tilts the plane, and a
  // point up to the ball's diameter away sees its height off by that tilt times the way: under
  // 1e-13 of the coordinates, inside the queries' 1e-12 slack, only for a distance above a
  // hundredth of the ball's radius. The proxy's planes are measured a radius or so away; a point
  // nearer a triangle than that (a query off the proxy's path) keeps no plane.
  const double distance = std::sqrt(squaredDistance);
  if (!(distance > 1e-2 * m_reach))
  {
    forgetSeparatingPlane(i);
    return;
  }
  const Vec3 normal = (point - closest) / distance;
  m_separatingX[i] = normal.x;
  m_separatingY[i] = normal.y;
  m_separatingZ[i] = normal.z;
  m_separatingOffset[i] = dot(normal, closest);
}

bool CandidateCache::clearUntil(int i, const Vec3& start, const Vec3& motion, double reach,
                                double bound) const
{
  // The sweep's centre rises over the separating plane at a constant rate, and its height is a
  // lower bound on its distance to the triangle, where the sweep stops no farther than
  // radius + skin (sweepSphereTriangleWithSkin's contact rule): a start `clearance` beyond
  // that, closing at `approach` per unit of the sweep, meets the triangle no sooner than
  // clearance / approach. Near a fan's apex a slide the first sliver stops after a nanometre
  // cannot reach the others, tenths of a nanometre to micrometres beyond the radius.
  const double clearance = separatingHeight(i, start) - reach;
  if (!(clearance > 0.0))
  {
    return false;
  }
  const double approach =
    -(m_separatingX[i] * motion.x + m_separatingY[i] * motion.y + m_separatingZ[i] * motion.z);
  return clearance > bound * approach * (1.0 + 1e-9);
}

SceneContact CandidateCache::firstContact(const CollisionScene& scene, const SweepQuery& query,
                                          double covered, QueryStats& stats) const
{
  SceneContact best;
  const Vec3 motion = query.end - query.start;
  const double motionSquared = dot(motion, motion);
  const double beyond = query.radius + query.skin;
  int blocker = -1;
  // The gather at the sweep's start found closest points this sweep can take.
  const bool fromGathered = std::memcmp(&query.start, &m_closestFrom, sizeof query.start) == 0;
  // The bound the filter pass below applied: a triangle it kept passes mayReachSegment at that
  // bound (the pass makes the same tests, term for term), so only a bound that has shrunk since
  // is worth testing again (negative: no pass yet).
  double filtered = -1.0;
  // How far a separating plane's height may be off by rounding (keepSeparatingPlane): far above
  // the rounding of coordinates this size (1e-16 of them), far below the tenths of a nanometre
  // between the slivers of a fan.
  const double clearOfReach = beyond + 1e-12 * (maxAbsComponent(query.start) + query.radius);
  auto test = [&](int i) {
    // Only the part of the path before the best contact so far (or the covered part) can give
    // an earlier one.
    const double bound = best.hit ? best.t : covered;
    if (clearUntil(i, query.start, motion, clearOfReach, bound))
    {
      return;
    }
    if (bound != filtered &&
        !mayReachSegment(i, query.start, motion * bound, motionSquared * bound * bound, beyond))
    {
      return;
    }
    ++stats.trianglesTested;
    const TriangleCorners& c = scene.objects[m_object[i]].mesh.corners(m_triangle[i]);
    const SweepResult hit =
      fromGathered && m_closestStamp[i] == m_closestGeneration
        ? sweepSphereTriangleWithSkin(query.start, motion, query.radius, query.skin, c,
                                      m_closestToStart[i])
        : sweepSphereTriangleWithSkin(query.start, motion, query.radius, query.skin, c);
    const bool earlier =
      !best.hit || hit.t < best.t ||
      (hit.t == best.t && (m_object[i] < best.object ||
                           (m_object[i] == best.object && m_triangle[i] < best.triangle)));
    if (hit.hit && hit.t <= covered && earlier)
    {
      best.hit = true;
      best.t = hit.t;
      best.object = m_object[i];
      best.triangle = m_triangle[i];
      blocker = i;
    }
  };
  const int first = m_lastBlocker;
  if (first >= 0)
  {
    test(first);
  }
  // The spheres near the part of the path that can still give the first contact.
  const double bound = best.hit ? best.t : covered;
  int near[kCapacity];
  const int numNear =
    keepNearEdges(scene, query.start, motion * bound, beyond, near,
                  trianglesNearSegment(query.start, motion * bound, beyond, near));
  filtered = bound;
  for (int k = 0; k < numNear; ++k)
  {
    if (near[k] != first)
    {
      test(near[k]);
    }
  }
  if (best.hit)
  {
    m_lastBlocker = blocker;
  }
  return best;
}

} // namespace proxima
