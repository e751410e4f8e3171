// The dynamics step of a haptic tick (Library/Dynamics): the touched body's force applied at the
// contact point (J^T f), one MuJoCo step at 1 kHz, and the new pose read back, for the mechanisms
// of the paper's section 6 (a hinge, a slider, a free body; one and four bodies). Issue 15's target
// is a median of at most 5 us per tick on one core.
#include "Dynamics/BodyWorld.h"
#include "Geometry/ProceduralMeshes.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace
{
using namespace proxima;

BodyDescription bar(JointType type, double offset)
{
  TriangleMesh mesh;
  MeshError error;
  mesh.build(makeBox({0.1, 0.01, 0.01}, {0.1, offset, 0.0}), error);
  BodyDescription body;
  body.name = "bar";
  body.joint.type = type;
  body.joint.anchor = {0.0, offset, 0.0};
  body.joint.stiffness = type == JointType::Free || type == JointType::Ball ? 0.0 : 2.0;
  body.joint.damping = type == JointType::Free ? 0.0 : 0.05;
  body.mass = solidMassProperties(mesh, 1000.0);
  return body;
}

void tick(benchmark::State& state, const std::vector<BodyDescription>& bodies)
{
  DynamicsSettings settings;
  settings.timeStep = 1e-3;
  BodyWorld world(bodies, settings);
  const Vec3 tip{0.2, 0.0, 0.0};
  for (auto _ : state)
  {
    const BodyPose before = world.pose(0);
    world.applyForce(0, before.apply(tip), {0.0, 0.01, 0.0});
    world.step();
    BodyPose after = world.pose(0);
    benchmark::DoNotOptimize(after);
  }
}

void BM_BodyStepHinge(benchmark::State& state)
{
  tick(state, {bar(JointType::Hinge, 0.0)});
}
void BM_BodyStepSlide(benchmark::State& state)
{
  tick(state, {bar(JointType::Slide, 0.0)});
}
void BM_BodyStepFree(benchmark::State& state)
{
  tick(state, {bar(JointType::Free, 0.0)});
}
void BM_BodyStepFourBodies(benchmark::State& state)
{
  tick(state, {bar(JointType::Hinge, 0.0), bar(JointType::Hinge, 0.1), bar(JointType::Slide, 0.2),
               bar(JointType::Ball, 0.3)});
}
BENCHMARK(BM_BodyStepHinge);
BENCHMARK(BM_BodyStepSlide);
BENCHMARK(BM_BodyStepFree);
BENCHMARK(BM_BodyStepFourBodies);
} // namespace

BENCHMARK_MAIN();
