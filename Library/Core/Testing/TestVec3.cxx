#include "Core/Aabb.h"
#include "Core/Vec3.h"

#include <gtest/gtest.h>

#include <limits>

using proxima::Aabb;
using proxima::Vec3;

TEST(Vec3, CrossIsOrthogonalAndRightHanded)
{
  const Vec3 x{1, 0, 0};
  const Vec3 y{0, 1, 0};
  EXPECT_EQ(proxima::cross(x, y), (Vec3{0, 0, 1}));
  const Vec3 a{0.3, -2.0, 5.5};
  const Vec3 b{-1.25, 0.5, 2.0};
  const Vec3 c = proxima::cross(a, b);
  EXPECT_NEAR(proxima::dot(c, a), 0.0, 1e-12);
  EXPECT_NEAR(proxima::dot(c, b), 0.0, 1e-12);
}

TEST(Vec3, NormalizedOrZeroRefusesZeroAndNonFinite)
{
  EXPECT_EQ(proxima::normalizedOrZero(Vec3{}), Vec3{});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(proxima::normalizedOrZero(Vec3{inf, 0, 0}), Vec3{});
  EXPECT_NEAR(proxima::norm(proxima::normalizedOrZero(Vec3{3, 4, 12})), 1.0, 1e-15);
  EXPECT_FALSE(proxima::isFinite(Vec3{0, std::nan(""), 0}));
}

TEST(Vec3, OverflowSafeNormAndDirectionAtTheEndsOfTheRange)
{
  const double inf = std::numeric_limits<double>::infinity();
  // 3-4-12 gives 13 at any scale where the plain norm's squares overflow or underflow.
  for (const double scale : {1e-200, 1.0, 1e155, 1e300})
  {
    const Vec3 v{3.0 * scale, -4.0 * scale, 12.0 * scale};
    EXPECT_NEAR(proxima::overflowSafeNorm(v) / (13.0 * scale), 1.0, 1e-15) << scale;
    const Vec3 unit = proxima::overflowSafeDirection(v);
    EXPECT_NEAR(unit.x, 3.0 / 13.0, 1e-15) << scale;
    EXPECT_NEAR(unit.y, -4.0 / 13.0, 1e-15) << scale;
    EXPECT_NEAR(unit.z, 12.0 / 13.0, 1e-15) << scale;
  }
  EXPECT_TRUE(std::isinf(proxima::norm(Vec3{1e155, 0, 0}))); // why the safe one exists
  EXPECT_EQ(proxima::overflowSafeNorm(Vec3{}), 0.0);
  EXPECT_EQ(proxima::overflowSafeNorm(Vec3{0, -inf, 1}), inf);
  EXPECT_EQ(proxima::overflowSafeDirection(Vec3{0, -inf, 1}), (Vec3{0, -1, 0}));
  EXPECT_EQ(proxima::overflowSafeDirection(Vec3{}), Vec3{});
}

TEST(Aabb, LongestAxisAndDiagonal)
{
  Aabb box;
  EXPECT_TRUE(box.isEmpty());
  EXPECT_EQ(box.diagonal(), 0.0);
  box.expand(Vec3{0, 0, 0});
  box.expand(Vec3{1, 3, 2});
  EXPECT_EQ(box.longestAxis(), 1);
  EXPECT_NEAR(box.diagonal(), std::sqrt(14.0), 1e-15);
  box.expand(Vec3{0, 0, 0}, 10.0);
  EXPECT_EQ(box.lower, (Vec3{-10, -10, -10}));
}
