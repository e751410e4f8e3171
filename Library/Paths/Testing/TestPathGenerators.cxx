// Path generators, as their header documents them: end points, durations, speeds, shapes.
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace proxima
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kRate = 1000.0;

void expectIncreasingTimes(const FingerPath& path, double rate)
{
  ASSERT_EQ(path.times.size(), path.positions.size());
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    ASSERT_GT(path.times[i], path.times[i - 1]) << "row " << i;
    // Rows at least as dense as the servo ticks (a little rounding allowed).
    ASSERT_LE(path.times[i] - path.times[i - 1], 1.0 / rate * (1 + 1e-9)) << "row " << i;
  }
}

/// Rows reached faster than `limit` from the previous row.
std::size_t rowsFasterThan(const FingerPath& path, double limit)
{
  std::size_t count = 0;
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    count +=
      distance(path.positions[i], path.positions[i - 1]) / (path.times[i] - path.times[i - 1]) >
          limit
        ? 1
        : 0;
  }
  return count;
}

/// Largest speed between consecutive rows.
double maxSpeed(const FingerPath& path)
{
  double fastest = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    fastest = std::max(fastest, distance(path.positions[i], path.positions[i - 1]) /
                                  (path.times[i] - path.times[i - 1]));
  }
  return fastest;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance)
{
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(PathGenerators, SlideIsStraightAtConstantSpeed)
{
  const Vec3 from{0.1, -0.2, 0.3};
  const Vec3 to{-0.3, 0.1, 0.3};
  const FingerPath path = makeSlidePath(from, to, 1.25, kRate);
  expectIncreasingTimes(path, kRate);
  EXPECT_EQ(path.size(), 1251u);
  EXPECT_EQ(path.positions.front(), from);
  EXPECT_EQ(path.times.front(), 0.0);
  expectNear(path.positions.back(), to, 1e-15);
  EXPECT_DOUBLE_EQ(path.endTime(), 1.25);
  const double speed = distance(from, to) / 1.25;
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    const double v =
      distance(path.positions[i], path.positions[i - 1]) / (path.times[i] - path.times[i - 1]);
    ASSERT_NEAR(v, speed, 1e-9 * speed) << i;
  }
}

TEST(PathGenerators, PressAndStrokeShape)
{
  PressAndStroke p;
  p.surfacePoint = {0.01, 0.02, 0.03};
  p.inward = {0, 0, -2}; // normalised by the generator
  p.approachHeight = 0.01;
  p.depth = 0.004;
  p.strokeDirection = {1, 0, 0.5}; // made tangent: the z part goes
  p.strokeLength = 0.03;
  p.speed = 0.1;
  const FingerPath path = makePressAndStrokePath(p, kRate);
  expectIncreasingTimes(path, kRate);
  // Starts above, presses `depth` past the surface point, strokes along +x, lifts back above.
  EXPECT_EQ(path.positions.front(), (Vec3{0.01, 0.02, 0.04}));
  double deepest = 1.0;
  for (const Vec3& q : path.positions)
  {
    deepest = std::min(deepest, q.z);
  }
  EXPECT_NEAR(deepest, 0.026, 1e-15);
  expectNear(path.positions.back(), {0.04, 0.02, 0.04}, 1e-15);
  // The stroke is tangent: at the pressed depth all the way along x.
  std::size_t pressedRows = 0;
  for (const Vec3& q : path.positions)
  {
    if (std::fabs(q.z - 0.026) < 1e-15)
    {
      ++pressedRows;
      EXPECT_NEAR(q.y, 0.02, 1e-15);
    }
  }
  EXPECT_GE(pressedRows, 300u); // 30 mm at 0.1 m/s
  // Speed: p.speed along every segment.
  EXPECT_NEAR(maxSpeed(path), 0.1, 1e-9);
  const double length = 0.014 + 0.03 + 0.014;
  // Each segment after the first starts one servo period after the previous one ends.
  EXPECT_NEAR(path.endTime(), length / 0.1 + 2.0 / kRate, 1e-12);
}

