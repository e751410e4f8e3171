// Stress: constraint planes that are nearly one plane, or too many through one point. Two faces
// meeting at 10^-12 .. 10^-2 rad from flat (a crease, convex or concave) and two planes crossing
// at such an angle; pyramid apexes and funnels of 4 to 16 faces at random slopes and
// orientations; concave trihedral corners whose three walls have random normals, entered along
// directions sampled on the sphere. Random with recorded seeds; the oracle watches every tick.
#include "StressSupport.h"

#include "Paths/PathGenerators.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxima::stress
{
namespace
{
// Presses at random points near the origin in the plane z = 0 with strokes across the y axis
// (the crease), and a slide along it: the finger crosses the crease at many angles.
FingerPath acrossTheCrease(Random& random, double half, double radius, double rate)
{
  std::vector<FingerPath> parts;
  for (int k = 0; k < 3; ++k)
  {
    PressAndStroke press;
    press.surfacePoint = {random.uniform(-0.4, 0.0) * half, random.uniform(-0.5, 0.5) * half, 0.0};
    press.approachHeight = 4.0 * radius;
    press.depth = random.uniform(0.5, 4.0) * radius;
    press.strokeDirection = {1.0, random.uniform(-1.0, 1.0), 0.0};
    press.strokeLength = random.uniform(0.4, 0.8) * half;
    press.speed = random.logUniform(0.01, 0.5);
    parts.push_back(makePressAndStrokePath(press, rate));
  }
  const double depth = random.uniform(0.5, 3.0) * radius;
  parts.push_back(makeSlidePath({0.0, -0.5 * half, -depth}, {0.0, 0.5 * half, -depth},
                                random.uniform(0.2, 1.0), rate));
  return concatenatePaths(parts, rate);
}

// Faces z = 0 for x < 0 and z = x tan(angle) for x > 0 (angle > 0: concave, < 0: convex), each
// `half` wide; or, when `crossing`, both planes over the whole square (they cut along x = 0).
TriangleSoup crease(double half, double angle, bool crossing)
{
  const double rise = half * std::tan(angle);
  const double back = crossing ? -rise : 0.0;
  TriangleSoup left = scenes::makeQuad({-half, -half, 0}, {crossing ? half : 0.0, -half, 0},
                                       {crossing ? half : 0.0, half, 0}, {-half, half, 0});
  TriangleSoup right = scenes::makeQuad({crossing ? -half : 0.0, -half, back}, {half, -half, rise},
                                        {half, half, rise}, {crossing ? -half : 0.0, half, back});
  return scenes::merge({left, right});
}

TEST(StressPlanes, NearParallelCreasesDownTo1e12Radians)
{
  runCases(4000, 16, [&](Random& random, StressCase& c) {
    c.proxy.radius = 0.001;
    const double half = 0.02;
    const bool crossing = random.uniform() < 0.3;
    // Crossing planes (two sheets cutting along x = 0) and creases (two faces meeting in an edge)
    // both go down to 1e-12 rad. Crossing planes stopped at 1e-6 rad until the same-plane merge
    // compared two face contacts by their cross product and the touching sweep let
    // rounding-level slides through (seed 4009, 8.2e-11 rad; kept as
    // ProxySolverFound.SheetsCrossingAtATinyAngleAreTwoPlanes).
    const double magnitude = random.logUniform(1e-12, 1e-2);
    const double angle = random.uniform() < 0.5 ? magnitude : -magnitude;
    char label[96];
    std::snprintf(label, sizeof label, "%s/angle-%.1e-rad", crossing ? "crossing-planes" : "crease",
                  angle);
    c.name = label;
    const Rotation rotation = Rotation::random(random);
    c.soup = transform(crease(half, angle, crossing), rotation);
    c.path = transform(acrossTheCrease(random, half, c.proxy.radius, c.rate), rotation);
  });
}

TEST(StressPlanes, ApexesAndFunnelsOfFourToSixteenFaces)
{
  runCases(5000, 16, [&](Random& random, StressCase& c) {
    c.proxy.radius = 0.001;
    const int sides = random.integer(4, 16);
    const double base = 0.02;
    // A funnel (pit, height > 0) or an apex; slopes from nearly flat to steep.
    const double height =
      (random.uniform() < 0.5 ? 1.0 : -1.0) * base * random.logUniform(0.01, 3.0);
    c.name = (height > 0 ? "funnel-" : "apex-") + std::to_string(sides);
    std::vector<FingerPath> parts;
    // Jabs at the apex from random directions above, then a circle just under it.
    Jabs jabs;
    jabs.target = {0, 0, 0};
    for (int j = 0; j < 4; ++j)
    {
      Vec3 d = random.direction();
      d.z = std::fabs(d.z) + 0.2;
      jabs.fromDirections.push_back(d);
    }
    jabs.standoff = 0.02;
    jabs.overshoot = random.uniform(0.001, 0.01);
    jabs.speed = random.logUniform(0.05, 10.0);
    parts.push_back(makeJabPath(jabs, c.rate));
    const double below = random.uniform(0.5, 5.0) * c.proxy.radius;
    parts.push_back(makeSlidePath({0, 0, 0.02}, {0.002, 0, -below}, 0.2, c.rate));
    parts.push_back(makeCirclePath({0, 0, -below}, {0, 0, 1}, {1, 0, 0}, 0.002, 2.0, 1.0, c.rate));
    const Rotation rotation = Rotation::random(random);
    c.soup = transform(scenes::makePyramid(sides, base, height), rotation);
    c.path = transform(concatenatePaths(parts, c.rate), rotation);
  });
}

// A trihedral cone: free space {x : n_i . x >= 0}, walls the three faces between its edge rays,
// `length` long. The normals are random, kept when the cone is neither too thin nor too flat.
TriangleSoup concaveCorner(Random& random, double length, Vec3 normals[3])
{
  for (;;)
  {
    for (int i = 0; i < 3; ++i)
    {
      normals[i] = random.direction();
    }
    if (dot(normals[0], cross(normals[1], normals[2])) < 0.0)
    {
      std::swap(normals[1], normals[2]);
    }
    // Edge rays: e_k lies on walls i and j (the two other than k) and inside wall k.
    Vec3 rays[3];
    bool good = true;
    for (int kk = 0; kk < 3; ++kk)
    {
      const Vec3 e = cross(normals[(kk + 1) % 3], normals[(kk + 2) % 3]);
      rays[kk] = normalizedOrZero(e);
      good = good && dot(rays[kk], normals[kk]) > 0.15;
    }
    if (!good)
    {
      continue;
    }
    TriangleSoup soup;
    soup.points.push_back({0, 0, 0});
    for (const Vec3& r : rays)
    {
      soup.points.push_back(r * length);
    }
    // Wall i holds the rays other than i; wound so that its normal points into free space.
    for (std::uint32_t i = 0; i < 3; ++i)
    {
      std::uint32_t a = 1 + (i + 1) % 3;
      std::uint32_t b = 1 + (i + 2) % 3;
      const Vec3 n = cross(soup.points[a], soup.points[b]);
      if (dot(n, normals[i]) < 0.0)
      {
        std::swap(a, b);
      }
      soup.triangles.push_back({0, a, b});
    }
    return soup;
  }
}

TEST(StressPlanes, ConcaveCornersEnteredFromASphereOfDirections)
{
  runCases(6000, 16, [&](Random& random, StressCase& c) {
    c.name = "concave-corner";
    c.proxy.radius = 0.001;
    Vec3 normals[3];
    c.soup = concaveCorner(random, 0.05, normals);
    const Vec3 inside = normalizedOrZero(normals[0] + normals[1] + normals[2]);
    // Strikes at the corner from directions on the sphere (those that come from inside the
    // cone; the others would start behind a wall), ending past the apex, then a wander inside.
    Jabs jabs;
    jabs.target = {0, 0, 0};
    while (jabs.fromDirections.size() < 6)
    {
      const Vec3 d = random.direction();
      if (dot(d, normals[0]) > 0.1 && dot(d, normals[1]) > 0.1 && dot(d, normals[2]) > 0.1)
      {
        jabs.fromDirections.push_back(d);
      }
    }
    jabs.standoff = 0.02;
    jabs.overshoot = random.uniform(0.001, 0.01);
    jabs.speed = random.logUniform(0.05, 10.0);
    std::vector<FingerPath> parts{makeJabPath(jabs, c.rate)};
    parts.push_back(
      makeCirclePath(inside * 0.001, inside, cross(inside, normals[0]), 0.004, 2.0, 1.0, c.rate));
    c.path = concatenatePaths(parts, c.rate);
    c.start = inside * 0.02;
  });
}

} // namespace
} // namespace proxima::stress
