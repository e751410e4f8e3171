// The person-like probe path of PathGenerators.h: seeded episodes of press-and-stroke, jab and
// wander at area-weighted random surface points, placed by the surface alone.
//
// Which side of a triangle is outside? A closed mesh would answer by ray parity, a consistently
// wound one by its winding, but the shared meshes include soups with overlapping, misoriented
// and open parts, where neither holds. What a person needs is simpler: a side from which the
// point can be reached. So the line through the point along the triangle's normal is cut
// against every triangle, and the side on which it crosses nothing (the point is visible from
// outside the mesh along the normal) is outward. A point with no such side (in a concavity, or
// inside a soup's overlapping parts) is drawn again; a point with both (an open sheet) takes the
// side its winding gives. On a closed mesh the clear side is always the outside, because the
// inward line must leave the volume again through some triangle.
#include "Paths/PathGenerators.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

namespace proxima
{
namespace
{
// The same numbers on every standard library: std::mt19937_64 is specified bit for bit, the
// standard distributions are not, so the mapping to [0, 1) is ours (the top 53 bits).
class ProbeRandom
{
public:
  explicit ProbeRandom(std::uint64_t seed)
    : m_engine(seed)
  {}
  double uniform() { return static_cast<double>(m_engine() >> 11) * 0x1.0p-53; }
  double between(double low, double high) { return low + (high - low) * uniform(); }

private:
  std::mt19937_64 m_engine;
};

Vec3 unitPerpendicular(const Vec3& v)
{
  const Vec3 helper = std::fabs(v.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalizedOrZero(cross(v, helper));
}

// Where the line origin + t direction meets the triangle, as t; false when it misses or runs
// in the triangle's plane. Edges count as hits, so a line through a shared edge counts twice:
// that only makes a clear side look blocked, never the reverse.
bool lineMeetsTriangle(const Vec3& origin, const Vec3& direction, const TriangleCorners& t,
                       double& parameter)
{
  const Vec3 ab = t.b - t.a;
  const Vec3 ac = t.c - t.a;
  const Vec3 p = cross(direction, ac);
  const double determinant = dot(ab, p);
  if (determinant == 0.0)
  {
    return false;
  }
  const double inverse = 1.0 / determinant;
  const Vec3 s = origin - t.a;
  const double u = dot(s, p) * inverse;
  if (u < 0.0 || u > 1.0)
  {
    return false;
  }
  const Vec3 q = cross(s, ab);
  const double v = dot(direction, q) * inverse;
  if (v < 0.0 || u + v > 1.0)
  {
    return false;
  }
  parameter = dot(ac, q) * inverse;
  return true;
}

struct SurfaceSite
{
  Vec3 point;
  Vec3 outward;
  bool visible = false;
};

class ProbeBuilder
{
public:
  ProbeBuilder(const std::vector<ProbeSurface>& surfaces, const ProbeOptions& options,
               std::vector<ProbePhase>* phases)
    : m_surfaces(surfaces)
    , m_options(options)
    , m_phases(phases)
    , m_random(options.seed)
  {
    for (const ProbeSurface& surface : m_surfaces)
    {
      for (std::uint32_t i = 0; i < surface.mesh->numTriangles(); ++i)
      {
        const TriangleCorners& t = surface.mesh->corners(i);
        m_totalArea += 0.5 * norm(cross(t.b - t.a, t.c - t.a));
        m_cumulativeArea.push_back(m_totalArea);
      }
      m_bounds.expand(surface.mesh->bounds().lower);
      m_bounds.expand(surface.mesh->bounds().upper);
    }
    if (!(m_totalArea > 0.0))
    {
      throw std::invalid_argument("makeProbePath: the surfaces have no area");
    }
    m_lineEpsilon = 1e-9 * m_bounds.diagonal();
    // Outside this sphere the finger touches nothing, whatever the approach distance.
    m_center = m_bounds.center();
    m_outerRadius = 0.5 * m_bounds.diagonal() + m_options.approachDistanceMax;
  }

  FingerPath build()
  {
    Vec3 exitPoint;
    Vec3 exitOutward;
    bool first = true;
    while (first || endTime() < m_options.duration)
    {
      const double kind = m_random.uniform();
      const double standoff =
        m_random.between(m_options.approachDistanceMin, m_options.approachDistanceMax);
      const SurfaceSite site = drawSite(standoff);
      const Vec3 start = site.point + site.outward * standoff;
      if (first)
      {
        append(start, ProbePhase::Transit);
        first = false;
      }
      else
      {
        transit(exitPoint, exitOutward, start, site.outward);
      }
      if (kind < m_options.jabFraction)
      {
        jab(site, start, exitPoint, exitOutward);
      }
      else if (kind < m_options.jabFraction + m_options.wanderFraction)
      {
        wander(site, exitPoint, exitOutward);
      }
      else
      {
        press(site, standoff, exitPoint, exitOutward);
      }
    }
    return std::move(m_path);
  }

  // makeSurfacePath's paths: `kind` at sites drawn as the probe's, with the lengths given.
  FingerPath buildNamed(const std::string& kind, double standoff, double radius, double stretch)
  {
    const double size = m_bounds.diagonal();
    if (kind == "jab")
    {
      // Five jabs at 1 m/s at one point, from close above it, a pause between.
      const double near = std::max(3.0 * radius, 0.25 * standoff);
      const SurfaceSite site = drawSite(near);
      const Vec3 start = site.point + site.outward * near;
      append(start, ProbePhase::Transit);
      for (int i = 0; i < 5; ++i)
      {
        moveTo(site.point - site.outward * std::max(0.0, stretch - radius), 1.0, ProbePhase::Jab);
        moveTo(start, 1.0, ProbePhase::Jab);
        hold(0.02, ProbePhase::Transit);
      }
      return std::move(m_path);
    }
    if (kind == "wander")
    {
      // In along a normal and straight through the whole object.
      const SurfaceSite site = drawSite(standoff);
      append(site.point + site.outward * standoff, ProbePhase::Transit);
      Vec3 exitPoint;
      Vec3 exitOutward;
      wander(site, exitPoint, exitOutward);
      return std::move(m_path);
    }

    // A press, a slide or a circle: the finger at `depth` below the surface gives the proxy,
    // resting r above it, the stretch asked for.
    const bool slide = kind == "slide";
    const bool circle = kind == "circle";
    const double depth = (slide ? 0.5 * radius : stretch) - radius;
    const double approachSpeed = 2.0 * standoff; // half a second from the standoff
    const double circleRadius = std::min(0.01, 0.05 * size);
    const double length = circle
                            ? 2.0 * 3.14159265358979323846 * circleRadius
                            : (slide ? std::min(0.04, 0.5 * size) : std::min(0.02, 0.3 * size));
    const double step = length / ((slide || circle ? 2.0 : 1.0) * m_options.rate);
    constexpr int kTries = 24;
    for (int attempt = 0; attempt < kTries; ++attempt)
    {
      m_path = FingerPath{};
      const SurfaceSite site = drawSite(standoff);
      const double angle = m_random.between(0.0, 2.0 * 3.14159265358979323846);
      if (!site.visible)
      {
        continue;
      }
      const Vec3 e1 = unitPerpendicular(site.outward);
      const Vec3 e2 = cross(site.outward, e1);
      const Vec3 heading = e1 * std::cos(angle) + e2 * std::sin(angle);
      const Vec3 start = site.point + site.outward * standoff;
      append(start, ProbePhase::Transit);
      moveTo(site.point - site.outward * depth, approachSpeed, ProbePhase::Approach);
      Vec3 normal = site.outward;
      const double walked = walkStroke(site, heading, circle ? 1.0 / circleRadius : 0.0, depth,
                                       step, length, radius, normal);
      hold(0.2, ProbePhase::Dwell);
      moveTo(current() + normal * (depth + standoff), approachSpeed, ProbePhase::Retract);
      if (walked >= 0.5 * length)
      {
        return std::move(m_path);
      }
    }
    throw std::runtime_error(
      "no place on the surface where a " + kind + " of " + std::to_string(length) +
      " m follows the surface for half its "
      "length (tried " +
      std::to_string(kTries) + " points): the mesh has no patch that smooth or that large");
  }

private:
  // A stroke that walks on the surface, for makeSurfacePath: each row one `step` from the last
  // along the heading laid in the local tangent plane (turning `turn` radians a metre: a
  // circle), put back on the surface at the nearest point and pushed `depth` in along the local
  // normal. The probe's strokes follow a straight tangent line instead, which leaves a bumpy
  // scan after a millimetre or less; walking follows it. The walk ends where it jumps (a step
  // landing more than three steps away: a crease or a gap), where it makes no headway, at a
  // sharp edge and where the proxy of `radius` cannot follow. Returns the length walked.
  double walkStroke(const SurfaceSite& site, Vec3 heading, double turn, double depth, double step,
                    double length, double radius, Vec3& normal)
  {
    Vec3 onSurface = site.point;
    // Queried from above the surface by a few steps, so that the offset to the nearest point
    // gives a normal that turns smoothly over convex facet edges.
    const double lift = 4.0 * step;
    double walked = 0.0;
    while (walked + step <= length)
    {
      Vec3 along = normalizedOrZero(heading - normal * dot(heading, normal));
      if (along == Vec3{})
      {
        break;
      }
      if (turn != 0.0)
      {
        const Vec3 side = cross(normal, along);
        along = along * std::cos(turn * step) + side * std::sin(turn * step);
      }
      const Vec3 query = onSurface + along * step + normal * lift;
      Vec3 triangleNormal;
      const NearestTriangle found = nearest(query, 2.0 * lift + 4.0 * step, triangleNormal);
      const Vec3 moved = found.closest.point - onSurface;
      // A jump (a crease, a gap) or no headway (bounced back at an edge) ends the walk.
      if (!found.found || norm(moved) > 3.0 * step || dot(moved, along) < 0.1 * step)
      {
        break;
      }
      const Vec3 offset = query - found.closest.point;
      Vec3 local = norm(offset) > 0.5 * lift ? normalizedOrZero(offset) : triangleNormal;
      if (dot(local, normal) < 0.0)
      {
        local = -local;
      }
      // A sharp edge ends it too: pressed over it, the finger would go into the next face. So
      // does a groove narrower than the proxy, which stays out of it while the finger follows
      // its floor: the proxy's place over the new point must be free.
      Vec3 unused;
      // And a wall thinner than the press, which the finger would come out of the far side of.
      if (dot(local, normal) < std::cos(0.25 * 3.14159265358979323846) ||
          nearest(found.closest.point + local * radius, 0.7 * radius, unused).found ||
          (depth > 0.0 && nearest(found.closest.point - local * depth, 0.5 * depth, unused).found))
      {
        break;
      }
      walked += distance(found.closest.point, onSurface);
      onSurface = found.closest.point;
      normal = local;
      heading = along;
      append(onSurface - normal * depth, ProbePhase::Stroke);
    }
    return walked;
  }

  double endTime() const { return m_path.empty() ? 0.0 : m_path.endTime(); }
  const Vec3& current() const { return m_path.positions.back(); }

  // Rows at exactly tick / rate (computed, not summed, so no drift).
  void append(const Vec3& position, ProbePhase phase)
  {
    m_path.append(static_cast<double>(m_path.size()) / m_options.rate, position);
    if (m_phases != nullptr)
    {
      m_phases->push_back(phase);
    }
  }

  // Straight to `target` at no more than `speed`, arriving on a tick.
  void moveTo(const Vec3& target, double speed, ProbePhase phase)
  {
    const Vec3 from = current();
    const double steps = std::max(1.0, std::ceil(distance(from, target) * m_options.rate / speed));
    for (double i = 1; i <= steps; ++i)
    {
      append(i == steps ? target : from + (target - from) * (i / steps), phase);
    }
  }

  void hold(double duration, ProbePhase phase)
  {
    const Vec3 here = current();
    const auto ticks =
      static_cast<std::size_t>(std::max(1.0, std::round(duration * m_options.rate)));
    for (std::size_t i = 0; i < ticks; ++i)
    {
      append(here, phase);
    }
  }

  // Crossings of the line point + t direction with every triangle, for t > 0 and t < 0.
  void countCrossings(const Vec3& point, const Vec3& direction, int& ahead, int& behind) const
  {
    ahead = 0;
    behind = 0;
    for (const ProbeSurface& surface : m_surfaces)
    {
      for (std::uint32_t i = 0; i < surface.mesh->numTriangles(); ++i)
      {
        double t = 0.0;
        if (lineMeetsTriangle(point, direction, surface.mesh->corners(i), t))
        {
          ahead += t > m_lineEpsilon ? 1 : 0;
          behind += t < -m_lineEpsilon ? 1 : 0;
        }
      }
    }
  }

  bool segmentIsClear(const Vec3& from, const Vec3& to) const
  {
    const double length = distance(from, to);
    if (!(length > m_lineEpsilon))
    {
      return true;
    }
    const Vec3 direction = (to - from) / length;
    for (const ProbeSurface& surface : m_surfaces)
    {
      for (std::uint32_t i = 0; i < surface.mesh->numTriangles(); ++i)
      {
        double t = 0.0;
        if (lineMeetsTriangle(from, direction, surface.mesh->corners(i), t) && t >= 0.0 &&
            t <= length)
        {
          return false;
        }
      }
    }
    return true;
  }

  NearestTriangle nearest(const Vec3& point, double maxDistance, Vec3& normal) const
  {
    NearestTriangle best;
    for (const ProbeSurface& surface : m_surfaces)
    {
      const NearestTriangle found =
        surface.tree->nearest(*surface.mesh, point, maxDistance, m_scratch);
      if (found.found &&
          (!best.found || found.closest.squaredDistance < best.closest.squaredDistance))
      {
        best = found;
        const TriangleCorners& t = surface.mesh->corners(found.triangle);
        normal = normalizedOrZero(cross(t.b - t.a, t.c - t.a));
      }
    }
    return best;
  }

  SurfaceSite drawSite(double standoff)
  {
    // Enough draws that a mesh with a small visible fraction still gets visible points; the
    // last draw is used anyway (its approach may then start inside another part, as a careless
    // hand's would).
    constexpr int kMaxDraws = 32;
    SurfaceSite site;
    for (int draw = 0; draw < kMaxDraws; ++draw)
    {
      const double where = m_random.uniform() * m_totalArea;
      const auto index = static_cast<std::size_t>(
        std::upper_bound(m_cumulativeArea.begin(), m_cumulativeArea.end(), where) -
        m_cumulativeArea.begin());
      const TriangleCorners& t = cornersAt(std::min(index, m_cumulativeArea.size() - 1));
      // Uniform over the triangle: fold the unit square's upper half back onto the lower.
      double u = m_random.uniform();
      double v = m_random.uniform();
      if (u + v > 1.0)
      {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      site.point = t.a + (t.b - t.a) * u + (t.c - t.a) * v;
      const Vec3 winding = normalizedOrZero(cross(t.b - t.a, t.c - t.a));
      int ahead = 0;
      int behind = 0;
      countCrossings(site.point, winding, ahead, behind);
      site.visible = ahead == 0 || behind == 0;
      if (!site.visible)
      {
        continue;
      }
      // Both sides clear is an open sheet: its winding decides.
      site.outward = ahead == 0 ? winding : -winding;
      // The approach must start clear of the surface (proxima run refuses a path that starts in
      // contact), sideways too: half the approach distance keeps a 3 mm proxy clear.
      Vec3 unused;
      if (!nearest(site.point + site.outward * standoff, 0.5 * standoff, unused).found)
      {
        return site;
      }
    }
    return site;
  }

  const TriangleCorners& cornersAt(std::size_t index) const
  {
    for (const ProbeSurface& surface : m_surfaces)
    {
      if (index < surface.mesh->numTriangles())
      {
        return surface.mesh->corners(static_cast<std::uint32_t>(index));
      }
      index -= surface.mesh->numTriangles();
    }
    return m_surfaces.back().mesh->corners(0);
  }

  // How far from `point` along unit `direction` the outer sphere is (0 if already outside).
  double toOuterSphere(const Vec3& point, const Vec3& direction) const
  {
    const Vec3 offset = point - m_center;
    const double b = dot(offset, direction);
    const double c = squaredNorm(offset) - m_outerRadius * m_outerRadius;
    const double discriminant = b * b - c;
    return discriminant > 0.0 ? std::max(0.0, -b + std::sqrt(discriminant)) : 0.0;
  }

  void arcOnOuterSphere(const Vec3& to, double speed)
  {
    const Vec3 u0 = normalizedOrZero(current() - m_center);
    const Vec3 u1 = normalizedOrZero(to - m_center);
    const double angle = std::acos(std::clamp(dot(u0, u1), -1.0, 1.0));
    // Nearly opposite directions have no unique great circle: go by a perpendicular one.
    if (angle > 3.0)
    {
      arcOnOuterSphere(m_center + unitPerpendicular(u0) * m_outerRadius, speed);
      arcOnOuterSphere(to, speed);
      return;
    }
    const double steps = std::max(1.0, std::ceil(angle * m_outerRadius * m_options.rate / speed));
    for (double i = 1; i <= steps; ++i)
    {
      const double s = i / steps;
      const Vec3 direction =
        angle < 1e-9
          ? u1
          : (u0 * std::sin((1.0 - s) * angle) + u1 * std::sin(s * angle)) / std::sin(angle);
      append(m_center + normalizedOrZero(direction) * m_outerRadius, ProbePhase::Transit);
    }
  }

  void transit(const Vec3& from, const Vec3& fromOutward, const Vec3& to, const Vec3& toOutward)
  {
    const double speed = m_random.between(m_options.transitSpeedMin, m_options.transitSpeedMax);
    if (segmentIsClear(from, to))
    {
      moveTo(to, speed, ProbePhase::Transit);
      return;
    }
    // Lift out, go over the outer sphere and come in along the next approach line.
    const Vec3 entry = to + toOutward * toOuterSphere(to, toOutward);
    moveTo(from + fromOutward * toOuterSphere(from, fromOutward), speed, ProbePhase::Transit);
    arcOnOuterSphere(entry, speed);
    moveTo(to, speed, ProbePhase::Transit);
  }

  void jab(const SurfaceSite& site, const Vec3& start, Vec3& exitPoint, Vec3& exitOutward)
  {
    const double depth = m_random.between(m_options.pressDepthMin, m_options.pressDepthMax);
    const double speed = m_random.between(m_options.jabSpeedMin, m_options.jabSpeedMax);
    moveTo(site.point - site.outward * depth, speed, ProbePhase::Jab);
    moveTo(start, speed, ProbePhase::Jab);
    exitPoint = start;
    exitOutward = site.outward;
  }

  void wander(const SurfaceSite& site, Vec3& exitPoint, Vec3& exitOutward)
  {
    const double speed = m_random.between(m_options.wanderSpeedMin, m_options.wanderSpeedMax);
    const Vec3 through = -site.outward;
    exitPoint = site.point + through * toOuterSphere(site.point, through);
    exitOutward = through;
    moveTo(exitPoint, speed, ProbePhase::Wander);
  }

  // The stroke row at `s` along the tangent line from the site: the nearest surface point,
  // pushed `depth` in along the local outward normal, which is the direction from that point
  // to the line point where they differ (edges and vertices included), else the triangle's,
  // either way turned to agree with the previous normal so the stroke stays on one side.
  bool strokeRow(const Vec3& linePoint, double depth, double reach, Vec3& normal, Vec3& row) const
  {
    Vec3 triangleNormal;
    const NearestTriangle found = nearest(linePoint, reach, triangleNormal);
    if (!found.found)
    {
      return false;
    }
    const Vec3 offset = linePoint - found.closest.point;
    const double offsetLength = norm(offset);
    Vec3 local = offsetLength > 1e-9 ? offset / offsetLength : triangleNormal;
    if (dot(local, normal) < 0.0)
    {
      local = -local;
    }
    normal = local;
    row = found.closest.point - normal * depth;
    return true;
  }

  void press(const SurfaceSite& site, double standoff, Vec3& exitPoint, Vec3& exitOutward)
  {
    const double depth = m_random.between(m_options.pressDepthMin, m_options.pressDepthMax);
    const double approachSpeed =
      m_random.between(m_options.approachSpeedMin, m_options.approachSpeedMax);
    const double length = m_random.between(m_options.strokeLengthMin, m_options.strokeLengthMax);
    const double speed = m_random.between(m_options.strokeSpeedMin, m_options.strokeSpeedMax);
    const double dwell = m_random.between(m_options.dwellMin, m_options.dwellMax);
    const double angle = m_random.between(0.0, 2.0 * 3.14159265358979323846);
    const Vec3 e1 = unitPerpendicular(site.outward);
    const Vec3 e2 = cross(site.outward, e1);
    const Vec3 tangent = e1 * std::cos(angle) + e2 * std::sin(angle);

    moveTo(site.point - site.outward * depth, approachSpeed, ProbePhase::Approach);

    // Each stroke row is one tick's travel (speed / rate) from the last: the surface under a
    // straight line is not straight, so the line parameter is found by a secant step and, where
    // that misses (the row swings fast round a facet edge), by bisection of a bracket. A row that
    // cannot be placed at that distance (the nearest point jumps across a crease or to another
    // part, or stops moving) ends the stroke: a finger does not teleport.
    Vec3 normal = site.outward;
    const double step = speed / m_options.rate;
    const double reach = length + standoff;
    const double tolerance = 1e-3 * step;
    double s = 0.0;
    double increment = step;
    double travelled = 0.0;
    while (travelled + step <= length && s < 3.0 * length)
    {
      // Gap from the last row to the row at s + delta; negative when there is no surface there.
      Vec3 row;
      Vec3 rowNormal;
      auto gapAt = [&](double delta) {
        rowNormal = normal;
        return strokeRow(site.point + tangent * (s + delta), depth, reach, rowNormal, row)
                 ? distance(row, current())
                 : -1.0;
      };
      double gap = gapAt(increment);
      if (gap > tolerance && std::fabs(gap - step) > tolerance)
      {
        increment *= step / gap;
        gap = gapAt(increment);
      }
      if (gap >= 0.0 && std::fabs(gap - step) > tolerance)
      {
        double low = 0.0;
        double high = increment;
        while (gap >= 0.0 && gap < step && high < 3.0 * length)
        {
          low = high;
          high *= 2.0;
          gap = gapAt(high);
        }
        while (gap >= 0.0 && std::fabs(gap - step) > tolerance && high - low > 1e-12 * length)
        {
          const double middle = 0.5 * (low + high);
          gap = gapAt(middle);
          (gap >= 0.0 && gap < step ? low : high) = middle;
        }
        increment = gap >= 0.0 && gap < step ? low : high;
        if (gap >= 0.0 && std::fabs(gap - step) > tolerance)
        {
          gap = gapAt(increment);
        }
      }
      if (gap < 0.0 || std::fabs(gap - step) > tolerance)
      {
        break;
      }
      s += increment;
      travelled += gap;
      normal = rowNormal;
      append(row, ProbePhase::Stroke);
    }
    hold(dwell, ProbePhase::Dwell);
    const double liftSpeed =
      m_random.between(m_options.approachSpeedMin, m_options.approachSpeedMax);
    exitPoint = current() + normal * (depth + standoff);
    exitOutward = normal;
    moveTo(exitPoint, liftSpeed, ProbePhase::Retract);
  }

  const std::vector<ProbeSurface>& m_surfaces;
  const ProbeOptions& m_options;
  std::vector<ProbePhase>* m_phases;
  ProbeRandom m_random;
  std::vector<double> m_cumulativeArea;
  double m_totalArea = 0.0;
  Aabb m_bounds;
  double m_lineEpsilon = 0.0;
  Vec3 m_center;
  double m_outerRadius = 0.0;
  mutable SphereTreeScratch m_scratch;
  FingerPath m_path;
};

void checkRange(double low, double high, const char* name)
{
  if (!(low >= 0.0 && low <= high && std::isfinite(high)))
  {
    throw std::invalid_argument(std::string("makeProbePath: ") + name +
                                " needs 0 <= minimum <= maximum");
  }
}

void checkOptions(const ProbeOptions& o)
{
  if (!(o.rate > 0.0 && std::isfinite(o.rate)) || !(o.duration >= 0.0 && std::isfinite(o.duration)))
  {
    throw std::invalid_argument("makeProbePath: rate must be positive, duration finite");
  }
  checkRange(o.approachDistanceMin, o.approachDistanceMax, "approachDistance");
  checkRange(o.pressDepthMin, o.pressDepthMax, "pressDepth");
  checkRange(o.strokeLengthMin, o.strokeLengthMax, "strokeLength");
  checkRange(o.dwellMin, o.dwellMax, "dwell");
  checkRange(o.jabFraction, 1.0 - o.wanderFraction, "jabFraction + wanderFraction");
  // Speeds divide lengths: zero is out too.
  for (const auto& [low, high, name] :
       {std::tuple{o.approachSpeedMin, o.approachSpeedMax, "approachSpeed"},
        std::tuple{o.strokeSpeedMin, o.strokeSpeedMax, "strokeSpeed"},
        std::tuple{o.jabSpeedMin, o.jabSpeedMax, "jabSpeed"},
        std::tuple{o.wanderSpeedMin, o.wanderSpeedMax, "wanderSpeed"},
        std::tuple{o.transitSpeedMin, o.transitSpeedMax, "transitSpeed"}})
  {
    checkRange(low, high, name);
    if (!(low > 0.0))
    {
      throw std::invalid_argument(std::string("makeProbePath: ") + name + " must be positive");
    }
  }
}
} // namespace

FingerPath makeProbePath(const std::vector<ProbeSurface>& surfaces, const ProbeOptions& options,
                         std::vector<ProbePhase>* phases)
{
  checkOptions(options);
  if (surfaces.empty())
  {
    throw std::invalid_argument("makeProbePath: no surfaces");
  }
  for (const ProbeSurface& surface : surfaces)
  {
    if (surface.mesh == nullptr || surface.tree == nullptr)
    {
      throw std::invalid_argument("makeProbePath: a surface without its mesh or tree");
    }
  }
  if (phases != nullptr)
  {
    phases->clear();
  }
  return ProbeBuilder(surfaces, options, phases).build();
}

FingerPath makeSurfacePath(const std::string& kind, const std::vector<ProbeSurface>& surfaces,
                           const SurfacePathOptions& options)
{
  const std::vector<std::string>& kinds = defaultPathKinds();
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
  {
    throw std::invalid_argument("unknown path kind '" + kind +
                                "' (known: slide, press-stroke, circle, jab, wander)");
  }
  if (surfaces.empty())
  {
    throw std::invalid_argument("makeSurfacePath: no surfaces");
  }
  Aabb bounds;
  for (const ProbeSurface& surface : surfaces)
  {
    if (surface.mesh == nullptr || surface.tree == nullptr)
    {
      throw std::invalid_argument("makeSurfacePath: a surface without its mesh or tree");
    }
    bounds.expand(surface.mesh->bounds().lower);
    bounds.expand(surface.mesh->bounds().upper);
  }
  const double size = bounds.diagonal();
  const double stretch = options.stretch > 0.0 ? options.stretch : std::min(0.003, 0.05 * size);
  // Clear of the surface by more than the proxy, and a few percent of the object at least.
  const double standoff = std::max(3.0 * options.radius, std::min(0.02, 0.1 * size));
  ProbeOptions probe;
  probe.seed = options.seed;
  probe.rate = options.rate;
  probe.duration = 0.0;
  probe.approachDistanceMin = probe.approachDistanceMax = standoff;
  // A wander crosses the object in about two seconds.
  probe.wanderSpeedMin = probe.wanderSpeedMax = std::max(0.05, 0.5 * size);
  checkOptions(probe);
  return ProbeBuilder(surfaces, probe, nullptr).buildNamed(kind, standoff, options.radius, stretch);
}

FingerPath makeProbePath(const TriangleMesh& mesh, const ProbeOptions& options,
                         std::vector<ProbePhase>* phases)
{
  SphereTree tree;
  tree.build(mesh);
  return makeProbePath({ProbeSurface{&mesh, &tree}}, options, phases);
}

} // namespace proxima
