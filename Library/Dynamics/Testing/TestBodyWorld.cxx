// The bodies' integration against closed forms: a physical pendulum's period, a lever's static
// deflection against its torsional spring (F L / k), a mass on a spring's natural frequency, a free
// body's momentum (F t = m v), no energy gained by a damped mechanism, and bad bodies refused.
#include "Dynamics/BodyWorld.h"
#include "Geometry/ProceduralMeshes.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kRate = 1000.0;

TriangleMesh boxMesh(const Vec3& half, const Vec3& center)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(makeBox(half, center), error));
  return mesh;
}

BodyDescription body(const char* name, const TriangleMesh& mesh, double density,
                     const JointDescription& joint)
{
  BodyDescription description;
  description.name = name;
  description.joint = joint;
  description.mass = solidMassProperties(mesh, density);
  return description;
}

DynamicsSettings settings(const Vec3& gravity = {})
{
  DynamicsSettings s;
  s.timeStep = 1.0 / kRate;
  s.gravity = gravity;
  return s;
}

// Times at which q crosses zero going up, interpolated within the step.
std::vector<double> upwardCrossings(BodyWorld& world, double seconds)
{
  std::vector<double> crossings;
  double previous = world.jointPosition(0);
  const auto steps = static_cast<int>(seconds * kRate);
  for (int i = 0; i < steps; ++i)
  {
    world.step();
    const double q = world.jointPosition(0);
    if (previous < 0.0 && q >= 0.0)
    {
      crossings.push_back(world.time() - (q / (q - previous)) / kRate);
    }
    previous = q;
  }
  return crossings;
}

// The measured against the analytic, in the test's output (Documentation/Dynamics.md quotes it).
void report(const char* what, double measured, double analytic)
{
  std::printf("%s: measured %.9g, analytic %.9g, error %.4f %%\n", what, measured, analytic,
              100.0 * (measured - analytic) / analytic);
}

