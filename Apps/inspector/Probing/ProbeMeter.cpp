#include "Probing/ProbeMeter.h"

#include "Geometry/SphereTree.h"

#include <algorithm>
#include <cmath>

namespace proxima::inspector
{

ProbeMeter::ProbeMeter(const CollisionScene& scene, const ProbeMeterSettings& settings)
  : m_scene(scene)
  , m_settings(settings)
  , m_scratch(std::make_unique<SphereTreeScratch>())
{}

ProbeMeter::~ProbeMeter() = default;

void ProbeMeter::addTick(const HapticState& state)
{
  ++m_measurements.ticks;
  const double depth = norm(state.finger - state.proxy);
  m_measurements.deepestPress = std::max(m_measurements.deepestPress, depth);
  if (depth > m_settings.stopDepth)
  {
    if (!m_inStop)
    {
      m_inStop = true;
      ++m_measurements.stopCount;
      if (m_measurements.stops.size() < m_settings.stopsKept)
      {
        m_measurements.stops.push_back({state.time, state.time, state.proxy, state.finger, depth});
      }
    }
    if (m_measurements.stopCount <= m_measurements.stops.size())
    {
      ProbeStop& stop = m_measurements.stops.back();
      stop.endTime = state.time;
      if (depth > stop.depth)
      {
        stop.depth = depth;
        stop.proxy = state.proxy;
        stop.finger = state.finger;
      }
    }
  }
  else
  {
    m_inStop = false;
  }
  measureGap(state);
  m_last = state;
}

void ProbeMeter::measureGap(const HapticState& state)
{
  // The nearest wall: a gap no wider than widestGap has one within half of it.
  const Vec3 centre = state.proxy;
  bool found = false;
  double nearest = 0.5 * m_settings.widestGap;
  Vec3 wall;
  for (const CollisionObject& object : m_scene.objects)
  {
    const NearestTriangle hit = object.tree.nearest(object.mesh, centre, nearest, *m_scratch);
    if (hit.found && std::sqrt(hit.closest.squaredDistance) <= nearest)
    {
      found = true;
      nearest = std::sqrt(hit.closest.squaredDistance);
      wall = hit.closest.point;
    }
  }
  if (!found || !(nearest > 0.0))
  {
    return;
  }
  // Across: the line from the wall through the centre, on until the widest gap.
  const Vec3 direction = (centre - wall) / nearest;
  const double reach = m_settings.widestGap - nearest;
  const SweepQuery ray{centre, centre + direction * reach, 0.0, 0.0};
  double travelled = 1.0;
  bool crossed = false;
  for (const CollisionObject& object : m_scene.objects)
  {
    const SweepContact hit = object.tree.firstContact(object.mesh, ray, *m_scratch);
    if (hit.hit && hit.t < travelled)
    {
      travelled = hit.t;
      crossed = true;
    }
  }
  if (!crossed)
  {
    return;
  }
  const double width = nearest + travelled * reach;
  if (!m_measurements.narrowestGap || width < m_measurements.narrowestGap->width)
  {
    m_measurements.narrowestGap =
      ProbeGap{width, state.time, centre, wall, centre + direction * (travelled * reach)};
  }
}

bool ProbeMeter::mark()
{
  if (!m_last || m_last->numContacts == 0)
  {
    ++m_measurements.marksMissed;
    return false;
  }
  const ContactSnapshot& contact = m_last->contacts[0];
  m_measurements.markers.push_back(
    {m_last->time, contact.point, contact.normal, contact.object, contact.triangle});
  const std::size_t count = m_measurements.markers.size();
  if (count >= 2)
  {
    const ProbeMarker& from = m_measurements.markers[count - 2];
    const ProbeMarker& to = m_measurements.markers[count - 1];
    m_measurements.distances.push_back({count - 2, count - 1, norm(to.point - from.point),
                                        std::abs(dot(to.point - from.point, from.normal))});
  }
  return true;
}

} // namespace proxima::inspector
