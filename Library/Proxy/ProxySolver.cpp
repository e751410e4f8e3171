#include "Proxy/ProxySolver.h"

#include "Proxy/ProxyTickState.h"
#include "Proxy/SurfaceTexture.h"

#include <algorithm>
#include <cmath>

namespace proxima
{
namespace
{
// Two planes whose unit normals agree this closely are one plane: triangles sharing the touched
// edge or vertex give the same normal, and one copy is all the goal solver needs. This also
// merges the tangent plane of a neighbour's edge or corner just off the face the proxy rests on
// (tilted by up to sqrt(4 eps / r), 3.5e-5 rad at r = 1 mm): harmless, as that edge stays
// within the face's plane.
constexpr double kSameNormalCosine = 1.0 - 1e-14;

// Two face contacts (each the projection onto its own triangle's plane) are one plane only if
// their normals differ by less than this angle, from the cross product: coplanar faces agree to
// rounding (~1e-15 rad), while two different planes this close are sheets crossing at a tiny
// angle. The cosine cannot tell angles below 1.5e-8 rad from 0, and merged sheets crossing at up
// to 1.4e-7 rad, so that the goal solver saw one and its slides ran into the other (stress seed
// 4009, 8.2e-11 rad). A merge at this angle hides a crossing of at most 1e-13 of a slide: below
// the goal solver's feasibility tolerance and the sweep's touching slope (both 1e-12).
constexpr double kSameFaceNormalSine = 1e-13;
// The reserve band (ProxySolver::nearBand) as a share of the contact gap DESIGN.md section 4
// allows: a plane promoted from it holds the proxy at most this far beyond its radius.
constexpr double kNearBandOfContactGap = 0.8;
// The steepest heading into a reserve triangle (over the step's length) that promotes its plane.
constexpr double kGrazingSlope = 0.5;

// Whether the proxy, touching `corners` at `closest` with contact normal `normal`, sits on a curved
// part of the triangle's configuration-space obstacle: an edge or corner contact off the face's
// normal line. Right above a face (or an edge shared with a coplanar neighbour) it is flat.
bool touchesCurvedPart(const TriangleCorners& corners, const ClosestPointResult& closest,
                       const Vec3& normal)
{
  if (closest.feature == TriangleFeature::Face)
  {
    return false;
  }
  const Vec3 faceNormal = cross(corners.b - corners.a, corners.c - corners.a);
  const double length = norm(faceNormal);
  if (!(length > 0.0))
  {
    return true; // a zero-area triangle is all edges and corners
  }
  return std::fabs(dot(faceNormal, normal)) < (1.0 - 1e-9) * length;
}

// The point normals of `triangle` interpolated with the contact weights, turned to the side of
// `contactNormal` (the paper's flip: a contact may lie on either side of a polygon). False when
// they cancel.
bool interpolatedNormal(const TriangleMesh& mesh, std::uint32_t triangle,
                        const ClosestPointResult& closest, const Vec3& contactNormal, Vec3& out)
{
  const auto& index = mesh.indices(triangle);
  const std::vector<Vec3>& normals = mesh.pointNormals();
  const Vec3 sum = normals[index[0]] * closest.weights[0] + normals[index[1]] * closest.weights[1] +
                   normals[index[2]] * closest.weights[2];
  const double length = norm(sum);
  if (!(length > 0.0))
  {
    return false;
  }
  out = dot(sum, contactNormal) < 0.0 ? sum / -length : sum / length;
  return true;
}

// Rotates v by the smallest rotation that takes unit vector `from` to unit vector `to`
// (Rodrigues' formula); the identity when they agree.
Vec3 rotateLike(const Vec3& from, const Vec3& to, const Vec3& v)
{
  const Vec3 axis = cross(from, to);
  const double sine = norm(axis);
  const double cosine = dot(from, to);
  if (!(sine > 1e-15))
  {
    return cosine >= 0.0 ? v : v - from * (2.0 * dot(from, v)); // opposite: a half turn
  }
  const Vec3 k = axis / sine;
  return v * cosine + cross(k, v) * sine + k * (dot(k, v) * (1.0 - cosine));
}
} // namespace

Vec3 ProxySolver::tiltedRimNormal(const TriangleMesh& mesh, const ContactPlane& plane) const
{
  // Paper 3.1, Fig. 7: a hypothetical configuration-space obstacle whose top face has the
  // interpolated normal of the rim (and whose bottom face the flipped one) is tilted from the
  // true one by the rotation that takes the face's normal to that interpolated normal; the shaded
  // normal is the contact's true configuration-space normal turned by the same rotation. Right
  // above the face it is the interpolated normal, right below it the flipped one, and in between
  // it turns with the proxy around the rim instead of flipping where the two sides meet.
  const TriangleCorners& c = mesh.corners(plane.triangle);
  const Vec3 faceCross = cross(c.b - c.a, c.c - c.a);
  const double faceLength = norm(faceCross);
  const auto& index = mesh.indices(plane.triangle);
  const std::vector<Vec3>& normals = mesh.pointNormals();
  const Vec3 sum = normals[index[0]] * plane.closest.weights[0] +
                   normals[index[1]] * plane.closest.weights[1] +
                   normals[index[2]] * plane.closest.weights[2];
  const double sumLength = norm(sum);
  if (!(faceLength > 0.0) || !(sumLength > 0.0))
  {
    return plane.shadedNormal;
  }
  const Vec3 interpolated = sum / sumLength;
  Vec3 face = faceCross / faceLength;
  if (dot(face, interpolated) < 0.0)
  {
    face = -face; // the face's normal on the side the point normals are given for
  }
  return rotateLike(face, interpolated, plane.normal);
}

void ProxySolver::setScene(const CollisionScene* scene, const ProxyParameters& parameters)
{
  m_scene = scene;
  m_parameters = parameters;
  m_moving = nullptr; // (a set this solver made stays until replaced: nothing is freed here)
  m_skin = scene != nullptr ? resolveSkin(parameters, scene->diagonal(), scene->maxAbsCoordinate())
                            : resolveSkin(parameters, 0.0, 0.0);
  m_numPlanes = 0;
  // DESIGN.md section 4's accuracy scale: 1 nm, or 1e-9 of the scene's size if larger.
  const double accuracyScale = std::max(1e-9, 1e-9 * (scene != nullptr ? scene->diagonal() : 0.0));
  m_numReserve = 0;
  m_nearBand = std::max(contactEpsilon(), kNearBandOfContactGap * accuracyScale);
  m_coherenceMargin =
    parameters.coherenceMargin > 0.0 ? parameters.coherenceMargin : parameters.radius;
  m_cacheMargin = m_coherenceMargin;
  m_cache.invalidate();
  m_planesValid = false;
  m_deforming = nullptr;
  m_reachRadius = 0.0;
  if (scene != nullptr && !scene->objects.empty())
  {
    Aabb box;
    for (const CollisionObject& object : scene->objects)
    {
      box.expand(object.mesh.bounds().lower);
      box.expand(object.mesh.bounds().upper);
    }
    m_reachCenter = box.center();
    m_reachRadius =
      kReachFactor * (scene->maxAbsCoordinate() + std::max(scene->diagonal(), parameters.radius));
  }
  m_shadingTolerance = accuracyScale;
}

void ProxySolver::setMovingObjects(const std::vector<std::uint32_t>& objects)
{
  m_ownedMoving =
    m_scene != nullptr && !objects.empty() ? makeMovingObjects(*m_scene, objects) : nullptr;
  useMovingObjects(m_ownedMoving.get());
}

void ProxySolver::useMovingObjects(MovingObjectSet* objects)
{
  m_moving = objects != nullptr && !objects->entries.empty() ? objects : nullptr;
  m_cache.invalidate();
  m_planesValid = false;
}

void ProxySolver::setObjectPose(std::uint32_t object, const RigidTransform& pose)
{
  const int moving = m_moving != nullptr ? m_moving->indexOf(object) : -1;
  if (moving >= 0)
  {
    m_moving->entries[static_cast<std::size_t>(moving)].pose = pose;
  }
}

const RigidTransform& ProxySolver::objectPose(std::uint32_t object) const
{
  static const RigidTransform identity;
  const int moving = m_moving != nullptr ? m_moving->indexOf(object) : -1;
  return moving < 0 ? identity : m_moving->entries[static_cast<std::size_t>(moving)].pose;
}

void ProxySolver::followMovingObjects(ProxyTickResult& result)
{
  bool moved = false;
  for (MovingObjectSet::Entry& moving : m_moving->entries)
  {
    if (moving.pose == moving.applied)
    {
      continue;
    }
    // The object's motion relative to the proxy, seen from the object: the proxy goes from where
    // the old pose puts it to where the new one does (a straight chord of a rotation's arc, whose
    // sag at a haptic rate is far inside the skin). A contact on the way means the object reached
    // the proxy and carries it from there on, as the move stage would stop the proxy on it.
    const CollisionObject& object = m_scene->objects[moving.object];
    SweepQuery query;
    query.start = moving.applied.applyInverse(m_proxy);
    query.end = moving.pose.applyInverse(m_proxy);
    query.radius = m_parameters.radius;
    query.skin = m_skin;
    const SweepContact contact =
      object.tree.firstContact(object.mesh, query, m_scratch, &result.queries);
    if (contact.hit && contact.t < 1.0)
    {
      const Vec3 stopped = query.start + (query.end - query.start) * contact.t;
      m_proxy = moving.pose.apply(stopped);
      result.conditions.set(TickCondition::pushedByObject);
    }
    moving.mesh.placeAs(object.mesh, moving.pose);
    moving.applied = moving.pose;
    moved = true;
  }
  if (moved)
  {
    ++m_surfaceChanges;
    m_planesValid = false;
    result.proxy = m_proxy;
  }
}

void ProxySolver::setDeformingObjects(const std::vector<std::uint32_t>& objects)
{
  useDeformingObjects(
    m_scene != nullptr && !objects.empty() ? makeDeformingObjects(*m_scene, objects) : nullptr);
}

void ProxySolver::useDeformingObjects(std::shared_ptr<DeformingObjectSet> objects)
{
  m_deforming = objects != nullptr && !objects->entries.empty() ? std::move(objects) : nullptr;
  m_cache.invalidate();
  m_planesValid = false;
}

bool ProxySolver::setObjectPoints(std::uint32_t object, const Vec3* points, std::size_t count)
{
  const int deforming = m_deforming != nullptr ? m_deforming->indexOf(object) : -1;
  if (deforming < 0)
  {
    return false;
  }
  DeformingObjectSet::Entry& entry = m_deforming->entries[static_cast<std::size_t>(deforming)];
  if (count != entry.pending.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!isFinite(points[i]))
    {
      return false;
    }
  }
  std::copy(points, points + count, entry.pending.begin());
  entry.hasPending = true;
  return true;
}

