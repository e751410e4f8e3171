// The Falcon's kinematics against independent oracles: forward kinematics against the inverse
// (a separate closed form per arm) in both directions, against the grip height on the axis
// worked out by hand from libnifalcon's dimensions, against the mechanism's threefold symmetry
// and against the linkage itself (every link its length); the Jacobian against central finite
// differences of the forward kinematics, and the torques against virtual work (tau . dtheta =
// F . dp).
#include "Devices/FalconKinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace proxima
{
namespace
{
TEST(FalconKinematics, ForwardThenInverseGivesTheAngles)
{
  const DeltaKinematics kinematics;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0.2, 1.3);
  int solved = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const JointAngles angles{angle(random), angle(random), angle(random)};
    const auto position = kinematics.forward(angles);
    if (!position)
    {
      continue;
    }
    ++solved;
    const auto back = kinematics.inverse(*position);
    ASSERT_TRUE(back) << "trial " << trial;
    for (std::size_t i = 0; i < 3; ++i)
    {
      EXPECT_NEAR((*back)[i], angles[i], 1e-9) << "trial " << trial << " arm " << i;
    }
  }
  EXPECT_GT(solved, 1900);
}

TEST(FalconKinematics, InverseThenForwardGivesThePosition)
{
  const DeltaKinematics kinematics;
  const double home = falcon::kThetaAtZeroCounts;
  const Vec3 neutral = *kinematics.forward({home, home, home});
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.03, 0.03);
  for (int trial = 0; trial < 2000; ++trial)
  {
    const Vec3 target = neutral + Vec3{offset(random), offset(random), offset(random)};
    const auto angles = kinematics.inverse(target);
    ASSERT_TRUE(angles) << "trial " << trial;
    const auto position = kinematics.forward(*angles);
    ASSERT_TRUE(position);
    EXPECT_LT(distance(*position, target), 1e-12) << "trial " << trial;
  }
}

TEST(FalconKinematics, JacobianMatchesFiniteDifferences)
{
  const DeltaKinematics kinematics;
  std::mt19937 random(13);
  std::uniform_real_distribution<double> angle(0.3, 1.2);
  const double h = 1e-6;
  for (int trial = 0; trial < 500; ++trial)
  {
    const JointAngles angles{angle(random), angle(random), angle(random)};
    const auto jacobian = kinematics.jacobian(angles);
    if (!jacobian || !kinematics.forward(angles))
    {
      continue;
    }
    for (std::size_t joint = 0; joint < 3; ++joint)
    {
      JointAngles plus = angles;
      JointAngles minus = angles;
      plus[joint] += h;
      minus[joint] -= h;
      const auto p = kinematics.forward(plus);
      const auto m = kinematics.forward(minus);
      ASSERT_TRUE(p && m);
      const Vec3 column = (*p - *m) / (2.0 * h);
      for (int axis = 0; axis < 3; ++axis)
      {
        EXPECT_NEAR((*jacobian)[static_cast<std::size_t>(axis)][joint], column[axis], 1e-6)
          << "trial " << trial << " joint " << joint << " axis " << axis;
      }
    }
  }
}

TEST(FalconKinematics, TorquesDoTheForcesVirtualWork)
{
  const DeltaKinematics kinematics;
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(0.4, 1.1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial)
  {
    const JointAngles angles{angle(random), angle(random), angle(random)};
    if (!kinematics.forward(angles))
    {
      continue;
    }
    const Vec3 force{unit(random) * 5, unit(random) * 5, unit(random) * 5};
    const JointAngles tau = kinematics.torques(angles, force);
    const JointAngles step{unit(random) * 1e-6, unit(random) * 1e-6, unit(random) * 1e-6};
    JointAngles moved = angles;
    for (std::size_t i = 0; i < 3; ++i)
    {
      moved[i] += step[i];
    }
    const Vec3 dp = *kinematics.forward(moved) - *kinematics.forward(angles);
    const double jointWork = tau[0] * step[0] + tau[1] * step[1] + tau[2] * step[2];
    EXPECT_NEAR(jointWork, dot(force, dp), 1e-9) << "trial " << trial;
  }
}

