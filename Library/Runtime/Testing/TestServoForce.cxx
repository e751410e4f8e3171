// The servo's force stage: the spring law, the clamp to the smaller of the servo's and the
// device's limit, the fade when the proxy state goes stale or the device is lost (and back in
// when the fault clears), and the force-rate limit after a scene change. Every expectation is
// worked out by hand from the documented rule, tick by tick.
#include "Runtime/ServoForce.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxima
{
namespace
{
constexpr double kPeriod = 0.001;

ServoParameters testParameters()
{
  ServoParameters parameters;
  parameters.stiffness = 1000.0;
  parameters.maxForce = 10.0;
  parameters.watchdogTimeout = 0.005;
  parameters.fadeTime = 0.01;        // ten ticks at 1 kHz
  parameters.forceRateLimit = 100.0; // 0.1 N a tick at 1 kHz
  parameters.sceneChangeWindow = 0.02;
  return parameters;
}

// What the force stage is given at one tick: the tick's input, and the proxy half of the state.
struct ForceTick
{
  TickInput input;
  HapticState proxy;
};

// A finger 2 mm under a proxy at the origin: a spring force of 2 N up.
ForceTick pressing(std::uint64_t tick)
{
  ForceTick given;
  given.input.tick = tick;
  given.input.time = static_cast<double>(tick) * kPeriod;
  given.input.sample.position = {0.0, 0.0, -0.002};
  given.proxy.proxy = {0.0, 0.0, 0.0};
  given.proxy.sceneVersion = 1;
  return given;
}

// The state the stage leaves.
HapticState step(ServoForce& stage, const ForceTick& given)
{
  HapticState state = given.proxy;
  stage.step(given.input, state);
  return state;
}

TEST(ServoForce, SpringLawAndClampToTheSmallerLimit)
{
  DeviceLimits limits;
  limits.maxForce = 1.5;
  ServoForce stage(testParameters(), limits);
  EXPECT_EQ(stage.maxForce(), 1.5);
  const HapticState output = step(stage, pressing(0));
  EXPECT_TRUE(output.conditions.has(TickCondition::forceClamped));
  EXPECT_NEAR(output.force.z, 1.5, 1e-15);
  EXPECT_EQ(output.force.x, 0.0);

  ServoForce unclamped(testParameters());
  ForceTick input = pressing(0);
  input.proxy.stiffnessScale = 0.5;
  const HapticState spring = step(unclamped, input);
  EXPECT_FALSE(spring.conditions.has(TickCondition::forceClamped));
  EXPECT_NEAR(spring.force.z, 1000.0 * 0.5 * 0.002, 1e-15);
}

TEST(ServoForce, TheClampCannotOverflowForAFingerFarAway)
{
  // A finger 1e154 m away made |F|^2 overflow to infinity and the clamped force 0 N; at 1e300 m
  // the spring force itself is infinite. Each must give the clamp's 10 N, pointing at the proxy.
  for (const double far : {1e154, 1e200, 1e300, 1.7e308})
  {
    for (const Vec3& direction : {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, -1.0, 0.0}, Vec3{0.6, 0.0, 0.8}})
    {
      ServoForce stage(testParameters());
      ForceTick given = pressing(0);
      given.input.sample.position = direction * far;
      const HapticState state = step(stage, given);
      ASSERT_TRUE(isFinite(state.force)) << far;
      EXPECT_TRUE(state.conditions.has(TickCondition::forceClamped)) << far;
      EXPECT_NEAR(norm(state.force), 10.0, 1e-12) << far;
      // Towards the proxy at the origin, that is against the finger's direction.
      EXPECT_NEAR(dot(state.force, direction), -10.0, 1e-12) << far;
    }
  }
}

TEST(ServoForce, StaleProxyFadesLinearlyToZeroThenFadesBackIn)
{
  ServoForce stage(testParameters());
  std::uint64_t tick = 0;
  for (; tick < 5; ++tick)
  {
    const HapticState output = step(stage, pressing(tick));
    EXPECT_NEAR(output.force.z, 2.0, 1e-15);
    EXPECT_FALSE(output.conditions.has(TickCondition::forceFading));
  }
  // The proxy loop stops publishing: the proxy state's age grows past the 5 ms timeout.
  double lastZ = 2.0;
  int fadingTicks = 0;
  for (int stalled = 0; stalled < 30; ++stalled, ++tick)
  {
    ForceTick input = pressing(tick);
    input.proxy.proxyAge = 0.006 + stalled * kPeriod;
    // The finger moves on while the proxy is stuck: the fade must not follow the stale spring.
    input.input.sample.position.z = -0.002 - 0.001 * stalled;
    const HapticState output = step(stage, input);
    EXPECT_TRUE(output.proxyStale);
    EXPECT_TRUE(output.conditions.has(TickCondition::forceFading));
    // Ten ticks of 1 ms over a 10 ms fade: 2 N less 0.2 N a tick, from the force at the fault.
    const double expected = std::max(0.0, 2.0 * (1.0 - (stalled + 1) * 0.1));
    EXPECT_NEAR(output.force.z, expected, 1e-12) << "stalled tick " << stalled;
    EXPECT_LE(output.force.z, lastZ);
    lastZ = output.force.z;
    fadingTicks += output.force.z > 0.0 ? 1 : 0;
  }
  EXPECT_EQ(fadingTicks, 9);
  EXPECT_EQ(stage.gain(), 0.0);
  // Fresh states again: the spring comes back over the fade time, not at once.
  for (int fresh = 0; fresh < 12; ++fresh, ++tick)
  {
    const HapticState output = step(stage, pressing(tick));
    const double gain = std::min(1.0, (fresh + 1) * 0.1);
    EXPECT_NEAR(output.force.z, 2.0 * gain, 1e-12) << "fresh tick " << fresh;
    EXPECT_EQ(output.conditions.has(TickCondition::forceFading), gain < 1.0 - 1e-12)
      << "fresh tick " << fresh;
  }
}

TEST(ServoForce, LostDeviceFadesAndIsReported)
{
  ServoForce stage(testParameters());
  step(stage, pressing(0));
  ForceTick input = pressing(1);
  input.input.sample.connected = false;
  input.input.sample.valid = false;
  input.proxy.conditions.set(TickCondition::fingerRefused);
  const HapticState output = step(stage, input);
  EXPECT_TRUE(output.conditions.has(TickCondition::deviceLost));
  EXPECT_TRUE(output.conditions.has(TickCondition::forceFading));
  EXPECT_NEAR(output.force.z, 1.8, 1e-12);
  for (std::uint64_t tick = 2; tick < 20; ++tick)
  {
    input.input.time = static_cast<double>(tick) * kPeriod;
    EXPECT_TRUE(std::isfinite(step(stage, input).force.z));
  }
  EXPECT_EQ(stage.lastForce(), Vec3{});
}

TEST(ServoForce, UnusableSampleHoldsTheLastForce)
{
  ServoForce stage(testParameters());
  step(stage, pressing(0));
  ForceTick input = pressing(1);
  input.input.sample.valid = false;
  input.input.sample.position = {std::nan(""), 0.0, 0.0};
  const HapticState output = step(stage, input);
  EXPECT_FALSE(output.conditions.has(TickCondition::forceFading));
  EXPECT_NEAR(output.force.z, 2.0, 1e-15);
}

TEST(ServoForce, AHeldClampedForceIsTheSameToTheLastBit)
{
  // This finger's clamped force has the magnitude 10.000000000000002 N: clamping it again while
  // it is held moved it in its last bit (found by the stress suite's NaN fingers).
  ServoForce stage(testParameters());
  ForceTick input = pressing(0);
  input.input.sample.position = {0.010392003859619449, 0.012572030410805402, -0.04344711407601869};
  const HapticState clamped = step(stage, input);
  EXPECT_TRUE(clamped.conditions.has(TickCondition::forceClamped));
  for (std::uint64_t tick = 1; tick <= 20; ++tick)
  {
    ForceTick refused = pressing(tick);
    refused.input.sample.valid = false;
    refused.input.sample.position = {std::nan(""), 0.0, 0.0};
    const HapticState held = step(stage, refused);
    EXPECT_EQ(held.force, clamped.force) << "tick " << tick;
  }
}

TEST(ServoForce, SceneChangeLimitsTheForceRateForTheWindow)
{
  ServoForce stage(testParameters());
  ForceTick input = pressing(0);
  input.input.sample.position.z = 0.0; // no force yet
  EXPECT_EQ(step(stage, input).force, Vec3{});
  // The first scene version is not a change; a jump to 2 N on the same scene goes through.
  EXPECT_NEAR(step(stage, pressing(1)).force.z, 2.0, 1e-15);
  // A new scene puts the proxy elsewhere: the spring asks for 8 N at once, the stage allows
  // 100 N/s, 0.1 N a tick, for 20 ms.
  std::uint64_t tick = 2;
  double expected = 2.0;
  for (; tick < 40; ++tick)
  {
    ForceTick changed = pressing(tick);
    changed.proxy.sceneVersion = 2;
    changed.proxy.proxy = {0.0, 0.0, 0.006};
    const HapticState output = step(stage, changed);
    // The window runs from the change (t = 2 ms) for 20 ms: ticks 2..21 are limited.
    if (changed.input.time < 0.002 + 0.02)
    {
      expected = std::min(8.0, expected + 0.1);
      EXPECT_TRUE(output.conditions.has(TickCondition::forceRateLimited)) << "tick " << tick;
    }
    else
    {
      expected = 8.0;
      EXPECT_FALSE(output.conditions.has(TickCondition::forceRateLimited)) << "tick " << tick;
    }
    EXPECT_NEAR(output.force.z, expected, 1e-9) << "tick " << tick;
  }
}

} // namespace
} // namespace proxima
