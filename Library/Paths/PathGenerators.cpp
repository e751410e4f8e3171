#include "Paths/PathGenerators.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace proxima
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// Samples the segment at the rate, including both ends, starting at `startTime`.
void appendSegment(FingerPath& path, const Vec3& from, const Vec3& to, double duration, double rate)
{
  const double startTime = path.empty() ? 0.0 : path.endTime() + 1.0 / rate;
  const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(duration * rate)));
  for (std::size_t i = 0; i <= steps; ++i)
  {
    const double s = static_cast<double>(i) / static_cast<double>(steps);
    path.append(startTime + s * duration, from + (to - from) * s);
  }
}

void appendAtSpeed(FingerPath& path, const Vec3& from, const Vec3& to, double speed, double rate)
{
  appendSegment(path, from, to, distance(from, to) / speed, rate);
}

Vec3 anyPerpendicular(const Vec3& v)
{
  const Vec3 helper = std::fabs(v.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalizedOrZero(cross(v, helper));
}
} // namespace

FingerPath makeSlidePath(const Vec3& from, const Vec3& to, double duration, double rate)
{
  FingerPath path;
  appendSegment(path, from, to, duration, rate);
  return path;
}

FingerPath makePressAndStrokePath(const PressAndStroke& p, double rate)
{
  const Vec3 inward = normalizedOrZero(p.inward);
  Vec3 stroke = p.strokeDirection - inward * dot(p.strokeDirection, inward);
  stroke = normalizedOrZero(stroke);
  if (stroke == Vec3{})
  {
    stroke = anyPerpendicular(inward);
  }
  const Vec3 above = p.surfacePoint - inward * p.approachHeight;
  const Vec3 pressed = p.surfacePoint + inward * p.depth;
  const Vec3 stroked = pressed + stroke * p.strokeLength;
  const Vec3 lifted = stroked - inward * (p.depth + p.approachHeight);
  FingerPath path;
  appendAtSpeed(path, above, pressed, p.speed, rate);
  appendAtSpeed(path, pressed, stroked, p.speed, rate);
  appendAtSpeed(path, stroked, lifted, p.speed, rate);
  return path;
}

FingerPath makeCirclePath(const Vec3& center, const Vec3& axis, const Vec3& startDir, double radius,
                          double revolutions, double duration, double rate)
{
  const Vec3 w = normalizedOrZero(axis);
  Vec3 u = normalizedOrZero(startDir - w * dot(startDir, w));
  if (u == Vec3{})
  {
    u = anyPerpendicular(w);
  }
  const Vec3 v = cross(w, u);
  FingerPath path;
  const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(duration * rate)));
  for (std::size_t i = 0; i <= steps; ++i)
  {
    const double s = static_cast<double>(i) / static_cast<double>(steps);
    const double angle = 2.0 * kPi * revolutions * s;
    path.append(s * duration, center + (u * std::cos(angle) + v * std::sin(angle)) * radius);
  }
  return path;
}

FingerPath makeJabPath(const Jabs& jabs, double rate)
{
  FingerPath path;
  for (const Vec3& direction : jabs.fromDirections)
  {
    const Vec3 d = normalizedOrZero(direction);
    const Vec3 start = jabs.target + d * jabs.standoff;
    const Vec3 deep = jabs.target - d * jabs.overshoot;
    appendSegment(path, start, start, jabs.pause, rate);
    appendAtSpeed(path, start, deep, jabs.speed, rate);
    appendAtSpeed(path, deep, start, jabs.speed, rate);
  }
  return path;
}

FingerPath concatenatePaths(const std::vector<FingerPath>& parts, double rate)
{
  FingerPath joined;
  for (const FingerPath& part : parts)
  {
    if (part.empty())
    {
      continue;
    }
    const double shift = (joined.empty() ? 0.0 : joined.endTime() + 1.0 / rate) - part.startTime();
    for (std::size_t i = 0; i < part.size(); ++i)
    {
      joined.append(part.times[i] + shift, part.positions[i]);
    }
  }
  return joined;
}

const std::vector<std::string>& defaultPathKinds()
{
  static const std::vector<std::string> kinds = {"slide", "press-stroke", "circle", "jab",
                                                 "wander"};
  return kinds;
}

FingerPath makeDefaultPath(const std::string& kind, const Aabb& bounds, double radius, double rate)
{
  const Vec3 center = bounds.center();
  const Vec3 extent = bounds.extent();
  const double size = std::max({extent.x, extent.y, extent.z, radius});
  const Vec3 top{center.x, center.y, bounds.upper.z};
  const double clearance = 2.0 * radius + 0.05 * size;
  if (kind == "press-stroke")
  {
    PressAndStroke p;
    p.surfacePoint = top;
    p.approachHeight = clearance;
    p.depth = std::min(0.25 * extent.z, 0.1 * size) + radius;
    p.strokeDirection = extent.x >= extent.y ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    p.strokeLength = 0.4 * std::max(extent.x, extent.y);
    p.speed = std::max(0.02, 0.5 * size); // about two seconds whatever the size
    // Start the stroke off centre so it crosses the middle of the top.
    p.surfacePoint = top - p.strokeDirection * (0.5 * p.strokeLength);
    return makePressAndStrokePath(p, rate);
  }
  if (kind == "slide")
  {
    const Vec3 along = extent.x >= extent.y ? Vec3{extent.x, 0, 0} : Vec3{0, extent.y, 0};
    const Vec3 skim{0, 0, radius * 0.5};
    return makeSlidePath(top - along * 0.6 + skim, top + along * 0.6 + skim, 2.0, rate);
  }
  if (kind == "circle")
  {
    const double ringRadius = 0.45 * std::min(extent.x, extent.y);
    const FingerPath descend =
      makeSlidePath(top + Vec3{ringRadius, 0, clearance},
                    Vec3{center.x + ringRadius, center.y, center.z}, 1.0, rate);
    const FingerPath ring =
      makeCirclePath(center, Vec3{0, 0, 1}, Vec3{1, 0, 0}, ringRadius, 2.0, 4.0, rate);
    return concatenatePaths({descend, ring}, rate);
  }
  if (kind == "jab")
  {
    Jabs jabs;
    jabs.target = top;
    jabs.standoff = clearance;
    jabs.overshoot = std::min(0.25 * extent.z, 0.1 * size) + radius;
    jabs.fromDirections = {{0, 0, 1}, {1, 0, 1}, {-1, 0, 1}, {0, 1, 1}, {0, -1, 1}};
    return makeJabPath(jabs, rate);
  }
  if (kind == "wander")
  {
    const Vec3 half = extent * 0.5 + Vec3{clearance, clearance, clearance};
    return makeSlidePath(center - Vec3{half.x, 0.3 * half.y, 0.2 * half.z},
                         center + Vec3{half.x, 0.3 * half.y, 0.2 * half.z}, 3.0, rate);
  }
  throw std::invalid_argument("unknown path kind '" + kind +
                              "' (known: slide, press-stroke, circle, jab, wander)");
}

} // namespace proxima