bool ProxySolver::followDeformingObjects(ProxyTickResult& result)
{
  bool moved = false;
  bool pushed = false;
  const double radius = m_parameters.radius;
  const double rest = radius + 0.5 * m_skin;
  for (DeformingObjectSet::Entry& entry : m_deforming->entries)
  {
    if (!entry.hasPending)
    {
      continue;
    }
    entry.hasPending = false;
    moved = true;
    CollisionObject& object = entry.current;
    const std::vector<Vec3>& before = object.mesh.points();
    double largestSquared = 0.0;
    for (std::size_t i = 0; i < before.size(); ++i)
    {
      largestSquared = std::max(largestSquared, squaredDistance(entry.pending[i], before[i]));
    }
    // The surface point nearest the proxy, among those the step could bring within its reach,
    // carries the proxy along the contact normal as far as that point comes toward it: a tissue
    // pressed back by the proxy's own force lifts it as a body's surface does.
    Vec3 lastNormal;
    const NearestTriangle near =
      object.tree.nearest(object.mesh, m_proxy, rest + contactEpsilon() + std::sqrt(largestSquared),
                          m_scratch, &result.queries);
    if (near.found)
    {
      const Vec3 away = m_proxy - near.closest.point;
      const double length = norm(away);
      if (length > 0.0)
      {
        lastNormal = away / length;
        const auto& corner = object.mesh.indices(near.triangle);
        Vec3 shift;
        for (int k = 0; k < 3; ++k)
        {
          shift += (entry.pending[corner[k]] - before[corner[k]]) * near.closest.weights[k];
        }
        const double height = dot(m_proxy - (near.closest.point + shift), lastNormal);
        if (height < rest)
        {
          m_proxy += lastNormal * (rest - height);
          pushed = true;
        }
      }
    }
    object.mesh.movePoints(entry.pending.data(), entry.pending.size());
    object.refitQueries(entry.refitMargin);
    // Whatever of the new surface still overlaps the proxy (a fold, a neighbour that rose more
    // than the carried point) pushes it out along its own normal, nearest first.
    for (int k = 0; k < kMaxDeformationPushes; ++k)
    {
      const NearestTriangle inside =
        object.tree.nearest(object.mesh, m_proxy, radius, m_scratch, &result.queries);
      if (!inside.found)
      {
        break;
      }
      const Vec3 away = m_proxy - inside.closest.point;
      const double length = norm(away);
      const Vec3 normal = length > 0.0 ? away / length : lastNormal;
      if (!(squaredNorm(normal) > 0.0))
      {
        break; // the centre on the surface with no contact seen before: no side to choose
      }
      m_proxy = inside.closest.point + normal * rest;
      lastNormal = normal;
      pushed = true;
    }
  }
  if (moved)
  {
    ++m_surfaceChanges;
    m_planesValid = false;
    result.proxy = m_proxy;
    if (pushed)
    {
      // Only ever set here: a moving object may already have pushed the proxy this tick.
      result.conditions.set(TickCondition::pushedByObject);
    }
  }
  return moved;
}

