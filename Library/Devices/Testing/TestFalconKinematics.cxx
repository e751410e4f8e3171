// The delta kinematics against independent oracles: forward kinematics against the inverse (a
// separate closed form per arm) in both directions, the Jacobian against central finite
// differences of the forward kinematics, and the torques against virtual work (tau . dtheta =
// F . dp).
#include "Devices/FalconKinematics.h"

#include <gtest/gtest.h>

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
  const Vec3 neutral = *kinematics.forward({0.785398, 0.785398, 0.785398});
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

TEST(FalconKinematics, UnreachableIsNullopt)
{
  const DeltaKinematics kinematics;
  EXPECT_FALSE(kinematics.inverse({0.0, 0.0, -1.0}));
  EXPECT_FALSE(kinematics.inverse({0.5, 0.0, -0.1}));
}

} // namespace
} // namespace proxima
