#include "Tissue/TissueContact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
const CollisionScene& sceneOf(const ProxySolver& solver)
{
  if (solver.scene() == nullptr)
  {
    throw std::invalid_argument("TissueContact: the solver has no scene");
  }
  return *solver.scene();
}
} // namespace

TissueContact::TissueContact(ElasticSolid& solid, const CollisionScene& scene, std::uint32_t object,
                             double stiffness)
  : m_solid(solid)
  , m_object(object)
  , m_stiffness(stiffness)
{
  const std::size_t count = solid.positions().size();
  if (object >= scene.objects.size())
  {
    throw std::invalid_argument("TissueContact: object " + std::to_string(object) +
                                " of a scene of " + std::to_string(scene.objects.size()));
  }
  if (scene.objects[object].mesh.numPoints() != count)
  {
    throw std::invalid_argument("TissueContact: the object's mesh has " +
                                std::to_string(scene.objects[object].mesh.numPoints()) +
                                " points, the solid " + std::to_string(count));
  }
  m_footprint.resize(kMaxFootprint);
  m_scratch = std::make_unique<SphereTreeScratch>();
  m_forceSum.assign(count, Vec3{});
  m_isLoaded.assign(count, 0);
  m_loaded.reserve(count);
  m_applied.assign(count, Vec3{});
  m_appliedTo.reserve(count);
}

TissueContact::TissueContact(ElasticSolid& solid, ProxySolver& solver, std::uint32_t object,
                             double stiffness)
  : TissueContact(solid, sceneOf(solver), object, stiffness)
{
  if (!solver.isDeforming(object))
  {
    solver.setDeformingObjects({object});
  }
  bind(solver);
}

bool TissueContact::bind(ProxySolver& solver)
{
  if (!solver.isDeforming(m_object) ||
      solver.placedMesh(m_object).numPoints() != m_solid.positions().size())
  {
    return false;
  }
  m_solver = &solver;
  return true;
}

void TissueContact::addTick(const ProxyTickResult& result)
{
  Vec3 force;
  double stiffness = 0.0;
  for (int k = 0; k < result.numContacts; ++k)
  {
    const ContactPlane& plane = result.contacts[k];
    if (plane.object == m_object && plane.depth > 0.0)
    {
      force += plane.normal * (-m_stiffness * plane.stiffnessScale * plane.depth);
      stiffness = std::max(stiffness, m_stiffness * plane.stiffnessScale);
    }
  }
  addPress(result.proxy, force, stiffness);
}

void TissueContact::addPress(const Vec3& proxy, const Vec3& force, double stiffness)
{
  ++m_ticks;
  m_numSprings = 0;
  m_numApproaching = 0;
  const CollisionObject& object = m_solver->queryObject(m_object);
  const double radius = m_solver->parameters().radius;
  const double gap = m_footprintGap * radius;
  const std::uint32_t found = object.tree.gatherWithin(
    object.mesh, proxy, radius + gap, m_footprint.data(), kMaxFootprint, *m_scratch);
  const std::uint32_t count = std::min(found, kMaxFootprint);
  const double total = sortFootprint(count);
  if (!(total > 0.0))
  {
    return;
  }
  if (!(stiffness > 0.0))
  {
    noteApproach(proxy, count, total);
    return;
  }
  for (std::uint32_t i = 0; i < count; ++i)
  {
    const NearbyTriangle& near = m_footprint[i];
    const double share = footprintWeight(std::sqrt(near.closest.squaredDistance)) / total;
    if (!(share > 0.0))
    {
      continue;
    }
    const auto& corner = object.mesh.indices(near.triangle);
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t vertex = corner[static_cast<std::size_t>(c)];
      m_forceSum[vertex] += force * (share * near.closest.weights[c]);
      if (m_isLoaded[vertex] == 0)
      {
        m_isLoaded[vertex] = 1;
        m_loaded.push_back(vertex);
      }
    }
    // The footprint held by the spring in every direction during the step, its stiffness shared
    // as the force is: along the force alone, the tangential part stayed explicit.
    const Vec3 axes[3] = {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}, Vec3{0.0, 0.0, 1.0}};
    for (const Vec3& axis : axes)
    {
      ContactSpring& spring = m_springs[m_numSprings++];
      spring.vertices = corner;
      spring.weights = {near.closest.weights[0], near.closest.weights[1], near.closest.weights[2]};
      spring.normal = axis;
      spring.stiffness = stiffness * share;
    }
  }
}

double TissueContact::footprintWeight(double distanceToCentre) const
{
  const double radius = m_solver->parameters().radius;
  const double clearance = distanceToCentre - radius;
  return std::max(0.0, 1.0 - clearance / (m_footprintGap * radius));
}

double TissueContact::sortFootprint(std::uint32_t count)
{
  // Nearest first: the footprint keeps the kMaxFootprint triangles that carry the most (every
  // one of them gets its springs: TissueContact.h asserts there are enough).
  std::sort(m_footprint.begin(), m_footprint.begin() + count,
            [](const NearbyTriangle& a, const NearbyTriangle& b) {
              return a.closest.squaredDistance < b.closest.squaredDistance ||
                     (a.closest.squaredDistance == b.closest.squaredDistance &&
                      a.triangle < b.triangle);
            });
  double total = 0.0;
  for (std::uint32_t i = 0; i < count; ++i)
  {
    total += footprintWeight(std::sqrt(m_footprint[i].closest.squaredDistance));
  }
  return total;
}

