// FingerPath playback (DESIGN.md section 3: sparse rows are interpolated linearly at the servo
// rate, and held beyond the ends) and ticksCovering.
#include "Runtime/FingerPath.h"
#include "Runtime/LockstepRuntime.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace proxima
{
namespace
{
FingerPath threeRows()
{
  FingerPath path;
  path.append(0.0, {0, 0, 0});
  path.append(1.0, {1, 2, 3});
  path.append(3.0, {5, 2, -1});
  return path;
}

TEST(FingerPath, InterpolatesLinearlyBetweenRows)
{
  const FingerPath path = threeRows();
  std::size_t hint = 0;
  EXPECT_EQ(path.positionAt(0.5, hint), (Vec3{0.5, 1, 1.5}));
  EXPECT_EQ(path.positionAt(2.0, hint), (Vec3{3, 2, 1}));
  EXPECT_EQ(path.positionAt(2.5, hint), (Vec3{4, 2, 0}));
  // On a row: that row exactly.
  EXPECT_EQ(path.positionAt(1.0, hint), (Vec3{1, 2, 3}));
  EXPECT_EQ(path.positionAt(3.0, hint), (Vec3{5, 2, -1}));
}

TEST(FingerPath, HeldBeyondTheEnds)
{
  const FingerPath path = threeRows();
  std::size_t hint = 0;
  EXPECT_EQ(path.positionAt(-10.0, hint), (Vec3{0, 0, 0}));
  EXPECT_EQ(path.positionAt(3.5, hint), (Vec3{5, 2, -1}));
  EXPECT_EQ(path.positionAt(1e9, hint), (Vec3{5, 2, -1}));
  EXPECT_EQ(path.startTime(), 0.0);
  EXPECT_EQ(path.endTime(), 3.0);
  EXPECT_EQ(path.size(), 3u);
}

TEST(FingerPath, AnyHintGivesTheSameAnswer)
{
  // The hint only speeds playback up: stale, too large or ahead of the time, it must not change
  // the position.
  const FingerPath path = threeRows();
  for (double t = -0.5; t <= 3.5; t += 0.125)
  {
    std::size_t fresh = 0;
    const Vec3 expected = path.positionAt(t, fresh);
    for (std::size_t hint :
         {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{1000}})
    {
      std::size_t h = hint;
      EXPECT_EQ(path.positionAt(t, h), expected) << "t " << t << " hint " << hint;
    }
  }
  // Playing forward with the returned hint (the servo loop's use) matches fresh lookups, and a
  // replay from the start after the end works too.
  std::size_t hint = 0;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int tick = 0; tick <= 3000; ++tick)
    {
      const double t = tick / 1000.0;
      std::size_t fresh = 0;
      ASSERT_EQ(path.positionAt(t, hint), path.positionAt(t, fresh)) << t;
    }
  }
}

TEST(FingerPath, SparseRowsAtTheServoRate)
{
  // Rows every 10 ms played at 1 kHz: ten linear steps per row interval.
  FingerPath path;
  for (int i = 0; i <= 10; ++i)
  {
    path.append(0.01 * i, {0.001 * i * i, 0, 0});
  }
  std::size_t hint = 0;
  for (int tick = 0; tick <= 100; ++tick)
  {
    const double t = tick / 1000.0;
    const int row = std::min(tick / 10, 9);
    const double s = (t - 0.01 * row) / 0.01;
    const double expected = 0.001 * (row * row + s * ((row + 1) * (row + 1) - row * row));
    EXPECT_NEAR(path.positionAt(t, hint).x, expected, 1e-15) << tick;
  }
}

TEST(FingerPath, RepeatedTimeGivesNoNaN)
{
  // Two rows at one time (a jump): never a division by zero.
  FingerPath path;
  path.append(0.0, {0, 0, 0});
  path.append(1.0, {1, 0, 0});
  path.append(1.0, {2, 0, 0});
  path.append(2.0, {3, 0, 0});
  std::size_t hint = 0;
  for (double t = 0.0; t <= 2.0; t += 0.25)
  {
    const Vec3 p = path.positionAt(t, hint);
    EXPECT_TRUE(isFinite(p)) << t;
  }
  std::size_t fresh = 0;
  EXPECT_EQ(path.positionAt(1.5, fresh), (Vec3{2.5, 0, 0}));
}

TEST(TicksCovering, BothEndsIncluded)
{
  EXPECT_EQ(ticksCovering(0.0, 1.0, 1000.0), 1001u);
  EXPECT_EQ(ticksCovering(0.0, 0.0, 1000.0), 1u);
  EXPECT_EQ(ticksCovering(0.0, 0.0015, 1000.0), 2u);
  EXPECT_EQ(ticksCovering(1.7, 2.7, 4000.0), 4001u);
  // A path ending exactly on a tick keeps that tick whatever the rounding of k / rate.
  for (int k = 1; k <= 5000; ++k)
  {
    ASSERT_EQ(ticksCovering(0.0, k / 1000.0, 1000.0), static_cast<std::uint64_t>(k) + 1) << k;
    ASSERT_EQ(ticksCovering(0.25, 0.25 + k / 4000.0, 4000.0), static_cast<std::uint64_t>(k) + 1)
      << k;
  }
}

TEST(TicksCovering, BadInputGivesNoTicks)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ticksCovering(1.0, 0.5, 1000.0), 0u);
  EXPECT_EQ(ticksCovering(0.0, 1.0, 0.0), 0u);
  EXPECT_EQ(ticksCovering(0.0, 1.0, -1000.0), 0u);
  EXPECT_EQ(ticksCovering(nan, 1.0, 1000.0), 0u);
  EXPECT_EQ(ticksCovering(0.0, nan, 1000.0), 0u);
  EXPECT_EQ(ticksCovering(0.0, 1.0, nan), 0u);
}

} // namespace
} // namespace proxima