void ProxySolver::refreshCache(QueryStats& stats)
{
  // The closest points the last gather kept stand as long as its planes do. The cache serves
  // static scenes alone (cacheNeedsRebuild), so nothing moves under them between ticks; they go
  // with the planes all the same, should that change. A tick that starts where the last one
  // ended reuses those planes without a gather, and its first sweep asked every triangle near
  // the proxy for its closest point again (at a fan's apex a tenth of the tick's work).
  if (!m_planesValid)
  {
    m_cache.forgetClosestPoints();
  }
  if (!cacheNeedsRebuild())
  {
    return;
  }
  // A proxy that travelled far last tick (a jab, free flight) will likely leave any ball worth
  // caching: this tick goes to the trees, and the cache waits for calmer ticks. (Not the
  // finger's distance: in sustained contact the finger is deep inside by design.)
  if (m_lastTravel > 0.5 * m_coherenceMargin)
  {
    m_cache.invalidate();
    return;
  }
  rebuildCache(stats);
}

bool ProxySolver::cacheNeedsRebuild() const
{
  if (!m_parameters.temporalCoherence || m_scene == nullptr || m_moving != nullptr ||
      m_deforming != nullptr)
  {
    return false; // moving or deforming objects: the cached triangles would move under the cache
  }
  // Valid, and the proxy within half the cached margin of the centre: the next moves are likely
  // to stay covered.
  const double margin = m_cache.reach() - (m_parameters.radius + contactEpsilon());
  return !(m_cache.valid() && norm(m_proxy - m_cache.center()) <= 0.5 * margin);
}

void ProxySolver::rebuildCache(QueryStats& stats)
{
  // A ball with more triangles than the cache holds (a large proxy on a fine or folded part)
  // left every query of the tick to the trees; a smaller margin still holds the contact's
  // neighbourhood, at the price of re-centring sooner.
  const double contactReach = m_parameters.radius + contactEpsilon();
  for (double margin = m_cacheMargin; margin >= m_coherenceMargin / 16.0; margin /= 4.0)
  {
    m_cache.rebuild(*m_scene, m_proxy, contactReach + margin, m_scratch, stats);
    if (m_cache.valid())
    {
      adaptCacheMargin(margin, m_cache.size());
      return;
    }
  }
}

void ProxySolver::adaptCacheMargin(double margin, int numCached)
{
  // Every sweep and gather scans the whole cache, and every re-centring rebuilds it: a crowded
  // ball makes each iteration slow, a sparse one re-centres often. The margin follows the number
  // of triangles the last ball held toward kCacheTriangles, between a sixteenth of the
  // coherence margin and all of it. On the shared bunny probe path (2 mm proxy, 0.5 mm facets)
  // the full margin held 300-450 triangles, and the solver's instructions fell by a fifth at
  // half of it, while on the screw path (0.5 mm proxy) a smaller margin cost more than it saved.
  if (numCached > 2 * kCacheTriangles)
  {
    m_cacheMargin = std::max(margin / 2.0, m_coherenceMargin / 16.0);
  }
  else if (numCached < kCacheTriangles / 2)
  {
    m_cacheMargin = std::min(margin * 2.0, m_coherenceMargin);
  }
  else
  {
    m_cacheMargin = margin;
  }
}

void ProxySolver::followInCache(QueryStats& stats)
{
  // A deep finger drags the proxy millimetres across the surface in one tick, out of the ball
  // cached at the tick's start: without a new one every later sweep and gather of that tick went
  // to the trees (about 60% of the exact tests on the shared bunny probe path). A contact far
  // from the cached centre re-centres the cache there (in free flight the sweeps are long and go
  // to the trees anyway).
  if (cacheNeedsRebuild())
  {
    rebuildCache(stats);
  }
}

ProxySolver::SweepOutcome ProxySolver::sweep(const Vec3& from, const Vec3& to, QueryStats& stats)
{
  SweepOutcome outcome;
  if (m_scene == nullptr)
  {
    return outcome;
  }
  SweepQuery query;
  query.start = from;
  query.end = to;
  query.radius = m_parameters.radius;
  query.skin = m_skin;
  const double sweepReach = m_parameters.radius + m_skin;
  // The cache answers for the part of the sweep it covers: a contact there is the first one; a
  // sweep that leaves the cached ball without one goes to the trees (a deep finger's slides aim
  // millimetres beyond the ball and are mostly blocked near their start).
  const double covered = m_cache.coveredFraction(from, to, sweepReach);
  if (covered > 0.0)
  {
    const SceneContact contact = m_cache.firstContact(*m_scene, query, covered, stats);
    if (contact.hit || covered >= 1.0)
    {
      outcome.hit = contact.hit;
      outcome.t = contact.hit ? contact.t : 1.0;
      return outcome;
    }
    // The cache holds every triangle the covered part can meet, and none does: the trees need
    // only look beyond it.
    query.clearBefore = covered;
  }
  for (std::uint32_t objectIndex = 0; objectIndex < m_scene->objects.size(); ++objectIndex)
  {
    const CollisionObject& object = queryObject(objectIndex);
    const RigidTransform* pose = treePose(objectIndex);
    SweepQuery inObject = query;
    // The records are in the mesh's frame, as the sweep is made below.
    inObject.filters =
      object.filters.size() == object.mesh.numTriangles() ? object.filters.data() : nullptr;
    if (pose != nullptr)
    {
      inObject.start = pose->applyInverse(from);
      inObject.end = pose->applyInverse(to);
    }
    const SweepContact contact = object.tree.firstContact(object.mesh, inObject, m_scratch, &stats);
    if (contact.hit && contact.t < outcome.t)
    {
      outcome.hit = true;
      outcome.t = contact.t;
    }
    else if (contact.hit && !outcome.hit)
    {
      outcome.hit = true;
      outcome.t = contact.t;
    }
  }
  return outcome;
}

