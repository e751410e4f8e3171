// Replayed work (TickReplay.h): a replay runs the tick itself, bit for bit, from a copy of the
// solver; and a budget-limited tick replayed without its budget ends where an unbudgeted solver
// in the same state ends, nearer the finger than the limited tick.
#include "Runtime/TickReplay.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace proxima
{
namespace
{
bool sameBits(const Vec3& a, const Vec3& b)
{
  return std::memcmp(&a.x, &b.x, sizeof(double)) == 0 &&
         std::memcmp(&a.y, &b.y, sizeof(double)) == 0 &&
         std::memcmp(&a.z, &b.z, sizeof(double)) == 0;
}

class TickReplayTest : public testing::Test
{
protected:
  TickReplayTest()
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(makeIcosphere(4, 0.04), error)) << error.message;
    scene.addObject(std::move(mesh));
    const CollisionObject& object = scene.objects.front();
    ProbeOptions options;
    options.seed = 3;
    options.duration = 3.0;
    path = makeProbePath({ProbeSurface{&object.mesh, &object.tree}}, options);
  }
  CollisionScene scene;
  FingerPath path;
};

TEST_F(TickReplayTest, ReplayRunsTheTickItself)
{
  ProxyParameters parameters;
  parameters.radius = 0.003;
  // Heap: a solver is about a hundred kilobytes of fixed buffers.
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front());
  auto replay = std::make_unique<TickReplay>(3);
  std::size_t contactTicks = 0;
  std::size_t iterations = 0;
  for (const Vec3& finger : path.positions)
  {
    replay->remember(*solver);
    const ProxyTickResult tick = solver->update(finger);
    ASSERT_TRUE(replay->replayable());
    const std::int64_t work = replay->workNanoseconds(finger);
    EXPECT_GE(work, 0);
    const ProxyTickResult& again = replay->lastReplay();
    ASSERT_TRUE(sameBits(tick.proxy, again.proxy));
    ASSERT_EQ(tick.iterations, again.iterations);
    ASSERT_EQ(tick.numContacts, again.numContacts);
    ASSERT_EQ(tick.queries.trianglesTested, again.queries.trianglesTested);
    contactTicks += tick.numContacts > 0 ? 1 : 0;
    iterations += static_cast<std::size_t>(tick.iterations);
  }
  // The path pressed into the sphere: the replays were checked where there is work.
  EXPECT_GT(contactTicks, 300u);
  EXPECT_GT(iterations, 1000u);
}

TEST_F(TickReplayTest, LimitedTickReplayedWithoutBudgetSettlesAsAnUnbudgetedSolver)
{
  ProxyParameters parameters;
  parameters.radius = 0.003;
  auto unbudgeted = std::make_unique<ProxySolver>();
  unbudgeted->setScene(&scene, parameters);
  parameters.tickBudgetIterations = 1;
  auto budgeted = std::make_unique<ProxySolver>();
  budgeted->setScene(&scene, parameters);
  auto replay = std::make_unique<TickReplay>(1);
  std::size_t limitedTicks = 0;
  for (const Vec3& finger : path.positions)
  {
    // The oracle: a fresh unbudgeted solver in the budgeted one's state (the same start, the same
    // caches), made without TickReplay.
    *unbudgeted = *budgeted;
    unbudgeted->setTickBudget(0, 0.0);
    replay->remember(*budgeted);
    const ProxyTickResult limited = budgeted->update(finger);
    if (!limited.conditions.has(TickCondition::budgetLimited))
    {
      continue;
    }
    ++limitedTicks;
    const ProxyTickResult settled = replay->settledWithoutBudget(finger);
    const ProxyTickResult expected = unbudgeted->update(finger);
    ASSERT_TRUE(sameBits(settled.proxy, expected.proxy));
    EXPECT_FALSE(settled.conditions.has(TickCondition::budgetLimited));
    EXPECT_GT(settled.iterations, limited.iterations);
    // The loop only brings the proxy nearer the finger: the settled end is at least as near.
    EXPECT_LE(distance(settled.proxy, finger), distance(limited.proxy, finger) + 1e-12);
  }
  EXPECT_GT(limitedTicks, 20u);
}

} // namespace
} // namespace proxima