TEST(PathGenerators, CircleIsACircleCounterClockwiseAboutTheAxis)
{
  const Vec3 center{0.1, 0.2, 0.3};
  const Vec3 axis{0, 0, 3};
  const FingerPath path = makeCirclePath(center, axis, {1, 0, 0.7}, 0.05, 2.0, 4.0, kRate);
  expectIncreasingTimes(path, kRate);
  EXPECT_DOUBLE_EQ(path.endTime(), 4.0);
  expectNear(path.positions.front(), center + Vec3{0.05, 0, 0}, 1e-15);
  expectNear(path.positions.back(), center + Vec3{0.05, 0, 0}, 1e-15); // two whole turns
  double turned = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i)
  {
    const Vec3 r = path.positions[i] - center;
    ASSERT_NEAR(norm(r), 0.05, 1e-15) << i;
    ASSERT_NEAR(r.z, 0.0, 1e-15) << i;
    if (i > 0)
    {
      const Vec3 previous = path.positions[i - 1] - center;
      const double step = std::atan2(cross(previous, r).z, dot(previous, r));
      ASSERT_GT(step, 0.0) << i; // counter-clockwise seen from the axis' tip
      turned += step;
    }
  }
  EXPECT_NEAR(turned, 2.0 * 2.0 * kPi, 1e-9);
  EXPECT_NEAR(maxSpeed(path), 2.0 * 2.0 * kPi * 0.05 / 4.0, 1e-6);
}

TEST(PathGenerators, JabsStrikeAtTheirSpeedFromEachDirection)
{
  Jabs jabs;
  jabs.target = {0.0, 0.0, 0.05};
  jabs.fromDirections = {{0, 0, 1}, {1, 0, 1}, {0, -2, 1}};
  jabs.standoff = 0.02;
  jabs.overshoot = 0.005;
  jabs.speed = 10.0;
  jabs.pause = 0.01;
  const FingerPath path = makeJabPath(jabs, kRate);
  expectIncreasingTimes(path, kRate);
  // Strikes at 10 m/s (10 mm per tick). The finger moves from one jab's standoff point to the
  // next in a single tick (undocumented; 23 m/s here, 73 m/s for makeDefaultPath on a 1 m
  // object): those repositioning steps are the only rows faster than the strike.
  EXPECT_EQ(rowsFasterThan(path, 10.0 * (1 + 1e-9)), jabs.fromDirections.size() - 1);
  std::cout << "[paths] jab repositioning speed " << maxSpeed(path) << " m/s\n";
  // Each jab reaches target - d * overshoot and starts at target + d * standoff.
  for (const Vec3& from : jabs.fromDirections)
  {
    const Vec3 d = normalizedOrZero(from);
    const Vec3 deep = jabs.target - d * jabs.overshoot;
    const Vec3 start = jabs.target + d * jabs.standoff;
    double nearestDeep = 1.0;
    double nearestStart = 1.0;
    for (const Vec3& q : path.positions)
    {
      nearestDeep = std::min(nearestDeep, distance(q, deep));
      nearestStart = std::min(nearestStart, distance(q, start));
    }
    EXPECT_LT(nearestDeep, 1e-15);
    EXPECT_LT(nearestStart, 1e-15);
  }
  expectNear(path.positions.front(), jabs.target + Vec3{0, 0, 0.02}, 1e-15);
}

TEST(PathGenerators, ConcatenateShiftsTimes)
{
  const FingerPath a = makeSlidePath({0, 0, 0}, {1, 0, 0}, 0.5, kRate);
  const FingerPath b = makeSlidePath({1, 0, 0}, {1, 1, 0}, 0.25, kRate);
  const FingerPath joined = concatenatePaths({a, FingerPath{}, b}, kRate);
  expectIncreasingTimes(joined, kRate);
  EXPECT_EQ(joined.size(), a.size() + b.size());
  EXPECT_DOUBLE_EQ(joined.times[a.size()], 0.5 + 1.0 / kRate);
  EXPECT_DOUBLE_EQ(joined.endTime(), 0.75 + 1.0 / kRate);
}

class DefaultPaths : public testing::TestWithParam<double>
{
protected:
  Aabb bounds() const
  {
    // A box `size` across, 60% as deep and 40% as tall, off the origin.
    const double s = GetParam();
    Aabb box;
    box.expand({0.3, -0.1, 0.2});
    box.expand(Vec3{0.3, -0.1, 0.2} + Vec3{s, 0.6 * s, 0.4 * s});
    return box;
  }
};