bool ProxySolver::gatherPlanes(const Vec3& position, QueryStats& stats)
{
  // The scene stands still between setScene calls and moves of its moving objects (which forget
  // the planes), so the planes at a point are the planes found there last time: a tick that
  // starts where the last one ended (every tick in resting or sliding contact) reuses the last
  // update stage's planes instead of gathering them again.
  if (m_planesValid && position == m_planesPosition)
  {
    return m_planesComplete;
  }
  m_planesValid = true;
  m_planesPosition = position;
  m_planesComplete = collectPlanes(position, stats);
  return m_planesComplete;
}

bool ProxySolver::collectPlanes(const Vec3& position, QueryStats& stats)
{
  m_numPlanes = 0;
  m_numFirstPass = 0;
  m_anyShaded = false;
  m_anyFriction = false;
  bool complete = true;
  if (m_scene == nullptr)
  {
    return complete;
  }
  m_numReserve = 0;
  // No reserve on a deforming surface: its contact force goes to the touched triangle's points
  // and the carry puts the proxy at its radius plus half a skin (DeformingObjects.h), so a plane
  // held a band away would change the force the tissue feels, by 2e-6 of it on the block scene
  // (TissueScenes.ABlockSceneFilePlaysAsTheCouplingBuiltByHand).
  const double reach =
    m_parameters.radius + (hasDeformingObjects() ? contactEpsilon() : m_nearBand);
  const double contactReach = m_parameters.radius + contactEpsilon();
  std::uint32_t stored = 0;
  if (m_cache.coversBall(position, reach))
  {
    const std::uint32_t found = m_cache.gatherWithin(*m_scene, position, reach, m_nearby,
                                                     m_nearbyObject, kMaxNearbyTriangles, stats);
    complete = found <= kMaxNearbyTriangles;
    stored = complete ? found : kMaxNearbyTriangles;
  }
  else
  {
    for (std::uint32_t objectIndex = 0; objectIndex < m_scene->objects.size(); ++objectIndex)
    {
      const CollisionObject& object = queryObject(objectIndex);
      const RigidTransform* pose = treePose(objectIndex);
      const std::uint32_t room = kMaxNearbyTriangles - stored;
      const std::uint32_t found = object.tree.gatherWithin(
        object.mesh, pose != nullptr ? pose->applyInverse(position) : position, reach,
        m_nearby + stored, room, m_scratch, &stats);
      complete = complete && found <= room;
      const std::uint32_t kept = found < room ? found : room;
      for (std::uint32_t i = 0; i < kept; ++i)
      {
        m_nearbyObject[stored + i] = objectIndex;
        if (pose != nullptr)
        {
          // Found in the object's frame; the planes are made in the world's.
          m_nearby[stored + i].closest.point = pose->apply(m_nearby[stored + i].closest.point);
        }
      }
      stored += kept;
    }
  }
  sortNearby(stored);
  m_numNearby = stored;
  for (std::uint32_t i = 0; i < stored; ++i)
  {
    if (m_nearby[i].closest.squaredDistance > contactReach * contactReach)
    {
      m_reserve[m_numReserve++] = static_cast<std::uint16_t>(i);
      continue;
    }
    complete = addPlane(position, i) && complete;
  }
  for (int k = 0; k < m_numPlanes; ++k)
  {
    complete = dressPlane(m_planes[k], !sharesTouchedFeature(m_planes[k], stored)) && complete;
  }
  return complete;
}

bool ProxySolver::addPlane(const Vec3& position, std::uint32_t i)
{
  const NearbyTriangle& near = m_nearby[i];
  const Vec3 away = position - near.closest.point;
  const double length = norm(away);
  if (!(length > 0.0))
  {
    return true; // the centre lies on the triangle: no direction is free of it
  }
  const Vec3 normal = away / length;
  const bool curved =
    touchesCurvedPart(placedMesh(m_nearbyObject[i]).corners(near.triangle), near.closest, normal);
  for (int k = 0; k < m_numPlanes; ++k)
  {
    const bool twoFaces = near.closest.feature == TriangleFeature::Face &&
                          m_planes[k].closest.feature == TriangleFeature::Face;
    const bool duplicate = dot(m_normals[k], normal) >= kSameNormalCosine &&
                           (!twoFaces || squaredNorm(cross(m_normals[k], normal)) <=
                                           kSameFaceNormalSine * kSameFaceNormalSine);
    if (duplicate)
    {
      m_planes[k].curved = m_planes[k].curved && curved; // one flat witness makes it flat
      return true;
    }
  }
  if (m_numPlanes == kMaxConstraintPlanes)
  {
    return false;
  }
  ContactPlane& plane = m_planes[m_numPlanes];
  plane.normal = normal;
  plane.object = m_nearbyObject[i];
  plane.triangle = near.triangle;
  plane.closest = near.closest;
  plane.depth = 0.0;
  plane.curved = curved;
  m_normals[m_numPlanes] = normal;
  ++m_numPlanes;
  return true;
}