void TissueContact::noteApproach(const Vec3& proxy, std::uint32_t count, double total)
{
  // Not touching, but within the footprint's gap: the nearest triangles, each along the
  // direction to the proxy, in case the step brings them into it (step() keeps those moving
  // toward it).
  const CollisionObject& object = m_solver->queryObject(m_object);
  for (std::uint32_t i = 0; i < count && m_numApproaching < kMaxContactSprings; ++i)
  {
    const NearbyTriangle& near = m_footprint[i];
    const double distanceToCentre = std::sqrt(near.closest.squaredDistance);
    const double share = footprintWeight(distanceToCentre) / total;
    if (!(share > 0.0) || !(distanceToCentre > 0.0))
    {
      continue;
    }
    ContactSpring& spring = m_approaching[m_numApproaching++];
    spring.vertices = object.mesh.indices(near.triangle);
    spring.weights = {near.closest.weights[0], near.closest.weights[1], near.closest.weights[2]};
    spring.normal = (proxy - near.closest.point) / distanceToCentre;
    spring.stiffness = m_stiffness * share;
  }
}

void TissueContact::step()
{
  loadStep();
  m_solid.step();
  handOverSurface();
}

void TissueContact::handOverSurface()
{
  const std::vector<Vec3>& positions = m_solid.positions();
  m_solver->setObjectPoints(m_object, positions.data(), positions.size());
}

void TissueContact::beforeSurfaceHandOver()
{
  if (m_solver == nullptr || m_numSprings == 0 || m_ticks == 0)
  {
    return;
  }
  const std::vector<Vec3>& pressed = m_solver->queryObject(m_object).mesh.points();
  const std::vector<Vec3>& now = m_solid.positions();
  const double ticks = static_cast<double>(m_ticks);
  for (int k = 0; k < m_numSprings; ++k)
  {
    const ContactSpring& spring = m_springs[k];
    Vec3 moved;
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t vertex = spring.vertices[static_cast<std::size_t>(c)];
      moved += (now[vertex] - pressed[vertex]) * spring.weights[static_cast<std::size_t>(c)];
    }
    const double along = dot(moved, spring.normal);
    if (along == 0.0)
    {
      continue;
    }
    // Summed as a tick's press is, so the mean over the ticks gives it once.
    const Vec3 force = spring.normal * (-spring.stiffness * along * ticks);
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t vertex = spring.vertices[static_cast<std::size_t>(c)];
      m_forceSum[vertex] += force * spring.weights[static_cast<std::size_t>(c)];
      if (m_isLoaded[vertex] == 0)
      {
        m_isLoaded[vertex] = 1;
        m_loaded.push_back(vertex);
      }
    }
  }
}

void TissueContact::loadStep()
{
  if (m_numSprings == 0)
  {
    // A surface springing back toward a proxy it does not touch yet would rise into it within
    // the step, unheld, and carry it: the spring's force would jump the next tick and the
    // contact be lost again (a release chattered at 0.84 N on the liver). Where it moves toward
    // the proxy, it is held along that direction as a contact would hold it, from where it is.
    const std::vector<Vec3>& velocities = m_solid.velocities();
    for (int k = 0; k < m_numApproaching; ++k)
    {
      const ContactSpring& spring = m_approaching[k];
      Vec3 velocity;
      for (int c = 0; c < 3; ++c)
      {
        velocity += velocities[spring.vertices[static_cast<std::size_t>(c)]] *
                    spring.weights[static_cast<std::size_t>(c)];
      }
      if (dot(velocity, spring.normal) > 0.0)
      {
        m_springs[m_numSprings++] = spring;
      }
    }
  }
  const double share = m_ticks > 0 ? 1.0 / static_cast<double>(m_ticks) : 0.0;
  m_solid.clearExternalForces();
  m_lastForce = Vec3{};
  if (m_relaxation < 1.0)
  {
    applyRelaxedLoad(share);
  }
  else
  {
    for (const std::uint32_t vertex : m_loaded)
    {
      const Vec3 force = m_forceSum[vertex] * share;
      m_solid.setExternalForce(vertex, force);
      m_lastForce += force;
      m_forceSum[vertex] = Vec3{};
      m_isLoaded[vertex] = 0;
    }
    m_loaded.clear();
  }
  m_ticks = 0;
  m_solid.setContactSprings(m_springs.data(), m_numSprings);
}

void TissueContact::applyRelaxedLoad(double share)
{
  // This step's footprint gets m_relaxation of the load; the last step's load, scaled to this
  // step's total force, the rest. The vertices of either are loaded.
  Vec3 total;
  for (const std::uint32_t vertex : m_loaded)
  {
    m_forceSum[vertex] = m_forceSum[vertex] * share;
    total += m_forceSum[vertex];
  }
  Vec3 before;
  for (const std::uint32_t vertex : m_appliedTo)
  {
    before += m_applied[vertex];
    if (m_isLoaded[vertex] == 0)
    {
      m_isLoaded[vertex] = 1;
      m_loaded.push_back(vertex);
    }
  }
  // Without a last load, or without a press now (the proxy left), this step's is the whole.
  const bool blend = norm(before) > 0.0 && norm(total) > 0.0;
  const double kept = blend ? (1.0 - m_relaxation) * norm(total) / norm(before) : 0.0;
  const double fresh = blend ? m_relaxation : 1.0;
  m_appliedTo.clear();
  for (const std::uint32_t vertex : m_loaded)
  {
    const Vec3 force = m_forceSum[vertex] * fresh + m_applied[vertex] * kept;
    m_applied[vertex] = force;
    if (force.x != 0.0 || force.y != 0.0 || force.z != 0.0)
    {
      m_appliedTo.push_back(vertex);
    }
    m_solid.setExternalForce(vertex, force);
    m_lastForce += force;
    m_forceSum[vertex] = Vec3{};
    m_isLoaded[vertex] = 0;
  }
  m_loaded.clear();
}

double TissueContact::maxDisplacement() const
{
  return m_solid.maxDisplacement();
}
} // namespace proxima
