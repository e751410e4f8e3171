// Stress: meshes a modeller or a scanner really produces and a kernel finds hard. Slivers with
// aspect ratios up to 1e12 (needles and caps, in a flat floor, in a shallow tent and loose in a
// soup), zero-area triangles (coincident corners, collinear corners, a point) and duplicated
// triangles (same and opposite winding) on a closed sphere. Every case is random with a recorded
// seed, and the oracle of Testing/ScriptedPaths looks at every tick.
#include "StressSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace proxima::stress
{
namespace
{
// A fan around a centre raised by `lift` over a polygon of side 2 * half in z = 0. Around the
// boundary, some neighbouring points are only `gap` apart (needles at the centre), and some
// boundary edges carry a cap: a third point `gap` outside the edge's midpoint.
TriangleSoup sliverFan(Random& random, double half, double lift, int* worstAspectDecade)
{
  TriangleSoup soup;
  soup.points.push_back({0, 0, lift});
  const int sides = random.integer(6, 20);
  double worst = 1.0;
  for (int i = 0; i < sides; ++i)
  {
    const double angle = 2.0 * std::numbers::pi * i / sides;
    const Vec3 p{half * std::cos(angle), half * std::sin(angle), 0.0};
    soup.points.push_back(p);
    if (random.uniform() < 0.5)
    {
      // A needle: the next point a tiny step on along the boundary.
      const double aspect = random.logUniform(1e2, 1e12);
      worst = std::max(worst, aspect);
      const Vec3 along{-std::sin(angle), std::cos(angle), 0.0};
      soup.points.push_back(p + along * (half / aspect));
    }
  }
  const auto n = static_cast<std::uint32_t>(soup.points.size());
  for (std::uint32_t i = 1; i < n; ++i)
  {
    const std::uint32_t j = i + 1 < n ? i + 1 : 1;
    soup.triangles.push_back({0, i, j});
    if (random.uniform() < 0.4)
    {
      // A cap over the edge (i, j), outside the fan: three nearly collinear corners.
      const Vec3 a = soup.points[i];
      const Vec3 b = soup.points[j];
      const double length = distance(a, b);
      const double aspect = random.logUniform(1e2, 1e12);
      const Vec3 mid = (a + b) * 0.5;
      const Vec3 outward = normalizedOrZero(Vec3{mid.x, mid.y, 0.0});
      if (length > 0.0)
      {
        worst = std::max(worst, aspect);
        soup.points.push_back(mid + outward * (length / aspect));
        soup.triangles.push_back({i, static_cast<std::uint32_t>(soup.points.size() - 1), j});
      }
    }
  }
  *worstAspectDecade = static_cast<int>(std::log10(worst));
  return soup;
}

// Loose slivers in a box `size` across: random orientation, long edge 5 to 20 mm, the third
// corner a 10^-2 .. 10^-12 fraction of it off the edge (a needle or a cap).
TriangleSoup sliverSoup(Random& random, int count, double size)
{
  TriangleSoup soup;
  for (int k = 0; k < count; ++k)
  {
    const Vec3 a{random.uniform(-0.5, 0.5) * size, random.uniform(-0.5, 0.5) * size,
                 random.uniform(-0.5, 0.5) * size};
    const Vec3 edge = random.direction() * random.uniform(0.005, 0.02);
    Vec3 off = cross(edge, random.direction());
    off = normalizedOrZero(off) * (norm(edge) / random.logUniform(1e2, 1e12));
    const bool needle = random.uniform() < 0.5;
    const Vec3 c = (needle ? a + edge : a + edge * 0.5) + off;
    const auto base = static_cast<std::uint32_t>(soup.points.size());
    soup.points.push_back(a);
    soup.points.push_back(a + edge);
    soup.points.push_back(c);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

// Finger paths over a surface near z = 0: presses at random points with strokes in random
// directions, and a circle under the surface.
FingerPath pressesAndCircle(Random& random, double half, double radius, double rate)
{
  std::vector<FingerPath> parts;
  for (int k = 0; k < 3; ++k)
  {
    PressAndStroke press;
    press.surfacePoint = {random.uniform(-0.6, 0.6) * half, random.uniform(-0.6, 0.6) * half, 0.0};
    press.approachHeight = 5.0 * radius;
    press.depth = random.uniform(0.5, 5.0) * radius;
    const Vec3 d = random.direction();
    press.strokeDirection = {d.x, d.y, 0.0};
    press.strokeLength = random.uniform(0.3, 1.2) * half;
    press.speed = random.logUniform(0.01, 1.0);
    parts.push_back(makePressAndStrokePath(press, rate));
  }
  parts.push_back(makeCirclePath({0, 0, -2.0 * radius}, {0, 0, 1}, {1, 0, 0}, 0.7 * half, 1.0,
                                 random.uniform(0.3, 1.0), rate));
  return concatenatePaths(parts, rate);
}

TEST(StressDegenerateMeshes, SliverFansToAspect1e12)
{
  runCases(1000, 12, [&](Random& random, StressCase& c) {
    c.proxy.radius = 0.001;
    const double half = 0.02;
    // Flat, or a shallow tent (convex), or a shallow funnel (concave) at the centre.
    const double lift = random.uniform() < 0.4 ? 0.0 : random.uniform(-0.3, 0.3) * half;
    int decade = 0;
    c.soup = sliverFan(random, half, lift, &decade);
    c.name = "sliver-fan/aspect-1e" + std::to_string(decade);
    c.path = pressesAndCircle(random, half, c.proxy.radius, c.rate);
    if (lift < 0.0)
    {
      // Free space is above; a funnel's centre is below the rim: lower the path with it.
      c.path = transform(c.path, Rotation{}, Vec3{0, 0, lift});
    }
  });
}

TEST(StressDegenerateMeshes, LooseSliverSoup)
{
  runCases(2000, 6, [&](Random& random, StressCase& c) {
    c.name = "sliver-soup";
    c.proxy.radius = random.logUniform(2e-4, 2e-3);
    c.soup = sliverSoup(random, 60, 0.04);
    Aabb box;
    box.expand(Vec3{-0.025, -0.025, -0.025});
    box.expand(Vec3{0.025, 0.025, 0.025});
    c.path = randomWander(random, box, 8, random.logUniform(0.02, 2.0), c.rate);
  });
}

// Zero-area and duplicated triangles added to a closed icosphere: each of a random subset of its
// triangles gets a twin (same or opposite winding, sharing points or with copies of them), or a
// zero-area neighbour on one of its edges or corners.
TEST(StressDegenerateMeshes, ZeroAreaAndDuplicatedTrianglesOnASphere)
{
  runCases(3000, 6, [&](Random& random, StressCase& c) {
    c.name = "sphere-with-degenerates";
    c.proxy.radius = 0.001;
    TriangleSoup soup = makeIcosphere(static_cast<std::uint32_t>(random.integer(2, 3)), 0.02);
    soup.pointNormals.clear();
    const std::size_t original = soup.triangles.size();
    for (std::size_t t = 0; t < original; ++t)
    {
      if (random.uniform() > 0.3)
      {
        continue;
      }
      auto [a, b, cc] = soup.triangles[t];
      const auto next = static_cast<std::uint32_t>(soup.points.size());
      switch (random.integer(0, 5))
      {
        case 0: // the same triangle again
          soup.triangles.push_back({a, b, cc});
          break;
        case 1: // opposite winding
          soup.triangles.push_back({a, cc, b});
          break;
        case 2: // a copy with its own points
          soup.points.push_back(soup.points[a]);
          soup.points.push_back(soup.points[b]);
          soup.points.push_back(soup.points[cc]);
          soup.triangles.push_back({next, next + 1, next + 2});
          break;
        case 3: // coincident corners: the edge (a, b) as a triangle
          soup.triangles.push_back({a, a, b});
          break;
        case 4: // collinear corners: the edge's midpoint as the third
          soup.points.push_back((soup.points[a] + soup.points[b]) * 0.5);
          soup.triangles.push_back({a, next, b});
          break;
        default: // a point
          soup.triangles.push_back({cc, cc, cc});
          break;
      }
    }
    c.soup = std::move(soup);
    Aabb bounds;
    for (const Vec3& p : c.soup.points)
    {
      bounds.expand(p);
    }
    std::vector<FingerPath> parts;
    for (const std::string& kind :
         {std::string("press-stroke"), std::string("circle"), std::string("jab")})
    {
      parts.push_back(makeDefaultPath(kind, bounds, c.proxy.radius, c.rate));
    }
    const Rotation rotation = Rotation::random(random);
    c.path = transform(concatenatePaths(parts, c.rate), rotation);
    c.soup = transform(std::move(c.soup), rotation);
  });
}

} // namespace
} // namespace proxima::stress
