// The scorer's rules on hand-made haptic states over a flat floor (z = 0) with a nodule region
// under it, where every expected figure is worked out by hand: a palpation mark's distance from
// the spot above the nodule, targets touched in order with the force in the band for the hold
// time, a trace's coverage and straying, and damage events as runs of ticks over a tissue's limit.
#include "Exercises/ExerciseScorer.h"

#include "Geometry/ProceduralMeshes.h"
#include "IO/InputChecks/InputError.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using namespace proxima;
using namespace proxima::trainer;

CollisionScene floorWithNodule()
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(makeGrid(0.2, 16, 0.0), error));
  SurfaceMaterial material;
  material.stiffnessRegions.push_back({{0.03, -0.02, -0.006}, 0.012, 4.0});
  CollisionScene scene;
  scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
  return scene;
}

// A state at `time` with the finger at `finger`; touching object 0 at `contact` with `force`
// (straight up) when `touching`.
HapticState stateAt(double time, const Vec3& finger, bool touching, const Vec3& contact = {},
                    double force = 0.0)
{
  HapticState state;
  state.time = time;
  state.finger = finger;
  if (touching)
  {
    state.numContacts = 1;
    state.contactObject = 0;
    state.contacts[0].point = contact;
    state.contacts[0].normal = {0.0, 0.0, 1.0};
    state.force = {0.0, 0.0, force};
  }
  return state;
}

Exercise exerciseWith(ExerciseTask task)
{
  Exercise exercise;
  exercise.path = "test-exercise.json";
  exercise.tissues.push_back({0, "floor", 5.0});
  exercise.tasks.push_back(std::move(task));
  return exercise;
}

TEST(ExerciseScorer, PalpationScoresTheLastMarkAgainstTheSpotAboveTheNodule)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseTask task;
  task.kind = TaskKind::Palpation;
  task.palpation = {0, 0, 0.01};
  const Exercise exercise = exerciseWith(task);
  ExerciseScorer scorer(exercise, scene);
  // The spot: the floor's point nearest the nodule's centre, straight above it.
  const Vec3 spot{0.03, -0.02, 0.0};
  scorer.mark(); // before any tick: in the air
  scorer.addTick(stateAt(0.0, {0.0, 0.0, 0.01}, false));
  scorer.addTick(stateAt(0.001, {0.0, 0.0, -0.002}, true, {0.0, 0.0, 0.0}, 1.0));
  scorer.mark(); // 3.6 cm from the spot
  ExerciseScore score = scorer.score();
  EXPECT_EQ(score.tasks[0].palpation.marks, 2);
  EXPECT_NEAR(norm(score.tasks[0].palpation.spot - spot), 0.0, 1e-12);
  EXPECT_NEAR(score.tasks[0].palpation.distance, std::sqrt(0.03 * 0.03 + 0.02 * 0.02), 1e-12);
  EXPECT_FALSE(score.tasks[0].passed);
  scorer.addTick(stateAt(0.002, {0.034, -0.017, -0.002}, true, {0.034, -0.017, 0.0}, 2.0));
  scorer.mark(); // 5 mm from the spot: passes
  score = scorer.score();
  EXPECT_NEAR(score.tasks[0].palpation.distance, 0.005, 1e-12);
  EXPECT_TRUE(score.tasks[0].passed);
  EXPECT_TRUE(score.passed);
  EXPECT_EQ(score.peakForce, 2.0);
  EXPECT_NEAR(score.fingerPathLength, 0.012 + std::sqrt(0.034 * 0.034 + 0.017 * 0.017), 1e-12);
}

TEST(ExerciseScorer, APalpationNamingARegionTheSceneHasNotIsRefused)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseTask task;
  task.kind = TaskKind::Palpation;
  task.palpation = {0, 1, 0.01};
  try
  {
    ExerciseScorer scorer(exerciseWith(task), scene);
    FAIL() << "no refusal";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "test-exercise.json: tasks[0].region: the scene's object 0 has 1 stiffness "
                 "region(s) (its material's stiffness_regions), numbered from 0: the inclusion "
                 "to find is one of them");
  }
}