void ProxySolver::sortNearby(std::uint32_t count)
{
  // The planes are deduplicated and solved in the order the triangles come, and the candidate
  // cache and the trees list the same triangles in different orders: near-duplicate normals
  // (within 1.5e-7 rad) then kept a different representative, and the goal solve rounded
  // differently. On a deep crawl that was enough for a tick to end at another local minimum
  // (0.36 mm away on the shared liver probe path) depending on where the cache was centred,
  // and a tick replayed from a fresh solver did not end where the running one did. Sorted by
  // object and triangle, the planes at a point are the same whichever structure found them.
  struct Key
  {
    std::uint64_t objectAndTriangle;
    std::uint32_t index;
  };
  Key keys[kMaxNearbyTriangles];
  bool sorted = true;
  for (std::uint32_t i = 0; i < count; ++i)
  {
    keys[i] = Key{(static_cast<std::uint64_t>(m_nearbyObject[i]) << 32) | m_nearby[i].triangle, i};
    sorted = sorted && (i == 0 || keys[i - 1].objectAndTriangle < keys[i].objectAndTriangle);
  }
  if (sorted)
  {
    return;
  }
  std::sort(keys, keys + count,
            [](const Key& a, const Key& b) { return a.objectAndTriangle < b.objectAndTriangle; });
  for (std::uint32_t i = 0; i < count; ++i)
  {
    m_sortedNearby[i] = m_nearby[keys[i].index];
  }
  for (std::uint32_t i = 0; i < count; ++i)
  {
    m_nearby[i] = m_sortedNearby[i];
    m_nearbyObject[i] = static_cast<std::uint32_t>(keys[i].objectAndTriangle >> 32);
  }
}

bool ProxySolver::sharesTouchedFeature(const ContactPlane& plane, std::uint32_t numNearby) const
{
  // The touched edge (both its points) or corner of the plane's triangle, looked for in the other
  // triangles within reach: a rim no other triangle shares is the edge of an open sheet.
  const auto& own = placedMesh(plane.object).indices(plane.triangle);
  std::uint32_t points[2] = {0, 0};
  int numPoints = 1;
  switch (plane.closest.feature)
  {
    case TriangleFeature::VertexA: points[0] = own[0]; break;
    case TriangleFeature::VertexB: points[0] = own[1]; break;
    case TriangleFeature::VertexC: points[0] = own[2]; break;
    case TriangleFeature::EdgeAB:
      points[0] = own[0];
      points[1] = own[1];
      numPoints = 2;
      break;
    case TriangleFeature::EdgeBC:
      points[0] = own[1];
      points[1] = own[2];
      numPoints = 2;
      break;
    case TriangleFeature::EdgeCA:
      points[0] = own[2];
      points[1] = own[0];
      numPoints = 2;
      break;
    case TriangleFeature::Face: return true;
  }
  const TriangleMesh& mesh = placedMesh(plane.object);
  if (numPoints == 2)
  {
    for (std::uint32_t i = 0; i < numNearby; ++i)
    {
      if (m_nearbyObject[i] != plane.object || m_nearby[i].triangle == plane.triangle)
      {
        continue;
      }
      const auto& other = mesh.indices(m_nearby[i].triangle);
      int found = 0;
      for (int p = 0; p < 2; ++p)
      {
        found += (other[0] == points[p] || other[1] == points[p] || other[2] == points[p]) ? 1 : 0;
      }
      if (found == 2)
      {
        return true;
      }
    }
    return false;
  }
  // A corner is inside a surface when its fan closes: every edge from it is used by two of the
  // triangles around it (all of which are within reach, since the proxy touches the corner).
  // An edge used once is on the rim of an open sheet.
  // Up to six ends a triangle: a degenerate one may name the corner at all three of its places.
  std::uint32_t ends[6 * kMaxNearbyTriangles];
  int numEnds = 0;
  for (std::uint32_t i = 0; i < numNearby; ++i)
  {
    if (m_nearbyObject[i] != plane.object)
    {
      continue;
    }
    const auto& t = mesh.indices(m_nearby[i].triangle);
    for (int k = 0; k < 3; ++k)
    {
      if (t[k] == points[0])
      {
        ends[numEnds++] = t[(k + 1) % 3];
        ends[numEnds++] = t[(k + 2) % 3];
      }
    }
  }
  for (int a = 0; a < numEnds; ++a)
  {
    int uses = 0;
    for (int b = 0; b < numEnds; ++b)
    {
      uses += ends[b] == ends[a] ? 1 : 0;
    }
    if (uses < 2)
    {
      return false;
    }
  }
  return true;
}

bool ProxySolver::dressPlane(ContactPlane& plane, bool alone)
{
  // Shading only where the material asks for it and the mesh has normals, texture only where it
  // has maps and texture coordinates: a plain surface pays a few branches per plane.
  const SurfaceMaterial& material = m_scene->objects[plane.object].material;
  const TriangleMesh& mesh = placedMesh(plane.object);
  plane.shaded =
    material.shading && mesh.hasPointNormals() &&
    interpolatedNormal(mesh, plane.triangle, plane.closest, plane.normal, plane.shadedNormal);
  if (plane.shaded && alone && plane.closest.feature != TriangleFeature::Face)
  {
    // An edge or corner that no other triangle shares here: the rim of an open sheet, where the
    // proxy can roll from the top side to the bottom. Paper Fig. 7's tilted hypothetical surface.
    plane.shadedNormal = tiltedRimNormal(mesh, plane);
  }
  plane.textured = !material.textures.empty() && mesh.hasTexCoords();
  plane.stiffnessScale = material.stiffness;
  for (const StiffnessRegion& region : material.stiffnessRegions)
  {
    // Regions lie in the object as placed, and move with it.
    const RigidTransform* pose = treePose(plane.object);
    plane.stiffnessScale *= stiffnessRegionScale(
      region, pose != nullptr ? pose->applyInverse(plane.closest.point) : plane.closest.point);
  }
  plane.staticFriction = material.staticFriction;
  plane.dynamicFriction = material.dynamicFriction;
  plane.viscosity = material.viscosity;
  m_anyFriction = m_anyFriction || material.hasFriction();
  const Vec3 firstPass = plane.shaded ? plane.shadedNormal : plane.normal;
  int bumps = 0;
  bool complete = true;
  if (plane.textured)
  {
    // Paper 4.3: the contact weights interpolate the texture coordinate; each bump map gives a
    // first-pass plane of its own, and property maps scale the coefficients there.
    plane.texCoord = interpolateTexCoord(mesh, plane.triangle, plane.closest);
    const double friction = textureScale(material, TextureRole::Friction, plane.texCoord);
    plane.staticFriction *= friction;
    plane.dynamicFriction *= friction;
    plane.viscosity *= textureScale(material, TextureRole::Viscosity, plane.texCoord);
    plane.stiffnessScale *= textureScale(material, TextureRole::Stiffness, plane.texCoord);
    for (const TextureMap& map : material.textures)
    {
      Vec3 bumped;
      if (map.role != TextureRole::Bump ||
          !bumpedNormal(mesh, plane.triangle, plane.texCoord, firstPass, map, bumped))
      {
        continue;
      }
      if (m_numFirstPass == kMaxConstraintPlanes)
      {
        complete = false;
        break;
      }
      m_firstPassNormals[m_numFirstPass++] = bumped;
      ++bumps;
    }
  }
  if (bumps == 0 && m_numFirstPass < kMaxConstraintPlanes)
  {
    m_firstPassNormals[m_numFirstPass++] = firstPass;
  }
  m_anyShaded = m_anyShaded || plane.shaded || bumps > 0;
  return complete;
}

