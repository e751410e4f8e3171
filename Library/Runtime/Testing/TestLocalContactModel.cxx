// The servo's local model of a contact on tissue (LocalContactModel.h), through the force stage,
// against a tissue whose answer is known in closed form: a surface of stiffness kt under a spring
// of stiffness kp, stepped quasi-statically every five ticks (its surface moves to where the
// spring's force at the step balances kt), and held still between steps as a solid's surface is.
// The force the hand should feel then rises along one straight line of slope kp kt / (kp + kt)
// per metre of press; the spring alone rises at kp between steps and falls back at each.
#include "Runtime/ServoForce.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace proxima
{
// Named, so that the unity build's batch that also holds TestServoForce.cxx keeps the two files'
// constants apart.
namespace local_contact_model_tests
{
constexpr double kPeriod = 0.001;
constexpr double kSpring = 1000.0; // kp, N/m
constexpr double kTissue = 250.0;  // kt, N/m
constexpr double kSeries = kSpring * kTissue / (kSpring + kTissue);
constexpr int kTicksPerStep = 5;

// The quasi-static tissue: its surface is depth `surface` (m) below z = 0, its normal +z.
struct QuasiStaticTissue
{
  double surface = 0.0;
  std::uint64_t steps = 0;
  bool deforms = true;
  /// A rigid object pressed beside the tissue (a second contact plane, tilted).
  bool besideRigid = false;

  // The proxy half of a tick with the finger `press` metres below z = 0: the proxy rests on
  // the surface while the finger is below it.
  HapticState proxyHalf(double press) const
  {
    HapticState state;
    state.sceneVersion = 1;
    state.surfaceChanges = steps;
    const bool touching = press > surface;
    state.proxy = {0.0, 0.0, touching ? -surface : -press};
    if (touching)
    {
      state.numContacts = 1;
      state.contacts[0].normal = {0.0, 0.0, 1.0};
      state.contacts[0].point = state.proxy;
      state.contacts[0].depth = press - surface;
      state.contacts[0].deforms = deforms;
      state.contactObject = 0;
      if (besideRigid)
      {
        state.numContacts = 2;
        state.contacts[1] = state.contacts[0];
        state.contacts[1].normal = {0.6, 0.0, 0.8};
        state.contacts[1].object = 1;
        state.contacts[1].deforms = false;
      }
    }
    return state;
  }

  // The step after a tick with the finger `press` metres in: the surface settles where kt
  // balances the spring stretched from it to the finger, kt s = kp (press - s), as the solid's
  // step takes its contact springs implicitly; without contact it rests at z = 0.
  void step(double press)
  {
    if (deforms)
    {
      surface = std::max(0.0, kSpring * press / (kSpring + kTissue));
      ++steps;
    }
  }
};

// Plays the finger's presses (m below z = 0, one a tick) on `tissue` through a force stage and
// returns the force's z on the finger at each tick; the spring's own, kp (proxy - finger), in
// `springs`.
std::vector<double> play(QuasiStaticTissue& tissue, const std::vector<double>& presses,
                         std::vector<double>* springs = nullptr)
{
  ServoParameters parameters;
  parameters.stiffness = kSpring;
  ServoForce stage(parameters);
  std::vector<double> forces;
  for (std::size_t k = 0; k < presses.size(); ++k)
  {
    TickInput input;
    input.tick = k;
    input.time = static_cast<double>(k) * kPeriod;
    input.sample.position = {0.0, 0.0, -presses[k]};
    HapticState state = tissue.proxyHalf(presses[k]);
    stage.step(input, state);
    forces.push_back(state.force.z);
    EXPECT_EQ(state.force.x, 0.0);
    EXPECT_EQ(state.force.y, 0.0);
    if (springs != nullptr)
    {
      springs->push_back(kSpring * (state.proxy.z - input.sample.position.z));
    }
    if ((k + 1) % kTicksPerStep == 0)
    {
      tissue.step(presses[k]);
    }
  }
  return forces;
}

// The finger from 1 mm above the surface into it at 10 mm/s for 0.4 s.
std::vector<double> steadyPress()
{
  std::vector<double> presses;
  for (int k = 0; k < 400; ++k)
  {
    presses.push_back(-0.001 + 0.01 * k * kPeriod);
  }
  return presses;
}

TEST(LocalContactModel, BetweenStepsTheForceFollowsTheTissuesStiffnessNotTheSprings)
{
  const std::vector<double> presses = steadyPress();
  QuasiStaticTissue tissue;
  std::vector<double> springs;
  const std::vector<double> forces = play(tissue, presses, &springs);
  const double tickPress = 0.01 * kPeriod;
  // The spring alone: kp per metre between steps, and a drop at every step.
  int drops = 0;
  for (std::size_t k = 150; k < presses.size(); ++k)
  {
    drops += springs[k] < springs[k - 1] ? 1 : 0;
  }
  EXPECT_GE(drops, 45) << "the oracle's spring has no sawtooth to remove";
  // The servo's force: a straight line of the series stiffness's slope, across the steps as
  // between them, once the fit has forgotten the first step's secant (the contact began inside
  // it): within 1 % ten steps on, to 1e-9 forty steps on.
  for (std::size_t k = 151; k < presses.size(); ++k)
  {
    const double tolerance = (k < 300 ? 1e-2 : 1e-9) * kSeries * tickPress;
    EXPECT_NEAR(forces[k] - forces[k - 1], kSeries * tickPress, tolerance) << "tick " << k;
  }
  // At each step's first tick, the spring's force exactly.
  for (std::size_t k = 100; k < presses.size(); k += kTicksPerStep)
  {
    EXPECT_EQ(forces[k], springs[k]) << "tick " << k;
  }
}

TEST(LocalContactModel, ARigidContactGetsTheSpringExactly)
{
  const std::vector<double> presses = steadyPress();
  QuasiStaticTissue rigid;
  rigid.deforms = false;
  std::vector<double> springs;
  const std::vector<double> forces = play(rigid, presses, &springs);
  for (std::size_t k = 0; k < presses.size(); ++k)
  {
    EXPECT_EQ(forces[k], springs[k]) << "tick " << k;
  }
}

TEST(LocalContactModel, APressThatAlsoTouchesARigidObjectGetsTheSpringExactly)
{
  const std::vector<double> presses = steadyPress();
  QuasiStaticTissue tissue;
  tissue.besideRigid = true;
  std::vector<double> springs;
  const std::vector<double> forces = play(tissue, presses, &springs);
  for (std::size_t k = 0; k < presses.size(); ++k)
  {
    EXPECT_EQ(forces[k], springs[k]) << "tick " << k;
  }
}

TEST(LocalContactModel, APressAndReleaseGivesTheHandNoEnergy)
{
  // In at 10 mm/s for 0.3 s, held 0.1 s, out at 10 mm/s until 1 mm clear.
  std::vector<double> presses = steadyPress();
  presses.resize(300);
  const double deepest = presses.back();
  presses.insert(presses.end(), 100, deepest);
  for (int k = 1; deepest - 0.01 * k * kPeriod >= -0.001; ++k)
  {
    presses.push_back(deepest - 0.01 * k * kPeriod);
  }
  QuasiStaticTissue tissue;
  std::vector<double> springs;
  const std::vector<double> forces = play(tissue, presses, &springs);
  // The work the force does on the finger, tick by tick (the force held over the tick's move).
  double work = 0.0;
  double springWork = 0.0;
  double pressWork = 0.0;
  for (std::size_t k = 0; k + 1 < presses.size(); ++k)
  {
    const double up = presses[k] - presses[k + 1]; // the finger's move along +z
    work += forces[k] * up;
    springWork += springs[k] * up;
    pressWork += std::min(0.0, forces[k] * up);
  }
  std::printf("work on the finger over the cycle: %.3g J with the model, %.3g J with the spring "
              "alone (the hand put in %.3g J)\n",
              work, springWork, -pressWork);
  EXPECT_LE(work, 0.0) << "the servo gave the hand energy over a closed cycle";
  EXPECT_LT(pressWork, 0.0);
  EXPECT_EQ(forces.back(), 0.0);
  for (std::size_t k = 0; k < forces.size(); ++k)
  {
    EXPECT_GE(forces[k], 0.0) << "a contact pulled at tick " << k;
  }
}

TEST(LocalContactModel, ANewSceneForgetsTheMeasuredStiffness)
{
  const std::vector<double> presses = steadyPress();
  QuasiStaticTissue tissue;
  ServoParameters parameters;
  parameters.stiffness = kSpring;
  ServoForce stage(parameters);
  for (std::size_t k = 0; k < presses.size(); ++k)
  {
    TickInput input;
    input.tick = k;
    input.time = static_cast<double>(k) * kPeriod;
    input.sample.position = {0.0, 0.0, -presses[k]};
    HapticState state = tissue.proxyHalf(presses[k]);
    stage.step(input, state);
    if ((k + 1) % kTicksPerStep == 0)
    {
      tissue.step(presses[k]);
    }
  }
  EXPECT_NEAR(stage.localModel().stiffness(), kSeries, 1e-9 * kSeries);
  TickInput input;
  input.tick = presses.size();
  input.time = static_cast<double>(input.tick) * kPeriod;
  input.sample.position = {0.0, 0.0, -presses.back()};
  HapticState state = tissue.proxyHalf(presses.back());
  state.sceneVersion = 2;
  stage.step(input, state);
  EXPECT_EQ(stage.localModel().stiffness(), kSpring);
}

} // namespace local_contact_model_tests
} // namespace proxima