TEST(ExerciseScorer, APalpationMayFindAnInclusionOfTheObjectsTissue)
{
  const CollisionScene scene = floorWithNodule();
  SceneDescription description;
  description.objects.resize(1);
  description.objects[0].hasTissue = true;
  description.objects[0].tissue.inclusions.push_back({{-0.04, 0.05, -0.01}, 0.008, 3e4});
  ExerciseTask task;
  task.kind = TaskKind::Palpation;
  task.palpation = {0, 0, 0.01, true};
  ExerciseScorer scorer(exerciseWith(task), scene, &description);
  // The floor's point nearest the inclusion's centre, straight above it (not the stiffness
  // region's).
  EXPECT_NEAR(norm(scorer.score().tasks[0].palpation.spot - Vec3{-0.04, 0.05, 0.0}), 0.0, 1e-12);
  task.palpation.region = 1;
  try
  {
    ExerciseScorer refused(exerciseWith(task), scene, &description);
    FAIL() << "no refusal";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "test-exercise.json: tasks[0].inclusion: the scene's object 0 has 1 tissue "
                 "inclusion(s) (its tissue's inclusions), numbered from 0: the inclusion to find "
                 "is one of them");
  }
}

TEST(ExerciseScorer, TargetsCountInOrderWithTheForceInTheBandForTheHoldTime)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseTask task;
  task.kind = TaskKind::Targets;
  task.targets.targets = {{"A", {0.0, 0.0, 0.0}, 0.005}, {"B", {0.05, 0.0, 0.0}, 0.005}};
  task.targets.minForce = 0.5;
  task.targets.maxForce = 2.0;
  task.targets.holdSeconds = 0.003;
  ExerciseScorer scorer(exerciseWith(task), scene);
  double t = 0.0;
  const auto press = [&](const Vec3& at, double force, int ticks) {
    for (int i = 0; i < ticks; ++i, t += 0.001)
    {
      scorer.addTick(stateAt(t, at - Vec3{0.0, 0.0, 0.002}, true, at, force));
    }
  };
  press({0.05, 0.0, 0.0}, 1.0, 10);  // B first: not the next target
  press({0.0, 0.004, 0.0}, 3.0, 10); // A too hard
  press({0.0, 0.004, 0.0}, 1.0, 3);  // A in the band for 2 ms: not yet
  press({0.0, 0.006, 0.0}, 1.0, 1);  // off A: the hold starts again
  EXPECT_EQ(scorer.score().tasks[0].targets.touched, 0);
  press({0.0, 0.004, 0.0}, 1.0, 4); // 3 ms held at the 4th tick: A touched then
  ExerciseScore score = scorer.score();
  EXPECT_EQ(score.tasks[0].targets.touched, 1);
  ASSERT_EQ(score.tasks[0].targets.touchedTimes.size(), 1u);
  EXPECT_NEAR(score.tasks[0].targets.touchedTimes[0], 0.027, 1e-12);
  press({0.051, 0.001, 0.0}, 0.5, 4); // B at the band's edge
  score = scorer.score();
  EXPECT_EQ(score.tasks[0].targets.touched, 2);
  EXPECT_TRUE(score.tasks[0].passed);
  EXPECT_NEAR(score.tasks[0].targets.seconds, 0.031, 1e-12);
  EXPECT_EQ(score.tasks[0].targets.peakForce, 3.0);
  EXPECT_TRUE(score.damage.empty());
}

// A trace task on a 4 cm line along x, tolerance 2 mm: sampled every 1 mm, 41 samples.
ExerciseTask traceAlongX()
{
  ExerciseTask task;
  task.kind = TaskKind::Trace;
  task.trace.line = {{-0.02, 0.0, 0.0}, {0.02, 0.0, 0.0}};
  task.trace.tolerance = 0.002;
  return task;
}

TEST(ExerciseScorer, TraceCoverageAndStraying)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseScorer scorer(exerciseWith(traceAlongX()), scene);
  double t = 0.0;
  const auto touch = [&](double x, double y) {
    scorer.addTick(stateAt(t, {x, y, -0.002}, true, {x, y, 0.0}, 1.0));
    t += 0.001;
  };
  touch(-0.05, 0.0); // before the line: not counted
  // Along the first half on the line (x from -0.02 to 0), then 5 ticks 5 mm off it, then on the
  // line again at x = 0.0015: covered samples x <= 0.003 (within 2 mm of the ticks on the
  // line): 24 of 41.
  for (int i = 0; i <= 20; ++i)
  {
    touch(-0.02 + i * 0.001, 0.0005);
  }
  for (int i = 0; i < 5; ++i)
  {
    touch(0.0, 0.005);
  }
  touch(0.0015, 0.0);
  touch(0.0, 0.009); // after the last tick on the line: not counted
  const ExerciseScore score = scorer.score();
  const TraceScore& trace = score.tasks[0].trace;
  EXPECT_NEAR(trace.coverage, 24.0 / 41.0, 1e-12);
  EXPECT_EQ(trace.contactTicks, 27u);
  EXPECT_NEAR(trace.offLine, 5.0 / 27.0, 1e-12);
  EXPECT_NEAR(trace.maxDeviation, 0.005, 1e-12);
  EXPECT_FALSE(score.tasks[0].passed);
}