Vec3 ProxySolver::shadedSubgoal(const Vec3& toFinger) const
{
  // Paper section 3: the first pass finds the subgoal of the curved (or bumpy) surface the
  // normals stand for, with the first-pass planes. A subgoal above every true plane is projected
  // onto the nearest one, so that the proxy stays on the surface (and friction and texture see a
  // contact). The second pass is the plain loop with this subgoal for the finger.
  // A finger above every true plane is leaving the surface: no shading, the proxy follows it
  // (projecting its subgoal back onto a plane would glue the proxy down and pull the finger).
  bool pressing = false;
  for (int k = 0; k < m_numPlanes && !pressing; ++k)
  {
    pressing = dot(m_normals[k], toFinger) < 0.0;
  }
  if (!pressing)
  {
    return toFinger;
  }
  Vec3 subgoal = solveGoal(toFinger, m_firstPassNormals, m_numFirstPass).displacement;
  const double tolerance = 1e-12 * norm(toFinger);
  int nearest = -1;
  double least = 0.0;
  bool aboveAll = m_numPlanes > 0;
  for (int k = 0; k < m_numPlanes; ++k)
  {
    const double height = dot(m_normals[k], subgoal);
    aboveAll = aboveAll && height > tolerance;
    if (nearest < 0 || height < least)
    {
      nearest = k;
      least = height;
    }
  }
  if (aboveAll)
  {
    subgoal -= m_normals[nearest] * least;
  }
  return subgoal;
}

bool ProxySolver::insideStaticCone(const Vec3& toFinger) const
{
  // The user's force on the proxy is kp (finger - proxy); kp cancels from the cone test
  // |f_t| <= mu_s |f_n|, which only counts a plane the finger presses on (f_n into it).
  for (int k = 0; k < m_numPlanes; ++k)
  {
    const ContactPlane& plane = m_planes[k];
    if (!(plane.staticFriction > 0.0))
    {
      continue;
    }
    const double normal = dot(toFinger, plane.normal);
    if (normal < 0.0 && norm(toFinger - plane.normal * normal) <= plane.staticFriction * -normal)
    {
      return true;
    }
  }
  return false;
}

double ProxySolver::frictionLimitedTravel(const GoalSolution& solution, double travel,
                                          double& viscousBudget) const
{
  // Paper eq. 21 with the proxy's mass going to zero: along the surface the proxy moves at
  // (|f_t| - mu_d |f_n|) / b. The drags of the active planes add (Coulomb), so that a contact
  // the solver splits between two nearly coincident planes (within 50 nm of a mesh edge) drags
  // as one. Dynamic friction stops the slide where the finger sits on the cone
  // |f_t| = mu_d |f_n| (with b = 0 the proxy gets there within the tick); viscosity spends a
  // travel of dt kp (|f_t| - mu_d |f_n|) / b per tick, measured where the tick's first slide
  // starts, with the largest b of the contacts (the lowest speed bound, 4.2).
  double drag = 0.0;
  double viscosity = 0.0;
  for (int k = 0; k < solution.numActive; ++k)
  {
    const ContactPlane& plane = m_planes[solution.active[k]];
    drag += plane.dynamicFriction * solution.depth[k]; // depth: |f_n| / kp on this plane
    viscosity = std::max(viscosity, plane.viscosity);
  }
  const double slack = travel - drag;
  double allowed = std::min(travel, slack);
  if (viscosity > 0.0)
  {
    if (viscousBudget < 0.0)
    {
      viscousBudget =
        std::max(0.0, m_parameters.timeStep * m_parameters.stiffness * slack / viscosity);
    }
    allowed = std::min(allowed, viscousBudget);
  }
  return std::max(0.0, allowed);
}

Vec3 ProxySolver::withinReach(const Vec3& finger) const
{
  if (!(m_reachRadius > 0.0))
  {
    return finger;
  }
  const Vec3 offset = finger - m_reachCenter;
  // Scaled first: the squares of a 1e200 m offset overflow.
  const double scale = maxAbsComponent(offset);
  if (!(scale > m_reachRadius / 2.0))
  {
    return finger;
  }
  const Vec3 direction = offset / scale;
  const double length = scale * norm(direction);
  if (length <= m_reachRadius)
  {
    return finger;
  }
  return m_reachCenter + direction * (m_reachRadius / norm(direction));
}

ProxyTickResult ProxySolver::update(const Vec3& requestedFinger)
{
  ProxyTickResult result;
  result.proxy = m_proxy;
  result.conditions.set(TickCondition::startedOutside, m_startedOutsidePending);
  m_startedOutsidePending = false;
  if (!isFinite(requestedFinger))
  {
    result.conditions.set(TickCondition::fingerRefused);
    return result;
  }
  if (m_moving != nullptr)
  {
    followMovingObjects(result);
  }
  if (m_deforming != nullptr && followDeformingObjects(result))
  {
    m_lastTravel = 0.0;
  }
  ProxyTickState tick(m_parameters, withinReach(requestedFinger), m_proxy, m_skin);
  if (m_moveRecord != nullptr)
  {
    m_moveRecord->clear();
    m_moveRecord->add(m_proxy, MovePointKind::Accepted);
  }
  refreshCache(result.queries);
  for (;;)
  {
    // Update stage (2.2) first, also at the start of a tick: a proxy already in contact must not
    // head straight for the finger, or every tick would push it a little deeper into the skin.
    updateStage(tick, result);
    if (atLocalMinimum(tick))
    {
      if (retracedTrials(tick))
      {
        continue; // a minimum farther than the last accepted point: seek on from that point
      }
      break;
    }
    if (tick.budget.secondHalf(result.iterations))
    {
      // The budget's second half is for plain slides (TickBudget::secondHalf).
      if (retracedTrials(tick))
      {
        continue;
      }
      tick.stretch.forbid();
    }
    const Vec3 step = nextStep(tick);
    const bool stretched = step != tick.solution.displacement;
    const Vec3 goal = m_proxy + step;
    if (tick.blocked.repeats(goal) || outOfWork(tick, result))
    {
      if (retracedTrials(tick))
      {
        solveAtProxy(tick, result); // the contacts are those where the retrace ended
      }
      break;
    }
    const double distanceBefore = moveStage(tick, goal, result);
    if (reachedTarget(tick, result))
    {
      judgeMove(tick); // at the target: never farther than the accepted point
      break;
    }
    if (judgeMove(tick))
    {
      continue; // the trial chain filled up without coming nearer: walked back
    }
    if (stretched)
    {
      tick.stretch.awaitPayoff(tick.solution.numActive, distanceBefore);
      continue;
    }
    const double toTarget = norm(tick.shading.target() - m_proxy);
    tick.stretch.judgePayoff(toTarget, tick.stepTolerance);
    if (stopsWithoutProgress(tick, toTarget, distanceBefore, result))
    {
      if (retracedTrials(tick))
      {
        solveAtProxy(tick, result);
      }
      break;
    }
  }
  finishTick(tick, result);
  return result;
}