TEST(FalconKinematics, EqualAnglesPutTheGripOnTheAxisAtTheHeightWorkedOutByHand)
{
  // With the grip centre on the axis, P = (0, 0, z), every arm sees the same picture in its own
  // frame: the shin's grip end at (c - r, f - s, z) from the hip, so the shin leans out of the
  // arm's plane by f - s and spans L = d + e + sqrt(b^2 - (f - s)^2) in it; the knee is at
  // (a cos t, a sin t), so (c - r - a cos t)^2 + (z - a sin t)^2 = L^2, and the knee-out
  // assembly has the grip beyond the knee: z = a sin t + sqrt(L^2 - (c - r - a cos t)^2).
  const DeltaKinematics kinematics;
  using namespace falcon;
  const double lean = kEffectorAlongAxis - kHipAlongAxis;
  const double span = kKneeLink + kEffectorLink + std::sqrt(kLowerArm * kLowerArm - lean * lean);
  for (const double degrees : {-20.0, 0.0, 20.0, 35.0, 50.0, 80.0})
  {
    const double t = degrees * std::numbers::pi / 180.0;
    const double radial = kEffectorRadial - kHipRadial - kUpperArm * std::cos(t);
    const double z = kUpperArm * std::sin(t) + std::sqrt(span * span - radial * radial);
    const auto position = kinematics.forward({t, t, t});
    ASSERT_TRUE(position) << degrees;
    EXPECT_NEAR(position->x, 0.0, 1e-12) << degrees;
    EXPECT_NEAR(position->y, 0.0, 1e-12) << degrees;
    EXPECT_NEAR(position->z, z, 1e-12) << degrees;
  }
  // The home pose (zero counts, 35 degrees): 134.6 mm out along the axis, by the same formula
  // on a calculator.
  const double home = kThetaAtZeroCounts;
  EXPECT_NEAR(kinematics.forward({home, home, home})->z, 0.1346, 1e-4);
}

TEST(FalconKinematics, CyclingTheAnglesTurnsTheGripAThirdOfATurn)
{
  // The arms are 120 degrees apart and alike: giving arm 0 arm 1's angle, arm 1 arm 2's and arm
  // 2 arm 0's is the same mechanism turned by +120 degrees about the axis.
  const DeltaKinematics kinematics;
  std::mt19937 random(19);
  std::uniform_real_distribution<double> angle(0.1, 1.2);
  const double c = std::cos(2.0 * std::numbers::pi / 3.0);
  const double s = std::sin(2.0 * std::numbers::pi / 3.0);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const JointAngles angles{angle(random), angle(random), angle(random)};
    const auto position = kinematics.forward(angles);
    const auto cycled = kinematics.forward({angles[1], angles[2], angles[0]});
    ASSERT_EQ(position.has_value(), cycled.has_value()) << "trial " << trial;
    if (!position)
    {
      continue;
    }
    ++compared;
    const Vec3 turned{c * position->x - s * position->y, s * position->x + c * position->y,
                      position->z};
    EXPECT_LT(distance(*cycled, turned), 1e-12) << "trial " << trial;
  }
  EXPECT_GT(compared, 150);
}

TEST(FalconKinematics, EveryLinkHasItsLengthAtTheForwardSolution)
{
  // Build each arm's chain from the solved grip position: hip, knee, the knee link's end, the
  // effector link's start, the shin's grip end. The short links turn about axes parallel to the
  // motor axis, so both point the way the shin leans in the arm's plane; the shin between their
  // ends must be b long.
  const DeltaKinematics kinematics;
  using namespace falcon;
  std::mt19937 random(23);
  std::uniform_real_distribution<double> angle(0.1, 1.2);
  for (int trial = 0; trial < 200; ++trial)
  {
    const JointAngles angles{angle(random), angle(random), angle(random)};
    const auto position = kinematics.forward(angles);
    if (!position)
    {
      continue;
    }
    for (std::size_t arm = 0; arm < 3; ++arm)
    {
      const double phi = kArmAngles[arm];
      const Vec3 u{std::cos(phi), std::sin(phi), 0.0};
      const Vec3 v{-std::sin(phi), std::cos(phi), 0.0};
      const Vec3 w{0.0, 0.0, 1.0};
      const Vec3 hip = u * kHipRadial + v * kHipAlongAxis;
      const Vec3 knee = hip + (u * std::cos(angles[arm]) + w * std::sin(angles[arm])) * kUpperArm;
      const Vec3 gripEnd = *position + u * kEffectorRadial + v * kEffectorAlongAxis;
      const Vec3 toGrip = gripEnd - knee;
      const Vec3 lean = normalizedOrZero(toGrip - v * dot(v, toGrip));
      const Vec3 shinStart = knee + lean * kKneeLink;
      const Vec3 shinEnd = gripEnd - lean * kEffectorLink;
      EXPECT_NEAR(distance(hip, knee), kUpperArm, 1e-15);
      EXPECT_NEAR(distance(shinStart, shinEnd), kLowerArm, 1e-10) << "trial " << trial;
      // Knee out: the shin runs from the knee toward the grip, not back across the links.
      EXPECT_GT(dot(shinEnd - shinStart, lean), 0.0) << "trial " << trial;
    }
  }
}

TEST(FalconKinematics, UnreachableIsNullopt)
{
  const DeltaKinematics kinematics;
  EXPECT_FALSE(kinematics.inverse({0.0, 0.0, -1.0}));
  EXPECT_FALSE(kinematics.inverse({0.5, 0.0, -0.1}));
}

} // namespace
} // namespace proxima