TEST_P(DefaultPaths, EveryKindIsSensibleForTheBox)
{
  const Aabb box = bounds();
  const double radius = 0.001;
  const Vec3 c = box.center();
  const Vec3 e = box.extent();
  const double size = std::max({e.x, e.y, e.z, radius});
  const double clearance = 2.0 * radius + 0.05 * size;
  ASSERT_EQ(defaultPathKinds(),
            (std::vector<std::string>{"slide", "press-stroke", "circle", "jab", "wander"}));
  for (const std::string& kind : defaultPathKinds())
  {
    const FingerPath path = makeDefaultPath(kind, box, radius, kRate);
    SCOPED_TRACE(kind + " at size " + std::to_string(size));
    expectIncreasingTimes(path, kRate);
    ASSERT_GT(path.size(), 10u);
    for (const Vec3& q : path.positions)
    {
      ASSERT_TRUE(isFinite(q));
    }
    // Starts outside the object (above it or beside it).
    const Vec3 start = path.positions.front();
    const bool outside = start.z > box.upper.z || start.x < box.lower.x || start.x > box.upper.x;
    EXPECT_TRUE(outside) << "starts at " << start.x << " " << start.y << " " << start.z;
  }
  // press-stroke: presses into the top by min(0.25 ez, 0.1 size) + radius, strokes across the
  // middle of the top along the longer horizontal axis, at max(0.02, 0.5 size) m/s.
  const FingerPath press = makeDefaultPath("press-stroke", box, radius, kRate);
  double deepest = 1e9;
  bool crossedMiddle = false;
  for (const Vec3& q : press.positions)
  {
    deepest = std::min(deepest, q.z);
    crossedMiddle = crossedMiddle || (std::fabs(q.x - c.x) < 0.01 * size && q.z < box.upper.z);
  }
  EXPECT_NEAR(deepest, box.upper.z - (std::min(0.25 * e.z, 0.1 * size) + radius), 1e-12);
  EXPECT_TRUE(crossedMiddle);
  EXPECT_NEAR(maxSpeed(press), std::max(0.02, 0.5 * size), 1e-9);
  EXPECT_NEAR(press.positions.front().z, box.upper.z + clearance, 1e-12);
  // slide: skims the top at half a radius above it, 1.2 x the extent, over two seconds.
  const FingerPath slide = makeDefaultPath("slide", box, radius, kRate);
  EXPECT_NEAR(slide.endTime(), 2.0, 1e-12);
  for (const Vec3& q : slide.positions)
  {
    ASSERT_NEAR(q.z, box.upper.z + 0.5 * radius, 1e-12);
  }
  EXPECT_NEAR(distance(slide.positions.front(), slide.positions.back()), 1.2 * e.x, 1e-12);
  // circle: descends for a second, then two turns at mid-height inside the object.
  const FingerPath circle = makeDefaultPath("circle", box, radius, kRate);
  const double ring = 0.45 * std::min(e.x, e.y);
  EXPECT_NEAR(circle.endTime(), 5.0 + 1.0 / kRate, 1e-12);
  std::size_t onRing = 0;
  for (const Vec3& q : circle.positions)
  {
    if (std::fabs(q.z - c.z) < 1e-12)
    {
      ++onRing;
      ASSERT_NEAR(std::hypot(q.x - c.x, q.y - c.y), ring, 1e-12);
    }
  }
  EXPECT_GE(onRing, 4000u);
  // jab: the top centre at 10 m/s from five directions, overshooting like press-stroke's depth.
  const FingerPath jab = makeDefaultPath("jab", box, radius, kRate);
  EXPECT_LE(rowsFasterThan(jab, 10.0 * (1 + 1e-9)), 4u); // at most the four repositionings
  double jabDeepest = 1e9;
  for (const Vec3& q : jab.positions)
  {
    jabDeepest = std::min(jabDeepest, q.z);
  }
  EXPECT_NEAR(jabDeepest, box.upper.z - (std::min(0.25 * e.z, 0.1 * size) + radius), 1e-12);
  // wander: straight through the object in three seconds, starting and ending beside it.
  const FingerPath wander = makeDefaultPath("wander", box, radius, kRate);
  EXPECT_NEAR(wander.endTime(), 3.0, 1e-12);
  EXPECT_LT(wander.positions.front().x, box.lower.x);
  EXPECT_GT(wander.positions.back().x, box.upper.x);
  expectNear((wander.positions.front() + wander.positions.back()) * 0.5, c, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Sizes, DefaultPaths, testing::Values(0.01, 0.05, 0.25, 1.0));

TEST(PathGenerators, UnknownKindThrows)
{
  Aabb box;
  box.expand({0, 0, 0});
  box.expand({1, 1, 1});
  EXPECT_THROW(makeDefaultPath("spiral", box, 0.001, kRate), std::invalid_argument);
}

} // namespace
} // namespace proxima