bool ProxySolver::judgeMove(ProxyTickState& tick)
{
  TrialChain& trials = tick.trials;
  const double toTarget = norm(tick.shading.target() - m_proxy);
  // Shading and friction send the proxy elsewhere than the finger on purpose (and never stretch):
  // their moves are not judged by the approach. A skin's rounding is no retreat: without it a
  // slide that ends 1e-18 m farther was walked back, changing traces for nothing.
  if (!(toTarget > trials.acceptedDistance() + m_skin) || tick.shading.used() || m_anyFriction)
  {
    trials.accept(m_proxy, std::min(toTarget, trials.acceptedDistance()));
    return false;
  }
  trials.addTrial(m_proxy);
  if (m_moveRecord != nullptr)
  {
    m_moveRecord->markLastTrial();
  }
  return trials.full() && retracedTrials(tick);
}

bool ProxySolver::retracedTrials(ProxyTickState& tick)
{
  TrialChain& trials = tick.trials;
  if (!trials.pending())
  {
    return false;
  }
  // The proxy is farther from the target than the last accepted point: walk back over the
  // trials' segments (each swept clear on the way out, so no sweep is needed) to that point, and
  // go on with plain slides. Without this a stretched slide could carry the proxy over a ridge of
  // the configuration-space surface into another basin, and the tick ended at a minimum farther
  // from the finger than where it began (shared bunny probe path, tick 2630: 4.2e-6 m).
  if (m_moveRecord != nullptr)
  {
    for (int k = trials.numTrials() - 2; k >= 0; --k)
    {
      m_moveRecord->add(trials.trial(k), MovePointKind::Trial);
    }
    m_moveRecord->add(trials.accepted(), MovePointKind::Accepted);
  }
  m_proxy = trials.accepted();
  trials.retraced();
  tick.stretch.forbid();
  tick.blocked.forget();
  return true;
}

void ProxySolver::solveAtProxy(ProxyTickState& tick, ProxyTickResult& result)
{
  gatherPlanesInto(m_proxy, result);
  tick.solution = solveGoal(tick.shading.target() - m_proxy, m_normals, m_numPlanes);
}

void ProxySolver::gatherPlanesInto(const Vec3& position, ProxyTickResult& result)
{
  if (!gatherPlanes(position, result.queries))
  {
    result.conditions.set(TickCondition::contactOverflow);
  }
}

void ProxySolver::updateStage(ProxyTickState& tick, ProxyTickResult& result)
{
  gatherPlanesInto(m_proxy, result);
  if (tick.shading.moving(m_anyShaded, result.iterations))
  {
    // Shading (and bump texture): the first pass picks the target that the second pass, the
    // plain loop with the true planes, seeks.
    tick.shading.reshade(m_proxy + shadedSubgoal(tick.finger - m_proxy), m_shadingTolerance);
  }
  tick.solution = solveGoal(tick.shading.target() - m_proxy, m_normals, m_numPlanes);
  if (m_numReserve > 0)
  {
    promoteNearPlanes(tick, result);
  }
  result.usedExactFallback = result.usedExactFallback || tick.solution.usedExactFallback;
  if (m_anyFriction)
  {
    applyFriction(tick, result);
  }
}

bool ProxySolver::plainSurface(std::uint32_t objectIndex) const
{
  // What dressPlane would give a plane of this object: no shading, texture or friction.
  const SurfaceMaterial& material = m_scene->objects[objectIndex].material;
  const TriangleMesh& mesh = placedMesh(objectIndex);
  return !(material.shading && mesh.hasPointNormals()) &&
         !(!material.textures.empty() && mesh.hasTexCoords()) && !material.hasFriction();
}

void ProxySolver::promoteNearPlanes(ProxyTickState& tick, ProxyTickResult& result)
{
  // Near the apex of a CAD cone made of slivers, dozens of facets lie within a nanometre of the
  // proxy, and only those within contactEpsilon() (a few picometres) gave planes: each move
  // toward the goal was stopped after a few nanometres by the next facet, one new plane an
  // iteration, each iteration an exact test of the 200 slivers touching the proxy. A triangle
  // lies behind its tangent plane at its closest point, so the goal may go as far as that plane
  // allows; one that would cross it (less the skin, where a fresh contact stops) is given the
  // plane before the move. Only plain surfaces: a shaded, textured or frictional plane changes the
  // target the update stage has already chosen.
  if (tick.shading.used() || m_anyFriction || m_anyShaded)
  {
    return;
  }
  const double stopAt = m_parameters.radius + m_skin;
  while (m_numReserve > 0 && m_numPlanes < kMaxConstraintPlanes)
  {
    const Vec3& step = tick.solution.displacement;
    const double stepLength = norm(step);
    int nearest = -1;
    double nearestShare = 1.0;
    for (int k = 0; k < m_numReserve; ++k)
    {
      const NearbyTriangle& near = m_nearby[m_reserve[k]];
      const Vec3 away = m_proxy - near.closest.point;
      const double length = norm(away);
      const double approach = -dot(away, step) / length;
      const double room = length - stopAt;
      // A step that heads into the triangle steeply settles onto it, as any fall onto a surface
      // does, and the contact keeps its skin-wide gap; a step that grazes it would be stopped
      // after room / slope, a few nanometres of a long slide.
      if (approach > room && approach < kGrazingSlope * stepLength &&
          room < nearestShare * approach)
      {
        nearest = k;
        nearestShare = room / approach;
      }
    }
    if (nearest < 0)
    {
      return;
    }
    const std::uint32_t index = m_reserve[nearest];
    m_reserve[nearest] = m_reserve[--m_numReserve];
    if (!plainSurface(m_nearbyObject[index]))
    {
      continue;
    }
    const int before = m_numPlanes;
    addPlane(m_proxy, index);
    if (m_numPlanes == before)
    {
      continue; // the same normal as a plane already there
    }
    if (!dressPlane(m_planes[before], !sharesTouchedFeature(m_planes[before], m_numNearby)))
    {
      result.conditions.set(TickCondition::contactOverflow);
    }
    tick.solution = solveGoal(tick.shading.target() - m_proxy, m_normals, m_numPlanes);
    if (squaredNorm(tick.solution.displacement) <= m_nearBand * m_nearBand)
    {
      // The promoted planes hold the proxy within the band of where it would settle: no step
      // that short is worth a move. Left to run, two planes a band apart traded the proxy
      // between two points 1.6e-12 m apart for ever, 1 km from the origin, where a nearly flat
      // crease's direction is rounding.
      tick.solution.displacement = Vec3{};
      return;
    }
  }
}

