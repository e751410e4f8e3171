// What the device tests run through the solver: a flat grid at z = 0, a finger path that presses
// 3 mm into it and strokes sideways, and a device wrapper that moves an emulator to the path's
// position before each read (the hand on the real device).
#pragma once

#include "Geometry/ProceduralMeshes.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/LockstepRuntime.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <vector>

namespace proxima::testing
{

constexpr double kTestRate = 1000.0;
constexpr double kTestRadius = 0.001;
constexpr double kTestStiffness = 500.0;

/// A press and stroke: from 8 mm above the grid down to 3 mm below its surface, 10 mm sideways,
/// and back up, over 0.3 s.
inline FingerPath pressStrokePath()
{
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.008});
  path.append(0.1, {0.0, 0.0, -0.003});
  path.append(0.2, {0.01, 0.0, -0.003});
  path.append(0.3, {0.01, 0.0, 0.008});
  return path;
}

class GridScene
{
public:
  GridScene()
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(makeGrid(0.2, 4, 0.0), error)) << error.message;
    m_scene.addObject(std::move(mesh));
  }

  /// Runs the press-stroke ticks through `device` in lockstep and returns the records.
  std::vector<HapticState> run(HapticDevice& device, const FingerPath& path)
  {
    ProxyParameters parameters;
    parameters.radius = kTestRadius;
    parameters.stiffness = kTestStiffness;
    parameters.timeStep = 1.0 / kTestRate;
    ProxySolver solver;
    solver.setScene(&m_scene, parameters);
    solver.resetProxy(path.positions.front());
    LockstepSettings settings;
    settings.rate = kTestRate;
    settings.startTime = path.startTime();
    settings.numTicks = ticksCovering(path.startTime(), path.endTime(), kTestRate);
    ServoParameters servo;
    servo.stiffness = kTestStiffness;
    servo.maxForce = 5.0;
    std::vector<HapticState> records;
    runLockstep(settings, solver, device, servo,
                [&](const HapticState& record) { records.push_back(record); });
    return records;
  }

private:
  CollisionScene m_scene;
};

/// Calls `before(time)` (moving the emulated hand) and then reads the wrapped device.
class DrivenDevice final : public HapticDevice
{
public:
  DrivenDevice(HapticDevice& device, std::function<void(double)> before)
    : m_device(device)
    , m_before(std::move(before))
  {}
  DeviceSample read(double time) override
  {
    m_before(time);
    return m_device.read(time);
  }
  void writeForce(const Vec3& force, double time) override { m_device.writeForce(force, time); }
  DeviceLimits limits() const override { return m_device.limits(); }

private:
  HapticDevice& m_device;
  std::function<void(double)> m_before;
};

inline std::size_t contactTicks(const std::vector<HapticState>& records)
{
  std::size_t count = 0;
  for (const HapticState& record : records)
  {
    count += record.numContacts > 0 ? 1 : 0;
  }
  return count;
}

/// The tick at which the unplug tests pull the device: mid-stroke, in contact.
constexpr std::size_t kUnplugTick = 150;

/// After the device is lost at `lostTick`: every tick reports it, the force fades from what it
/// was to zero over the servo's fade time without ever growing, and nothing is NaN.
/// A SpaceMouse run against the same path through the simulated device: the same ticks, with
/// the finger within half a count (1e-5 m scale) on each axis and the force within kp times that.
inline void expectFollowsReference(const std::vector<HapticState>& trace,
                                   const std::vector<HapticState>& reference)
{
  ASSERT_EQ(trace.size(), reference.size());
  EXPECT_GT(contactTicks(trace), 100u);
  for (std::size_t i = 0; i < trace.size(); ++i)
  {
    EXPECT_LT(distance(trace[i].finger, reference[i].finger), 1e-5) << i;
    EXPECT_LT(distance(trace[i].force, reference[i].force), kTestStiffness * 2e-5) << i;
  }
}

inline void expectFadeOut(const std::vector<HapticState>& records, std::size_t lostTick)
{
  ASSERT_GT(records.size(), lostTick + 80);
  ASSERT_GT(records[lostTick - 1].numContacts, 0) << "the unplug should come in contact";
  const double before = norm(records[lostTick - 1].force);
  ASSERT_GT(before, 0.1);
  const double fadeTicks = ServoParameters{}.fadeTime * kTestRate;
  double previous = before;
  for (std::size_t i = lostTick; i < records.size(); ++i)
  {
    const HapticState& record = records[i];
    EXPECT_TRUE(record.conditions.has(TickCondition::deviceLost)) << i;
    EXPECT_TRUE(isFinite(record.force)) << i;
    const double magnitude = norm(record.force);
    EXPECT_LE(magnitude, previous + 1e-12) << i;
    previous = magnitude;
    if (static_cast<double>(i - lostTick) >= fadeTicks + 1)
    {
      EXPECT_EQ(magnitude, 0.0) << i;
    }
    else if (static_cast<double>(i - lostTick) < fadeTicks - 2)
    {
      EXPECT_GT(magnitude, 0.0) << "faded too soon, tick " << i;
    }
  }
  for (std::size_t i = 0; i < lostTick; ++i)
  {
    EXPECT_FALSE(records[i].conditions.has(TickCondition::deviceLost)) << i;
  }
}

} // namespace proxima::testing