double meanPeriod(const std::vector<double>& crossings)
{
  EXPECT_GE(crossings.size(), 3u);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(BodyWorld, PhysicalPendulumPeriod)
{
  // A 20 cm bar hanging from a hinge at its top end, swinging a few hundredths of a radian.
  const Vec3 half{0.01, 0.01, 0.1};
  const TriangleMesh bar = boxMesh(half, {0.0, 0.0, -0.1});
  JointDescription hinge;
  hinge.axis = {1.0, 0.0, 0.0};
  BodyWorld world({body("pendulum", bar, 1000.0, hinge)}, settings({0.0, 0.0, -9.81}));
  // A short push sideways starts the swing.
  for (int i = 0; i < 5; ++i)
  {
    world.applyForce(0, {0.0, 0.0, -0.2}, {0.0, 0.2, 0.0});
    world.step();
  }
  const SolidMassProperties& mass = solidMassProperties(bar, 1000.0);
  const double d = 0.1; // pivot to centre of mass
  const double pivotInertia = mass.inertia[0] + mass.mass * d * d;
  const double analytic = 2.0 * std::numbers::pi * std::sqrt(pivotInertia / (mass.mass * 9.81 * d));
  const double period = meanPeriod(upwardCrossings(world, 10.0));
  report("pendulum period (s)", period, analytic);
  EXPECT_NEAR(period, analytic, 0.01 * analytic);
}

TEST(BodyWorld, LeverDeflectsByForceTimesLengthOverStiffness)
{
  // A 20 cm lever on a hinge about z at the origin, a torsional spring k, pushed at its tip.
  const double length = 0.2;
  const double k = 2.0;
  const double force = 1.0;
  const TriangleMesh lever = boxMesh({0.1, 0.01, 0.01}, {0.1, 0.0, 0.0});
  JointDescription hinge;
  hinge.stiffness = k;
  hinge.damping = 0.05;
  BodyWorld world({body("lever", lever, 1000.0, hinge)}, settings());
  const Vec3 tip{length, 0.0, 0.0};
  for (int i = 0; i < 8000; ++i)
  {
    // Perpendicular to the lever as it turns: the torque is F L whatever the angle.
    const BodyPose pose = world.pose(0);
    const Vec3 along = pose.apply(tip) - pose.apply({0.0, 0.0, 0.0});
    const Vec3 perpendicular = cross(Vec3{0.0, 0.0, 1.0}, along) * (1.0 / norm(along));
    world.applyForce(0, pose.apply(tip), perpendicular * force);
    world.step();
  }
  report("lever deflection, force across the lever (rad)", world.jointPosition(0),
         force * length / k);
  EXPECT_NEAR(world.jointPosition(0), force * length / k, 1e-6);
  EXPECT_NEAR(world.jointVelocity(0), 0.0, 1e-6);

  // A force fixed in the world (+y) at the tip: the equilibrium solves k q = F L cos q.
  BodyWorld fixed({body("lever", lever, 1000.0, hinge)}, settings());
  for (int i = 0; i < 8000; ++i)
  {
    fixed.applyForce(0, fixed.pose(0).apply(tip), {0.0, force, 0.0});
    fixed.step();
  }
  double q = force * length / k;
  for (int i = 0; i < 50; ++i)
  {
    q -= (k * q - force * length * std::cos(q)) / (k + force * length * std::sin(q));
  }
  report("lever deflection, force fixed in the world (rad)", fixed.jointPosition(0), q);
  EXPECT_NEAR(fixed.jointPosition(0), q, 1e-6);
}

TEST(BodyWorld, MassOnASpringOscillatesAtItsNaturalFrequency)
{
  // The micro-sensor's test mass: a slider on a spring, pushed once.
  const TriangleMesh mass = boxMesh({0.01, 0.01, 0.01}, {0.0, 0.0, 0.0});
  JointDescription slide;
  slide.type = JointType::Slide;
  slide.axis = {1.0, 0.0, 0.0};
  slide.stiffness = 50.0;
  BodyWorld world({body("test mass", mass, 1000.0, slide)}, settings());
  world.applyForce(0, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  world.step();
  const double m = solidMassProperties(mass, 1000.0).mass;
  const double analytic = 2.0 * std::numbers::pi * std::sqrt(m / 50.0);
  const double period = meanPeriod(upwardCrossings(world, 20.0 * analytic));
  report("spring-mass period (s)", period, analytic);
  EXPECT_NEAR(period, analytic, 0.01 * analytic);
}

TEST(BodyWorld, FreeBodyGainsTheImpulsesMomentum)
{
  const TriangleMesh block = boxMesh({0.05, 0.02, 0.01}, {0.3, 0.0, 0.0});
  JointDescription free;
  free.type = JointType::Free;
  BodyWorld world({body("block", block, 500.0, free)}, settings());
  const SolidMassProperties mass = solidMassProperties(block, 500.0);
  const Vec3 force{0.0, 2.0, 0.0};
  const int steps = 100;
  for (int i = 0; i < steps; ++i)
  {
    // At the centre of mass: a pure translation.
    world.applyForce(0, world.pose(0).apply(mass.centroid), force);
    world.step();
  }
  const double seconds = steps / kRate;
  const Vec3 velocity = world.pointVelocity(0, world.pose(0).apply(mass.centroid));
  EXPECT_NEAR(velocity.y, force.y * seconds / mass.mass, 1e-12);
  EXPECT_NEAR(velocity.x, 0.0, 1e-12);
  // Semi-implicit Euler: y = sum over steps of v_k dt = F dt^2 n (n + 1) / (2 m).
  const Vec3 moved = world.pose(0).apply(mass.centroid) - mass.centroid;
  EXPECT_NEAR(moved.y, force.y * seconds * seconds * (steps + 1) / (2.0 * steps * mass.mass),
              1e-12);
}

TEST(BodyWorld, DampedMechanismGainsNoEnergy)
{
  // A pendulum with hinge damping, kicked, then left alone: its energy only falls.
  const TriangleMesh bar = boxMesh({0.01, 0.01, 0.1}, {0.0, 0.0, -0.1});
  JointDescription hinge;
  hinge.axis = {1.0, 0.0, 0.0};
  hinge.damping = 0.002;
  BodyWorld world({body("pendulum", bar, 1000.0, hinge)}, settings({0.0, 0.0, -9.81}));
  for (int i = 0; i < 20; ++i)
  {
    world.applyForce(0, {0.0, 0.0, -0.2}, {0.0, 1.0, 0.0});
    world.step();
  }
  BodyEnergy start = world.energy();
  double previous = start.kinetic + start.potential;
  double rise = 0.0;
  for (int i = 0; i < 5000; ++i)
  {
    world.step();
    const BodyEnergy now = world.energy();
    const double total = now.kinetic + now.potential;
    rise = std::max(rise, total - previous);
    previous = total;
  }
  EXPECT_GT(start.kinetic, 0.0);
  EXPECT_LT(previous, start.kinetic + start.potential);
  EXPECT_LE(rise, 1e-9 * start.kinetic) << "energy rose in a step by " << rise << " J";
}

TEST(BodyWorld, EffectiveMassIsWhatAPushMovesThroughTheJoint)
{
  // A 20 x 2 x 2 cm bar of 1000 kg/m^3 (0.08 kg) on a hinge about z through one end: a push at a
  // point d from the axis, across it, moves I / d^2 (I = m (L^2 + w^2) / 12 + m (L/2)^2); along
  // the bar it moves nothing (an infinite mass), so the least over directions is I / d^2.
  const TriangleMesh bar = boxMesh({0.1, 0.01, 0.01}, {0.1, 0.0, 0.0});
  const double mass = 1000.0 * 0.2 * 0.02 * 0.02;
  const double inertia = mass * (0.2 * 0.2 + 0.02 * 0.02) / 12.0 + mass * 0.1 * 0.1;
  BodyWorld hinged({body("bar", bar, 1000.0, JointDescription{})}, settings());
  const Vec3 tip{0.2, 0.01, 0.0};
  const double reach = 0.2 * 0.2 + 0.01 * 0.01;
  report("effective mass at the tip of a hinged bar (kg)", hinged.leastEffectiveMass(0, {tip}),
         inertia / reach);
  EXPECT_NEAR(hinged.leastEffectiveMass(0, {tip}), inertia / reach, 1e-12);
  // The least over several points is the farthest one's.
  EXPECT_NEAR(hinged.leastEffectiveMass(0, {{0.05, 0.0, 0.0}, tip, {0.1, 0.0, 0.0}}),
              inertia / reach, 1e-12);
  // A free bar pushed at its centre of mass moves its whole mass, in every direction.
  JointDescription none;
  none.type = JointType::Free;
  BodyWorld free({body("bar", bar, 1000.0, none)}, settings());
  EXPECT_NEAR(free.leastEffectiveMass(0, {{0.1, 0.0, 0.0}}), mass, 1e-12);
}

// An axis is a direction of any length: one whose squared norm overflows (1e300) or underflows
// (1e-300) turns the lever as the unit axis does. MuJoCo normalised 1e300 to a zero axis, warned
// on standard output that the inertia was singular, wrote MUJOCO_LOG.TXT in the current folder,
// and the lever never moved.
TEST(BodyWorld, AnAxisOfAnyLengthTurnsAsItsDirection)
{
  const TriangleMesh lever = boxMesh({0.1, 0.01, 0.01}, {0.1, 0.0, 0.0});
  const auto deflection = [&](const Vec3& axis, const Vec3& push) {
    JointDescription hinge;
    hinge.axis = axis;
    hinge.stiffness = 2.0;
    hinge.damping = 0.05;
    BodyWorld world({body("lever", lever, 1000.0, hinge)}, settings());
    for (int i = 0; i < 2000; ++i)
    {
      world.applyForce(0, world.pose(0).apply({0.2, 0.0, 0.0}), push);
      world.step();
    }
    return world.jointPosition(0);
  };
  std::filesystem::remove("MUJOCO_LOG.TXT");
  testing::internal::CaptureStdout();
  const Vec3 y{0.0, 1.0, 0.0};
  const Vec3 z{0.0, 0.0, 1.0};
  double unit = 0.0;
  double huge = 0.0;
  double tiny = 0.0;
  double diagonal = 0.0;
  double hugeDiagonal = 0.0;
  std::string refused;
  try
  {
    unit = deflection({0.0, 0.0, 1.0}, y);
    huge = deflection({0.0, 0.0, 1e300}, y);
    tiny = deflection({0.0, 0.0, 1e-300}, y);
    diagonal = deflection({1.0, 1.0, 0.0}, z);
    hugeDiagonal = deflection({1e300, 1e300, 0.0}, z);
  }
  catch (const std::exception& error)
  {
    refused = error.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(refused, "");
  EXPECT_FALSE(std::filesystem::exists("MUJOCO_LOG.TXT"));
  EXPECT_GT(unit, 0.05);
  EXPECT_DOUBLE_EQ(huge, unit);
  EXPECT_DOUBLE_EQ(tiny, unit);
  EXPECT_LT(diagonal, -0.01);
  EXPECT_DOUBLE_EQ(hugeDiagonal, diagonal);
}

// MuJoCo's warnings are one line of Proxima's on standard error, its errors exceptions; neither
// reaches standard output or writes MUJOCO_LOG.TXT in the current folder.
TEST(BodyWorld, MujocoMessagesGoToStandardErrorNotToAFile)
{
  const TriangleMesh bar = boxMesh({0.01, 0.01, 0.1}, {0.0, 0.0, -0.1});
  BodyWorld world({body("pendulum", bar, 1000.0, JointDescription{})}, settings());
  std::filesystem::remove("MUJOCO_LOG.TXT");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  mju_warning("a test warning");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(err, "proxima: MuJoCo warning: a test warning\n");
  // MuJoCo's own handler would print, write the log and exit: the test runs it in a child,
  // which leaves by _Exit (no exit-time leak check of the forked copy under the sanitizers).
  EXPECT_EXIT(
    {
      try
      {
        mju_error("a test error");
      }
      catch (const std::runtime_error& error)
      {
        std::_Exit(std::string(error.what()) == "MuJoCo: a test error" ? 0 : 3);
      }
      std::_Exit(4);
    },
    testing::ExitedWithCode(0), "");
  EXPECT_FALSE(std::filesystem::exists("MUJOCO_LOG.TXT"));
}

TEST(BodyWorld, BadBodiesAreRefusedByName)
{
  const TriangleMesh bar = boxMesh({0.01, 0.01, 0.1}, {0.0, 0.0, -0.1});
  const auto refusal = [&](const JointDescription& joint) {
    try
    {
      BodyWorld world({body("crank", bar, 1000.0, joint)}, settings());
    }
    catch (const std::invalid_argument& error)
    {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  JointDescription zeroAxis;
  zeroAxis.axis = {0.0, 0.0, 0.0};
  EXPECT_EQ(refusal(zeroAxis), "body 'crank': the joint's axis is zero");
  JointDescription empty;
  empty.limited = true;
  empty.range[0] = 1.0;
  empty.range[1] = -1.0;
  EXPECT_NE(refusal(empty).find("range is empty"), std::string::npos);
  JointDescription negative;
  negative.damping = -1.0;
  EXPECT_NE(refusal(negative).find("damping is negative"), std::string::npos);
  JointDescription infiniteAxis;
  infiniteAxis.axis = {std::numeric_limits<double>::infinity(), 0.0, 0.0};
  EXPECT_EQ(refusal(infiniteAxis), "body 'crank': the joint's axis is not finite");
  BodyDescription weightless = body("crank", bar, 1000.0, JointDescription{});
  weightless.mass.mass = 0.0;
  EXPECT_THROW(BodyWorld({weightless}, settings()), std::invalid_argument);
}
} // namespace
} // namespace proxima
