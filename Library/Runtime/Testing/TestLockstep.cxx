// Lockstep mode (DESIGN.md section 2): the same step functions in one thread on a virtual clock;
// the same input gives the same trace bit for bit, all but the measured solve time.
#include "Runtime/LockstepRuntime.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

namespace proxima
{
namespace
{
struct LockstepRun
{
  std::vector<HapticState> records;
  Vec3 lastForce;
};

LockstepRun runOnce(const CollisionScene& scene, const FingerPath& path, double rate)
{
  ProxyParameters parameters;
  parameters.radius = 0.002;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front() + Vec3{0, 0, 0.01});
  SimulatedDevice device(path);
  ServoParameters servo;
  servo.stiffness = 800.0;
  servo.maxForce = 8.0;
  LockstepSettings settings;
  settings.rate = rate;
  settings.startTime = path.startTime();
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), rate);
  LockstepRun run;
  runLockstep(settings, *solver, device, servo,
              [&](const HapticState& record) { run.records.push_back(record); });
  run.lastForce = device.lastForce();
  return run;
}

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameBits(const Vec3& a, const Vec3& b)
{
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

class LockstepTest : public testing::Test
{
protected:
  LockstepTest()
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(makeIcosphere(3, 0.04), error)) << error.message;
    scene.addObject(std::move(mesh));
  }
  CollisionScene scene;
};

TEST_F(LockstepTest, SameInputSameTraceBitForBit)
{
  // Contact-heavy paths: pressing, stroking, and 10 m/s jabs.
  for (const char* kind : {"press-stroke", "jab", "circle"})
  {
    Aabb bounds;
    bounds.expand({-0.04, -0.04, -0.04});
    bounds.expand({0.04, 0.04, 0.04});
    const FingerPath path = makeDefaultPath(kind, bounds, 0.002, 1000.0);
    const LockstepRun a = runOnce(scene, path, 1000.0);
    const LockstepRun b = runOnce(scene, path, 1000.0);
    ASSERT_EQ(a.records.size(), b.records.size()) << kind;
    ASSERT_GT(a.records.size(), 50u) << kind;
    std::size_t contacts = 0;
    for (std::size_t i = 0; i < a.records.size(); ++i)
    {
      const HapticState& x = a.records[i];
      const HapticState& y = b.records[i];
      contacts += x.numContacts > 0 ? 1 : 0;
      ASSERT_EQ(x.tick, y.tick) << kind << " tick " << i;
      ASSERT_TRUE(sameBits(x.time, y.time)) << kind << " tick " << i;
      ASSERT_TRUE(sameBits(x.finger, y.finger)) << kind << " tick " << i;
      ASSERT_TRUE(sameBits(x.proxy, y.proxy)) << kind << " tick " << i;
      ASSERT_TRUE(sameBits(x.force, y.force)) << kind << " tick " << i;
      ASSERT_EQ(x.numContacts, y.numContacts) << kind << " tick " << i;
      ASSERT_EQ(x.iterations, y.iterations) << kind << " tick " << i;
      ASSERT_EQ(x.conditions.has(TickCondition::fingerRefused),
                y.conditions.has(TickCondition::fingerRefused))
        << kind << " tick " << i;
      ASSERT_EQ(x.conditions.has(TickCondition::hitIterationCap),
                y.conditions.has(TickCondition::hitIterationCap))
        << kind << " tick " << i;
      ASSERT_EQ(x.conditions.has(TickCondition::contactOverflow),
                y.conditions.has(TickCondition::contactOverflow))
        << kind << " tick " << i;
      ASSERT_EQ(x.conditions.has(TickCondition::forceClamped),
                y.conditions.has(TickCondition::forceClamped))
        << kind << " tick " << i;
      ASSERT_EQ(x.trianglesTested, y.trianglesTested) << kind << " tick " << i;
    }
    // The runs touched the sphere: determinism was tested where it matters.
    EXPECT_GT(contacts, 10u) << kind;
    EXPECT_TRUE(sameBits(a.lastForce, b.lastForce)) << kind;
  }
}

TEST_F(LockstepTest, VirtualClockAndTickOrder)
{
  const FingerPath path = makeSlidePath({-0.1, 0, 0.1}, {0.1, 0, 0.1}, 0.5, 1000.0);
  for (const double rate : {1000.0, 4000.0})
  {
    LockstepSettings settings;
    settings.rate = rate;
    settings.startTime = 12.5;
    settings.numTicks = 777;
    auto solver = std::make_unique<ProxySolver>();
    ProxyParameters parameters;
    solver->setScene(&scene, parameters);
    solver->resetProxy({-0.1, 0, 0.1});
    SimulatedDevice device(path);
    std::vector<HapticState> records;
    runLockstep(settings, *solver, device, ServoParameters{},
                [&](const HapticState& r) { records.push_back(r); });
    ASSERT_EQ(records.size(), 777u);
    for (std::size_t k = 0; k < records.size(); ++k)
    {
      EXPECT_EQ(records[k].tick, k);
      // From the tick count, not accumulated: no drift.
      EXPECT_EQ(records[k].time, 12.5 + static_cast<double>(k) / rate);
    }
  }
}

TEST_F(LockstepTest, ZeroTicksCallsNothing)
{
  LockstepSettings settings;
  settings.numTicks = 0;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, ProxyParameters{});
  SimulatedDevice device(makeSlidePath({0, 0, 1}, {0, 0, 2}, 1.0, 1000.0));
  int calls = 0;
  runLockstep(settings, *solver, device, ServoParameters{}, [&](const HapticState&) { ++calls; });
  EXPECT_EQ(calls, 0);
}

} // namespace
} // namespace proxima
