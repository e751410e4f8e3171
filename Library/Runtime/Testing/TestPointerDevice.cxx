// The mouse's finger without a window: PointerDevice's speed limit against the distance a finger
// at top speed covers (closed form), and PointerAimPlane's ray-plane geometry and anchoring rules
// against hand-computed points.
#include "Runtime/PointerAimPlane.h"
#include "Runtime/PointerDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

namespace
{
using namespace proxima;

void expectNear(const Vec3& actual, const Vec3& expected, double tolerance)
{
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(PointerDevice, StaysAtItsStartUntilAimed)
{
  PointerDeviceSettings settings;
  settings.start = {0.1, -0.2, 0.3};
  PointerDevice device(settings);
  EXPECT_EQ(device.read(0.0).position, settings.start);
  EXPECT_EQ(device.read(1.0).position, settings.start);
  EXPECT_STREQ(device.name(), "mouse");
}

TEST(PointerDevice, MovesTowardItsAimNoFasterThanItsTopSpeed)
{
  PointerDeviceSettings settings;
  settings.maxSpeed = 0.5;
  PointerDevice device(settings);
  EXPECT_EQ(device.read(0.0).position, Vec3{});
  // 10 cm away along a diagonal: 0.2 s at 0.5 m/s; after 0.05 s, 2.5 cm along it.
  const Vec3 aim = Vec3{1.0, 2.0, 2.0} * (0.1 / 3.0);
  device.aimAt(aim, 5u);
  const DeviceSample sample = device.read(0.05);
  expectNear(sample.position, aim * 0.25, 1e-15);
  EXPECT_EQ(sample.buttons, 5u);
  expectNear(device.read(0.1).position, aim * 0.5, 1e-15);
  // Arrives at 0.2 s and stays, exactly at the aim.
  EXPECT_EQ(device.read(0.2000001).position, aim);
  EXPECT_EQ(device.read(5.0).position, aim);
}

TEST(PointerDevice, AClockThatGoesBackMovesNothing)
{
  PointerDevice device(PointerDeviceSettings{});
  device.read(1.0);
  device.aimAt({1.0, 0.0, 0.0});
  EXPECT_EQ(device.read(0.5).position, Vec3{});
  expectNear(device.read(0.6).position, {0.05, 0.0, 0.0}, 1e-15);
}

TEST(PointerDevice, RefusesAnAimThatIsNotFinite)
{
  PointerDevice device(PointerDeviceSettings{});
  device.aimAt({0.01, 0.0, 0.0});
  device.aimAt({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0});
  device.aimAt({std::numeric_limits<double>::infinity(), 0.0, 0.0});
  EXPECT_EQ(device.aim(), (Vec3{0.01, 0.0, 0.0}));
  device.read(0.0);
  EXPECT_EQ(device.read(1.0).position, (Vec3{0.01, 0.0, 0.0}));
}

TEST(PointerDevice, KeepsTheLastForceForDisplay)
{
  PointerDevice device(PointerDeviceSettings{});
  device.writeForce({0.0, 0.0, 2.5}, 0.1);
  EXPECT_EQ(device.lastForce(), (Vec3{0.0, 0.0, 2.5}));
}

TEST(PointerDevice, AnAimFromAnotherThreadArrivesWhole)
{
  // The window's thread aims at points whose three coordinates are equal; the servo's reads must
  // never see a mix of two aims (the finger moves along the diagonal only).
  PointerDeviceSettings settings;
  settings.maxSpeed = 1e9;
  PointerDevice device(settings);
  std::thread aimer([&device] {
    for (int i = 1; i <= 20000; ++i)
    {
      const double v = i * 1e-4;
      device.aimAt({v, v, v});
    }
  });
  double time = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    time += 1e-3;
    const Vec3 p = device.read(time).position;
    ASSERT_EQ(p.x, p.y);
    ASSERT_EQ(p.y, p.z);
  }
  aimer.join();
  device.read(time + 1.0);
  EXPECT_EQ(device.read(time + 2.0).position, (Vec3{2.0, 2.0, 2.0}));
}

// A camera at z = 1 looking down -z; rays from the eye.
const Vec3 kEye{0.0, 0.0, 1.0};
const Vec3 kView{0.0, 0.0, -1.0};

TEST(PointerAimPlane, PutsTheFingerUnderTheCursorOnThePlaneThroughTheProxy)
{
  PointerAimPlane plane;
  // The proxy at z = 0.2, free; the ray toward (0.1, 0.05, 0) meets z = 0.2 at 0.8 of the way.
  const Vec3 aim = plane.aim(kEye, Vec3{0.1, 0.05, -1.0}, kView, {0.3, 0.3, 0.2}, false);
  expectNear(aim, {0.08, 0.04, 0.2}, 1e-15);
}

TEST(PointerAimPlane, APressGoesBehindThePlaneAlongTheView)
{
  PointerAimPlane plane;
  plane.setDepth(0.003);
  const Vec3 aim = plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.0, 0.0, 0.2}, true);
  expectNear(aim, {0.0, 0.0, 0.197}, 1e-15);
  plane.setDepth(-1.0);
  EXPECT_EQ(plane.depth(), 0.0);
  plane.setDepth(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(plane.depth(), 0.0);
}

TEST(PointerAimPlane, HoversOverTheSurfaceUnderTheCursorWhenFreeAndNotPressed)
{
  PointerAimPlane plane;
  const Vec3 hover{0.0, 0.0, 0.05};
  const Vec3 aim = plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.5, 0.5, 0.5}, false, &hover);
  expectNear(aim, hover, 1e-15);
  EXPECT_EQ(plane.anchor(), hover);
}

TEST(PointerAimPlane, PressedIntoFreeSpaceThePlaneStaysPut)
{
  // Pressed in while free, the plane keeps its last anchor: a plane through the free proxy (where
  // the finger is) would run away by the depth at every aim.
  PointerAimPlane plane;
  plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.0, 0.0, 0.2}, false);
  plane.setDepth(0.01);
  Vec3 proxy{0.0, 0.0, 0.2};
  for (int i = 0; i < 5; ++i)
  {
    const Vec3 aim = plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, proxy, false);
    expectNear(aim, {0.0, 0.0, 0.19}, 1e-15);
    proxy = aim;
  }
  // Touching, the plane goes through the proxy again.
  const Vec3 aim = plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.0, 0.0, 0.195}, true);
  expectNear(aim, {0.0, 0.0, 0.185}, 1e-15);
}

TEST(PointerAimPlane, PressedAndSlidOffIntoFreeSpaceAPressGoesBackIntoTheSurfaceUnderTheCursor)
{
  // A pressed finger whose proxy slid off an edge is free with its plane in mid-air; once the
  // cursor's ray meets a surface again, the press goes `depth` behind that hover point.
  PointerAimPlane plane;
  plane.setDepth(0.01);
  plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.0, 0.0, 0.3}, false);
  const Vec3 hover{0.0, 0.0, 0.05};
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 aim = plane.aim(kEye, Vec3{0.0, 0.0, -1.0}, kView, {0.0, 0.0, 0.3}, false, &hover);
    expectNear(aim, {0.0, 0.0, 0.04}, 1e-15);
    EXPECT_EQ(plane.anchor(), hover);
  }
}

TEST(PointerAimPlane, ARayAlongThePlaneAimsAtItsPoint)
{
  PointerAimPlane plane;
  const Vec3 aim = plane.aim(kEye, Vec3{1.0, 0.0, 0.0}, kView, {0.1, 0.2, 0.3}, false);
  expectNear(aim, {0.1, 0.2, 0.3}, 0.0);
}

} // namespace
