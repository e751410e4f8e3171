#include "Proxy/ProxySolver.h"

#include <cmath>

namespace proxima
{
namespace
{
// Two planes whose unit normals agree this closely are one plane: triangles sharing the touched
// edge or vertex give the same normal, and one copy is all the goal solver needs.
constexpr double kSameNormalCosine = 1.0 - 1e-14;
} // namespace

void ProxySolver::setScene(const CollisionScene* scene, const ProxyParameters& parameters)
{
  m_scene = scene;
  m_parameters = parameters;
  m_skin = scene != nullptr
             ? resolveSkin(parameters, scene->diagonal(), scene->maxAbsCoordinate())
             : resolveSkin(parameters, 0.0, 0.0);
  m_numPlanes = 0;
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
  for (const CollisionObject& object : m_scene->objects)
  {
    const SweepContact contact = object.tree.firstContact(object.mesh, query, m_scratch, &stats);
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
  m_numPlanes = 0;
  bool complete = true;
  if (m_scene == nullptr)
  {
    return complete;
  }
  const double reach = m_parameters.radius + contactEpsilon();
  for (std::uint32_t objectIndex = 0; objectIndex < m_scene->objects.size(); ++objectIndex)
  {
    const CollisionObject& object = m_scene->objects[objectIndex];
    const std::uint32_t found = object.tree.gatherWithin(object.mesh, position, reach, m_nearby,
                                                         kMaxNearbyTriangles, m_scratch, &stats);
    complete = complete && found <= kMaxNearbyTriangles;
    const std::uint32_t stored = found < kMaxNearbyTriangles ? found : kMaxNearbyTriangles;
    for (std::uint32_t i = 0; i < stored; ++i)
    {
      const NearbyTriangle& near = m_nearby[i];
      const Vec3 away = position - near.closest.point;
      const double length = norm(away);
      if (!(length > 0.0))
      {
        continue; // the centre lies on the triangle: no direction is free of it
      }
      const Vec3 normal = away / length;
      bool duplicate = false;
      for (int k = 0; k < m_numPlanes && !duplicate; ++k)
      {
        duplicate = dot(m_normals[k], normal) >= kSameNormalCosine;
      }
      if (duplicate)
      {
        continue;
      }
      if (m_numPlanes == kMaxConstraintPlanes)
      {
        complete = false;
        continue;
      }
      ContactPlane& plane = m_planes[m_numPlanes];
      plane.normal = normal;
      plane.object = objectIndex;
      plane.triangle = near.triangle;
      plane.closest = near.closest;
      plane.depth = 0.0;
      m_normals[m_numPlanes] = normal;
      ++m_numPlanes;
    }
  }
  return complete;
}

ProxyTickResult ProxySolver::update(const Vec3& finger)
{
  ProxyTickResult result;
  result.proxy = m_proxy;
  if (!isFinite(finger))
  {
    result.refusedFinger = true;
    return result;
  }
  // Steps shorter than this are rounding noise of the goal solve, not motion: 1% of the skin.
  const double stepTolerance = 0.01 * m_skin;
  GoalSolution solution;
  Vec3 previousGoal = m_proxy;
  bool blockedAtOnce = false;
  for (;;)
  {
    // Update stage (2.2) first, also at the start of a tick: a proxy already in contact must not
    // head straight for the finger, or every tick would push it a little deeper into the skin.
    result.contactOverflow = !gatherPlanes(m_proxy, result.queries) || result.contactOverflow;
    solution = solveGoal(finger - m_proxy, m_normals, m_numPlanes);
    result.usedExactFallback = result.usedExactFallback || solution.usedExactFallback;
    const Vec3 goal = m_proxy + solution.displacement;
    if (squaredNorm(solution.displacement) <= stepTolerance * stepTolerance)
    {
      break; // a local minimum: no feasible step brings the proxy nearer the finger
    }
    if (blockedAtOnce && goal == previousGoal)
    {
      break; // the last move was blocked at once and nothing changed: repeating cannot help
    }
    if (result.iterations == m_parameters.maxIterations)
    {
      result.hitIterationCap = true;
      break;
    }
    // Move stage (2.1): sweep toward the goal and stop at the first contact.
    ++result.iterations;
    const SweepOutcome contact = sweep(m_proxy, goal, result.queries);
    const Vec3 before = m_proxy;
    m_proxy = contact.hit ? m_proxy + (goal - m_proxy) * contact.t : goal;
    blockedAtOnce = m_proxy == before;
    previousGoal = goal;
    if (m_proxy == finger)
    {
      solution = GoalSolution{};
      break;
    }
  }
  result.proxy = m_proxy;
  for (int k = 0; k < solution.numActive; ++k)
  {
    ContactPlane plane = m_planes[solution.active[k]];
    plane.depth = solution.depth[k];
    result.contacts[result.numContacts++] = plane;
  }
  return result;
}

} // namespace proxima