// A trace drawn 8 mm beside the line, never within its 2 mm tolerance: nothing covered, and its
// largest deviation is 8 mm (the ticks' farthest), not the 0 of no tick on the line.
TEST(ExerciseScorer, TraceBesideTheLineDeviatesByItsDistance)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseScorer scorer(exerciseWith(traceAlongX()), scene);
  EXPECT_FALSE(scorer.score().tasks[0].trace.touched);
  double t = 0.0;
  for (int i = 0; i <= 40; ++i)
  {
    const double x = -0.02 + i * 0.001;
    scorer.addTick(stateAt(t, {x, 0.008, -0.002}, true, {x, i == 20 ? 0.0085 : 0.008, 0.0}, 1.0));
    t += 0.001;
  }
  const ExerciseScore score = scorer.score();
  const TraceScore& trace = score.tasks[0].trace;
  EXPECT_TRUE(trace.touched);
  EXPECT_EQ(trace.coverage, 0.0);
  EXPECT_EQ(trace.contactTicks, 0u);
  EXPECT_NEAR(trace.maxDeviation, 0.0085, 1e-12);
  EXPECT_FALSE(scorer.score().tasks[0].passed);
}

/// The score of a press on the floor (limit 5 N) with one tick of each force, 1 ms apart.
ExerciseScore scoreOfPress(const std::vector<double>& forces)
{
  const CollisionScene scene = floorWithNodule();
  ExerciseTask task;
  task.kind = TaskKind::Targets;
  task.targets.targets = {{"A", {0.09, 0.09, 0.0}, 0.001}};
  task.targets.minForce = 0.5;
  task.targets.maxForce = 2.0;
  ExerciseScorer scorer(exerciseWith(task), scene);
  double t = 0.0;
  for (const double force : forces)
  {
    scorer.addTick(stateAt(t, {0.01, 0.0, -0.01}, true, {0.01, 0.0, 0.0}, force));
    t += 0.001;
  }
  return scorer.score();
}

TEST(ExerciseScorer, DamageEventsAreRunsOfTicksOverTheTissuesLimit)
{
  const ExerciseScore score = scoreOfPress({1.0, 5.5, 7.0, 6.0, 4.0, 5.0, 5.01, 1.0});
  ASSERT_EQ(score.damage.size(), 2u);
  EXPECT_EQ(score.damage[0].tissue, "floor");
  EXPECT_NEAR(score.damage[0].startTime, 0.001, 1e-12);
  EXPECT_NEAR(score.damage[0].duration, 0.002, 1e-12);
  EXPECT_EQ(score.damage[0].peakForce, 7.0);
  EXPECT_NEAR(score.damage[1].startTime, 0.006, 1e-12);
  EXPECT_EQ(score.damage[1].duration, 0.0);
  EXPECT_FALSE(score.passed);
}

TEST(ExerciseScorer, AForceHoveringAtTheLimitIsOneDamageEventUntilItFallsBelowTheRelease)
{
  // The floor's limit is 5 N and an event ends below 90 % of it (4.5 N): a press held at the
  // limit, rippling 4.6-5.4 N, is one event; falling to 4.4 N ends it, and rising above 5 N again
  // is a second.
  std::vector<double> forces = {1.0};
  for (int i = 0; i < 20; ++i)
  {
    forces.push_back(i % 2 == 0 ? 5.4 : 4.6);
  }
  forces.push_back(4.5); // at the release level: still held
  forces.push_back(4.4); // below it: the event ends
  forces.push_back(4.9); // under the limit: no new event
  forces.push_back(5.2); // over it: a new one
  const ExerciseScore score = scoreOfPress(forces);
  ASSERT_EQ(score.damage.size(), 2u);
  EXPECT_NEAR(score.damage[0].startTime, 0.001, 1e-12);
  EXPECT_NEAR(score.damage[0].duration, 0.020, 1e-12); // ticks 1 to 21, the last at 4.5 N
  EXPECT_EQ(score.damage[0].peakForce, 5.4);
  EXPECT_NEAR(score.damage[1].startTime, 0.024, 1e-12);
  EXPECT_EQ(score.damage[1].peakForce, 5.2);
}

} // namespace