void ProxySolver::applyFriction(ProxyTickState& tick, ProxyTickResult& result) const
{
  GoalSolution& solution = tick.solution;
  // Paper 4.1: inside a static friction cone the subgoal is the proxy itself.
  if (insideStaticCone(tick.finger - m_proxy))
  {
    if (result.iterations == 0)
    {
      result.conditions.set(TickCondition::stuck); // held where the tick began
    }
    solution.displacement = Vec3{};
    return;
  }
  const double travel = norm(solution.displacement);
  const double allowed = frictionLimitedTravel(solution, travel, tick.viscous.budget);
  if (allowed < travel)
  {
    result.conditions.set(TickCondition::frictionLimited);
    solution.displacement = solution.displacement * (allowed / travel);
  }
}

bool ProxySolver::atLocalMinimum(const ProxyTickState& tick) const
{
  // No feasible step brings the proxy nearer the finger.
  const Vec3& displacement = tick.solution.displacement;
  return squaredNorm(displacement) <= tick.stepTolerance * tick.stepTolerance;
}

Vec3 ProxySolver::nextStep(const ProxyTickState& tick) const
{
  // The Newton stretch and the no-progress rule assume the proxy seeks the finger; a shaded
  // surface sends it elsewhere on purpose.
  if (!tick.stretch.allowed() || tick.shading.used() || m_anyFriction)
  {
    return tick.solution.displacement;
  }
  return curvatureCorrectedStep(tick.solution, tick.shading.target() - m_proxy,
                                tick.stretch.creaseLimit());
}

bool ProxySolver::outOfWork(const ProxyTickState& tick, ProxyTickResult& result) const
{
  if (result.iterations == m_parameters.maxIterations)
  {
    result.conditions.set(TickCondition::hitIterationCap);
    return true;
  }
  if (tick.budget.spent(result.iterations))
  {
    result.conditions.set(TickCondition::budgetLimited);
    return true;
  }
  return false;
}

double ProxySolver::moveStage(ProxyTickState& tick, const Vec3& goal, ProxyTickResult& result)
{
  // Move stage (2.1): sweep toward the goal and stop at the first contact.
  ++result.iterations;
  const SweepOutcome contact = sweep(m_proxy, goal, result.queries);
  const Vec3 before = m_proxy;
  m_proxy = contact.hit ? m_proxy + (goal - m_proxy) * contact.t : goal;
  if (contact.hit || tick.solution.numActive > 0)
  {
    // Stopped by a contact, or a slide that ran clear (off a convex edge, the next move falls
    // back onto the surface there): the proxy is on or near the surface.
    followInCache(result.queries);
  }
  tick.blocked.moved(goal, before, m_proxy);
  tick.viscous.spend(before, m_proxy);
  if (m_moveRecord != nullptr)
  {
    m_moveRecord->add(m_proxy, MovePointKind::Accepted); // judgeMove marks a trial
  }
  return norm(tick.shading.target() - before);
}

bool ProxySolver::reachedTarget(ProxyTickState& tick, const ProxyTickResult& result) const
{
  // Progress is measured toward a fixed target: not while shading still moves it.
  if (m_proxy == tick.shading.target() && !tick.shading.moving(m_anyShaded, result.iterations))
  {
    tick.solution = GoalSolution{};
    return true;
  }
  return false;
}

bool ProxySolver::stopsWithoutProgress(ProxyTickState& tick, double toTarget, double distanceBefore,
                                       ProxyTickResult& result)
{
  const bool progressed = toTarget < distanceBefore - tick.stepTolerance ||
                          tick.shading.moving(m_anyShaded, result.iterations);
  if (!tick.progress.stalls(progressed))
  {
    return false;
  }
  // The last update stage's planes stand for the contact.
  solveAtProxy(tick, result);
  return true;
}

void ProxySolver::finishTick(ProxyTickState& tick, ProxyTickResult& result)
{
  result.proxy = m_proxy;
  result.usedShading = tick.shading.used();
  m_lastTravel = norm(m_proxy - tick.start);
  if (result.usedShading || m_anyFriction)
  {
    // The contacts are the planes the finger pushes on, with the depths of eq. 19: where the loop
    // sought a shaded subgoal, or friction cut its slide, its last solve says less than that.
    gatherPlanesInto(m_proxy, result);
    tick.solution = solveGoal(tick.finger - m_proxy, m_normals, m_numPlanes);
  }
  const GoalSolution& solution = tick.solution;
  double depthSum = 0.0;
  double scaledSum = 0.0;
  for (int k = 0; k < solution.numActive; ++k)
  {
    ContactPlane plane = m_planes[solution.active[k]];
    plane.depth = solution.depth[k];
    result.contacts[result.numContacts++] = plane;
    depthSum += plane.depth;
    scaledSum += plane.depth * plane.stiffnessScale;
  }
  if (depthSum > 0.0)
  {
    result.stiffnessScale = scaledSum / depthSum;
  }
}

} // namespace proxima
