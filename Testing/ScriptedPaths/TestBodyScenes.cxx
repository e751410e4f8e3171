// The paper's section 6 scenes (Data/Scenes: lever, pendulum, sensor-mass, free-block), played
// from their scripted paths (Data/Paths/Bodies) through the coupling `proxima run` uses, and
// checked against answers that do not come from the coupling:
// - statics and closed forms: the lever's spring balances the push (k q = F L), the pendulum's
//   and the test mass's periods (2 pi sqrt(I / m g d), 2 pi sqrt(m / k)), a free block's momentum
//   equals the impulse the trace's forces gave it;
// - no tick penetrates a moving body: the oracle (CGAL, 128-bit distances) measures the proxy
//   against the body's mesh in the body's frame, with the pose the tick's proxy update used;
// - the coupled system adds no energy: the bodies' energy gain never exceeds the work the finger
//   did on them.
// Masses and inertias in the closed forms come from the box's dimensions, not from the mesh
// integration the scene builder uses.
#include "Dynamics/BodyCoupling.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "ProxyOracle.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace proxima
{
namespace
{
// Data/Meshes/box.obj: 0.1 x 0.2 x 0.01 m, centred on the origin; at 1000 kg/m^3 it weighs 0.2 kg.
constexpr double kBoxMass = 0.2;
constexpr double kBoxX = 0.1;
constexpr double kBoxY = 0.2;
constexpr double kBoxZ = 0.01;

struct BodyTick
{
  HapticState state;
  /// Each body's pose after the tick's dynamics step (used by the next tick's proxy update).
  std::vector<RigidTransform> poses;
  std::vector<double> q;
  std::vector<double> qRate;
};

struct BodyRun
{
  std::vector<BodyTick> ticks;
  ScriptedRunOutcome outcome;
  std::vector<std::uint32_t> objects;
  /// Each body's energy (kinetic + potential) at the start.
  std::vector<double> startEnergy;
  LoadedScene loaded;
};

BodyRun playBodyScene(const std::string& scene, const std::string& path)
{
  ScriptedRunSettings settings;
  settings.scene = std::string(PROXIMA_SOURCE_DIR) + "/Data/Scenes/" + scene;
  settings.path = std::string(PROXIMA_SOURCE_DIR) + "/Data/Paths/Bodies/" + path;
  BodyRun run;
  run.loaded = loadScene(settings);
  const std::unique_ptr<BodyCoupling> bodies = sceneBodies(settings, run.loaded);
  EXPECT_NE(bodies, nullptr);
  for (std::size_t body = 0; body < bodies->numBodies(); ++body)
  {
    run.objects.push_back(bodies->object(body));
    const BodyEnergy energy = bodies->world().bodyEnergy(body);
    run.startEnergy.push_back(energy.kinetic + energy.potential);
  }
  const FingerPath finger = readFingerPathFile(settings.path);
  SimulatedDevice device(finger);
  run.outcome = playScriptedPath(
    settings, *run.loaded.scene, finger, device,
    [&](const HapticState& state) {
      BodyTick tick;
      tick.state = state;
      for (std::size_t body = 0; body < bodies->numBodies(); ++body)
      {
        tick.poses.push_back(bodies->transform(body));
        tick.q.push_back(bodies->world().jointPosition(body));
        tick.qRate.push_back(bodies->world().jointVelocity(body));
      }
      run.ticks.push_back(std::move(tick));
    },
    {}, bodies.get());
  return run;
}

// Upward zero crossings of body 0's joint coordinate after `after` seconds, interpolated.
std::vector<double> upwardCrossings(const BodyRun& run, double after)
{
  std::vector<double> times;
  for (std::size_t k = 1; k < run.ticks.size(); ++k)
  {
    const double q0 = run.ticks[k - 1].q[0];
    const double q1 = run.ticks[k].q[0];
    const double t0 = run.ticks[k - 1].state.time;
    const double t1 = run.ticks[k].state.time;
    if (t0 > after && q0 < 0.0 && q1 >= 0.0)
    {
      times.push_back(t0 + (0.0 - q0) / (q1 - q0) * (t1 - t0));
    }
  }
  return times;
}

// Body 0 swings with `period` after `after` seconds: every full swing (upward zero crossing to
// the next) within 1 %, and at least two of them.
void expectPeriods(const BodyRun& run, double after, double period, const char* what)
{
  const std::vector<double> crossings = upwardCrossings(run, after);
  ASSERT_GE(crossings.size(), 3u) << what;
  for (std::size_t i = 1; i < crossings.size(); ++i)
  {
    const double measured = crossings[i] - crossings[i - 1];
    std::printf("[ measured ] %s period %.6f s, closed form %.6f s (%+.4f %%)\n", what, measured,
                period, 100.0 * (measured - period) / period);
    EXPECT_NEAR(measured, period, 0.01 * period) << what;
  }
}

// The largest depth of the proxy inside any moving body, each tick measured against the body
// where that tick's proxy update saw it (the pose after the previous tick's dynamics step).
double deepestPenetration(const BodyRun& run, double radius)
{
  double deepest = 0.0;
  for (std::size_t b = 0; b < run.objects.size(); ++b)
  {
    const TriangleMesh& placed = run.loaded.scene->objects[run.objects[b]].mesh;
    std::vector<TriangleCorners> corners;
    for (std::uint32_t t = 0; t < placed.numTriangles(); ++t)
    {
      corners.push_back(placed.corners(t));
    }
    const oracle::MeshOracle mesh(std::move(corners));
    RigidTransform pose; // the identity: where the body was placed
    for (const BodyTick& tick : run.ticks)
    {
      const Vec3 inBody = pose.applyInverse(tick.state.proxy);
      deepest = std::max(deepest, radius - mesh.distance(inBody, 2.0 * radius));
      pose = tick.poses[b];
    }
  }
  return deepest;
}

void expectNoPenetration(const BodyRun& run)
{
  const double deepest = deepestPenetration(run, 0.001);
  std::printf("[ measured ] deepest the proxy came inside a moving body: %.3g m\n", deepest);
  EXPECT_LE(deepest, 1e-9);
}

void expectNoEnergyGain(const BodyRun& run)
{
  for (std::size_t b = 0; b < run.outcome.bodies.size(); ++b)
  {
    const BodyOutcome& body = run.outcome.bodies[b];
    const double gain = body.kinetic + body.potential - run.startEnergy[b];
    std::printf("[ measured ] %s: energy gained %.6g J, work by the finger %.6g J\n",
                body.name.c_str(), gain, body.work);
    EXPECT_LE(gain, body.work + 1e-12) << body.name;
  }
}

TEST(BodyScenes, LeverSpringBalancesThePushAsFLOverK)
{
  const BodyRun run = playBodyScene("lever.json", "lever-press-hold.csv");
  // Settled under the held finger (1.4 s): the joint's spring torque k q against the moment of
  // the force on the body, -F_finger, about the hinge (anchor (0, -0.1, 0), axis x).
  const BodyTick& held = run.ticks[1400];
  ASSERT_EQ(held.state.numContacts, 1);
  const double k = 2.0;
  const double q = held.q[0];
  const Vec3 onBody = -held.state.force;
  const Vec3 arm = held.state.contacts[0].point - Vec3{0.0, -0.1, 0.0};
  const double pushTorque = cross(arm, onBody).x;
  std::printf("[ measured ] lever: q %.9g rad, F %.6g N, k q %.9g N m, push moment %.9g N m\n", q,
              norm(onBody), k * q, pushTorque);
  EXPECT_LT(q, -0.01); // pressed down (about -x) by a visible angle
  EXPECT_NEAR(-k * q + pushTorque, 0.0, 0.01 * std::abs(pushTorque));
  // The closed form F L / k with L the lever arm of the force's normal component.
  const double lever = std::abs(arm.y);
  EXPECT_NEAR(std::abs(q), std::abs(onBody.z) * lever / k, 0.01 * std::abs(q));
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, PendulumSwingsWithItsSmallAnglePeriod)
{
  const BodyRun run = playBodyScene("pendulum.json", "pendulum-push-release.csv");
  // A bar hung from one end, swinging about x: I_pivot = m (y^2 + z^2) / 12 + m d^2 over its
  // cross-section across the axis (0.01 x 0.2 m once turned upright), d = 0.1 m.
  const double d = kBoxY / 2.0;
  const double inertia = kBoxMass * (kBoxZ * kBoxZ + kBoxY * kBoxY) / 12.0 + kBoxMass * d * d;
  const double period = 2.0 * M_PI * std::sqrt(inertia / (kBoxMass * 9.81 * d));
  expectPeriods(run, 0.4, period, "pendulum");
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, SensorTestMassDeflectsAndRingsAtItsNaturalFrequency)
{
  const BodyRun run = playBodyScene("sensor-mass.json", "sensor-press-release.csv");
  // Held (2.1 s, settled): the spring k x balances the force on the mass.
  const double k = 50.0;
  const double damping = 2.0;
  const BodyTick& held = run.ticks[2100];
  std::printf("[ measured ] test mass: x %.9g m under %.6g N (k x = %.9g N)\n", held.q[0],
              -held.state.force.z, k * held.q[0]);
  EXPECT_LT(held.q[0], -0.001);
  EXPECT_NEAR(k * held.q[0], -held.state.force.z, 0.01 * std::abs(held.state.force.z));
  // Released: it rings at its damped natural frequency, sqrt(k / m) sqrt(1 - zeta^2).
  const double zeta = damping / (2.0 * std::sqrt(k * kBoxMass));
  const double period = 2.0 * M_PI * std::sqrt(kBoxMass / k) / std::sqrt(1.0 - zeta * zeta);
  expectPeriods(run, 2.25, period, "test mass");
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, FreeBlockTakesTheImpulseOfThePush)
{
  const BodyRun run = playBodyScene("free-block.json", "free-block-push.csv");
  // The impulse of the forces on the block (minus the finger's, one period each), against the
  // block's momentum at the end from its motion over the last 0.1 s.
  Vec3 impulse;
  for (const BodyTick& tick : run.ticks)
  {
    if (tick.state.contactObject == 0)
    {
      impulse -= tick.state.force * 0.001;
    }
  }
  const std::size_t last = run.ticks.size() - 1;
  ASSERT_GT(run.ticks[last].state.time, 1.5);
  const Vec3 velocity =
    (run.ticks[last].poses[0].translation - run.ticks[last - 100].poses[0].translation) / 0.1;
  std::printf("[ measured ] free block: impulse %.9g N s, m v %.9g N s\n", impulse.x,
              kBoxMass * velocity.x);
  EXPECT_GT(velocity.x, 0.01);
  EXPECT_NEAR(kBoxMass * velocity.x, impulse.x, 0.01 * impulse.x);
  // It glides out of the scene's bounds (the box around both boxes, 0.1 x 0.2 x 0.022 m, grown
  // by 0.2 m on every side: x up to 0.25 m) when its centre passes x = 0.25 m, and is reported.
  const double exit =
    run.ticks[last].state.time + (0.25 - run.ticks[last].poses[0].translation.x) / velocity.x;
  std::printf(
    "[ measured ] free block: left the scene's bounds at %.4f s, gliding there at %.4f s\n",
    run.outcome.bodies[0].leftBoundsAt, exit);
  EXPECT_NEAR(run.outcome.bodies[0].leftBoundsAt, exit, 0.002);
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, WindmillTurnsAsFastAsItsDampingLetsThePush)
{
  const BodyRun run = playBodyScene("windmill.json", "windmill-turn.csv");
  // The finger goes round the axis at 2 rad/s, pressing on the rotor 4 cm out; once the rotor
  // keeps pace its damping takes the whole moment of the push: c omega = tau, so the terminal
  // speed is tau / c (the paper's windmill spun by the user).
  const double damping = 0.01;
  for (const std::size_t k : {600u, 900u, 1200u, 1500u})
  {
    const BodyTick& tick = run.ticks[k];
    ASSERT_EQ(tick.state.numContacts, 1) << "tick " << k;
    const double torque = cross(tick.state.contacts[0].point, -tick.state.force).z;
    std::printf("[ measured ] windmill at %.1f s: %.6f rad/s, torque / damping %.6f rad/s\n",
                tick.state.time, tick.qRate[0], torque / damping);
    EXPECT_NEAR(tick.qRate[0], torque / damping, 0.01 * tick.qRate[0]);
    EXPECT_NEAR(tick.qRate[0], 2.0, 0.02);
  }
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, CarouselTakesTheAngularImpulseAndCoastsDownAtDampingOverInertia)
{
  const BodyRun run = playBodyScene("carousel.json", "carousel-flick.csv");
  // The flat box on a hinge about z through its centre: I = m (a^2 + b^2) / 12.
  const double inertia = kBoxMass * (kBoxX * kBoxX + kBoxY * kBoxY) / 12.0;
  const double damping = 0.002;
  // Flicked: its angular momentum right after the flick is the angular impulse of the forces on
  // it (the finger's, negated, at the contacts; one period each), less what damping took.
  double impulse = 0.0;
  double lost = 0.0;
  std::size_t last = 0;
  for (std::size_t k = 0; k < run.ticks.size(); ++k)
  {
    const BodyTick& tick = run.ticks[k];
    if (tick.state.numContacts > 0)
    {
      impulse += cross(tick.state.contacts[0].point, -tick.state.force).z * 0.001;
      last = k;
    }
    if (last == k || last == 0)
    {
      lost += damping * tick.qRate[0] * 0.001;
    }
  }
  const double momentum = inertia * run.ticks[last].qRate[0];
  std::printf("[ measured ] carousel: angular impulse %.9g N m s, I omega + damping's %.9g N m s\n",
              impulse, momentum + lost);
  EXPECT_GT(run.ticks[last].qRate[0], 1.0);
  EXPECT_NEAR(momentum + lost, impulse, 0.01 * impulse);
  // Then it coasts: omega(t) = omega_0 exp(-c t / I), measured over 2 s of coasting.
  const BodyTick& early = run.ticks[500];
  const BodyTick& late = run.ticks[2500];
  const double rate =
    std::log(early.qRate[0] / late.qRate[0]) / (late.state.time - early.state.time);
  std::printf("[ measured ] carousel: coasts down at %.6f /s, c / I %.6f /s (%+.3f %%)\n", rate,
              damping / inertia, 100.0 * (rate - damping / inertia) / (damping / inertia));
  EXPECT_NEAR(rate, damping / inertia, 0.01 * damping / inertia);
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

TEST(BodyScenes, BallPendulumSwingsInItsPlaneWithThatPlanesPeriod)
{
  BodyRun run = playBodyScene("ball-pendulum.json", "ball-pendulum-push-release.csv");
  // The upright box hung by a ball at its top edge's middle, pushed on its side: it swings about
  // y, in its own plane, where its inertia about the ball is m (x^2 + z^2) / 12 + m d^2 over
  // its 0.1 x 0.2 m face, d = 0.1 m. A ball joint has no single coordinate: the signed angle
  // about y comes from the pose, and the pose must hold no turn about any other axis.
  const double d = kBoxY / 2.0;
  const double inertia = kBoxMass * (kBoxX * kBoxX + kBoxY * kBoxY) / 12.0 + kBoxMass * d * d;
  const double period = 2.0 * M_PI * std::sqrt(inertia / (kBoxMass * 9.81 * d));
  double offPlane = 0.0;
  std::vector<double> reported;
  std::vector<double> reportedRate;
  for (BodyTick& tick : run.ticks)
  {
    const RigidTransform& pose = tick.poses[0];
    reported.push_back(tick.q[0]);
    reportedRate.push_back(tick.qRate[0]);
    tick.q[0] = std::atan2(pose.row[0].z, pose.row[0].x);
    offPlane = std::max(
      {offPlane, std::abs(pose.row[1].x), std::abs(pose.row[1].z), std::abs(pose.row[0].y)});
  }
  std::printf("[ measured ] ball pendulum: largest turn out of its plane %.3g\n", offPlane);
  EXPECT_LT(offPlane, 1e-9);
  // What the summary and --bodies-out report for it: the angle of its turn, |theta|, and its
  // angular speed, |d theta / dt| (central differences of the pose's angle, once the finger has
  // let go: its push is a kick within a tick); and with them, after the release, the energy of the swing about the ball, I w^2 / 2 + m g d (1 - cos q),
  // stays that of its largest angle, m g d (1 - cos q_max).
  double largest = 0.0;
  double fastest = 0.0;
  for (std::size_t k = 0; k < run.ticks.size(); ++k)
  {
    EXPECT_NEAR(reported[k], std::abs(run.ticks[k].q[0]), 1e-9) << "tick " << k;
    fastest = std::max(fastest, reportedRate[k]);
    if (run.ticks[k].state.time > 0.4)
    {
      largest = std::max(largest, reported[k]);
    }
  }
  ASSERT_GT(largest, 0.01);
  const double swing = kBoxMass * 9.81 * d * (1.0 - std::cos(largest));
  double worstRate = 0.0;
  double worstEnergy = 0.0;
  for (std::size_t k = 1; k + 1 < run.ticks.size(); ++k)
  {
    if (run.ticks[k].state.time > 0.4)
    {
      const double dt = run.ticks[k + 1].state.time - run.ticks[k - 1].state.time;
      const double rate = std::abs(run.ticks[k + 1].q[0] - run.ticks[k - 1].q[0]) / dt;
      worstRate = std::max(worstRate, std::abs(reportedRate[k] - rate));
      const double energy = 0.5 * inertia * reportedRate[k] * reportedRate[k] +
                            kBoxMass * 9.81 * d * (1.0 - std::cos(reported[k]));
      worstEnergy = std::max(worstEnergy, std::abs(energy - swing));
    }
  }
  std::printf("[ measured ] ball pendulum: q up to %.6f rad, q_rate up to %.6f rad/s, off the "
              "pose's d theta / dt by up to %.3g rad/s, energy off by up to %.3g of %.6g J\n",
              largest, fastest, worstRate, worstEnergy, swing);
  EXPECT_LT(worstRate, 0.01 * fastest);
  EXPECT_LT(worstEnergy, 0.02 * swing);
  expectPeriods(run, 0.4, period, "ball pendulum");
  expectNoPenetration(run);
  expectNoEnergyGain(run);
}

// The crank's links (Data/Scenes/crank.xml): aluminium boxes, the arm 2 x 0.8 x 12 cm centred
// 5 cm below the hinge (axis y), the handle 1.6 x 3 x 1.6 cm centred 10 cm below it.
constexpr double kAluminium = 2700.0;
constexpr double kArmMass = kAluminium * 0.02 * 0.008 * 0.12;
constexpr double kHandleMass = kAluminium * 0.016 * 0.03 * 0.016;

TEST(BodyScenes, CrankTurnsAgainstItsWeightAndItsDamping)
{
  const BodyRun run = playBodyScene("crank.json", "crank-turn.csv");
  ASSERT_EQ(run.objects.size(), 2u); // the arm (the hinge's body) and the handle fixed to it
  // About the hinge: I = sum of m (a^2 + c^2) / 12 + m d^2 over the links; gravity's moment at
  // angle q from hanging is -m g d sin q summed, the damping's -c q'.
  const double inertia = kArmMass * (0.02 * 0.02 + 0.12 * 0.12) / 12.0 + kArmMass * 0.05 * 0.05 +
                         kHandleMass * (0.016 * 0.016 + 0.016 * 0.016) / 12.0 +
                         kHandleMass * 0.1 * 0.1;
  const double weightMoment = 9.81 * (kArmMass * 0.05 + kHandleMass * 0.1);
  const double damping = 0.03;
  const double dt = 0.001;
  // While the finger goes round (a turn at pi rad/s, from 0.2 s to 2.45 s; after the first
  // half second, once the push has settled) the moment of its push about the hinge is what the
  // equation of motion asks: I q'' + c q' + m g d sin q.
  double worst = 0.0;
  for (std::size_t k = 700; k < 2400; ++k)
  {
    const BodyTick& tick = run.ticks[k];
    ASSERT_GE(tick.state.numContacts, 1) << "tick " << k;
    const double push = cross(tick.state.contacts[0].point, -tick.state.force).y;
    const double acceleration = (run.ticks[k + 1].qRate[0] - run.ticks[k - 1].qRate[0]) / (2 * dt);
    const double asked =
      inertia * acceleration + damping * tick.qRate[0] + weightMoment * std::sin(tick.q[0]);
    worst = std::max(worst, std::abs(push - asked));
    // The handle turns with the arm: one rigid motion.
    for (int r = 0; r < 3; ++r)
    {
      EXPECT_LT(norm(tick.poses[1].row[r] - tick.poses[0].row[r]), 1e-12);
    }
    EXPECT_LT(norm(tick.poses[1].translation - tick.poses[0].translation), 1e-12);
  }
  std::printf("[ measured ] crank: push moment against I q'' + c q' + m g d sin q: worst %.3g N m "
              "of %.3g (weight) + %.3g (damping at pi rad/s)\n",
              worst, weightMoment, damping * M_PI);
  EXPECT_LT(worst, 0.01 * (weightMoment + damping * M_PI));
  // A whole turn and more, then it hangs again (q back to 2 pi, within its slow settling).
  const BodyTick& released = run.ticks[2450];
  EXPECT_GT(released.q[0], 2.0 * M_PI);
  const double rest = run.ticks.back().q[0];
  std::printf("[ measured ] crank: q %.6f rad at release, %.6f rad at the end\n", released.q[0],
              rest);
  EXPECT_NEAR(rest, 2.0 * M_PI, 0.02);
  // The energy the finger put in went into the damper: the work equals the damping's loss plus
  // the change of the links' energy.
  double dissipated = 0.0;
  for (const BodyTick& tick : run.ticks)
  {
    dissipated += damping * tick.qRate[0] * tick.qRate[0] * dt;
  }
  double work = 0.0;
  double gain = 0.0;
  for (std::size_t b = 0; b < run.outcome.bodies.size(); ++b)
  {
    const BodyOutcome& body = run.outcome.bodies[b];
    work += body.work;
    gain += body.kinetic + body.potential - run.startEnergy[b];
  }
  std::printf("[ measured ] crank: work by the finger %.6g J, damping's loss %.6g J, energy "
              "gained %.3g J\n",
              work, dissipated, gain);
  EXPECT_NEAR(work, dissipated + gain, 0.01 * work);
  EXPECT_LE(gain, work);
  expectNoPenetration(run);
}

TEST(BodyScenes, OnlyObjectsWithABodyAreCoupled)
{
  // The slab under the free block is no body: only the block is coupled, and a scene without
  // bodies makes no coupling at all.
  const BodyRun run = playBodyScene("free-block.json", "free-block-push.csv");
  ASSERT_EQ(run.objects.size(), 1u);
  EXPECT_EQ(run.objects[0], 0u);
  ScriptedRunSettings plain;
  plain.scene = std::string(PROXIMA_SOURCE_DIR) + "/Data/Scenes/spheres-on-table.json";
  const LoadedScene loaded = loadScene(plain);
  EXPECT_EQ(sceneBodies(plain, loaded), nullptr);
}

} // namespace
} // namespace proxima
