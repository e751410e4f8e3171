// The force plot's curve against its samples, worked out by hand for a box from (0.5, 0.5) to
// (1, 1): x goes from the box's left (the window's start) to its right (the newest sample), y from
// its bottom (0 N) to its top (the clamp), forces above the clamp drawn at the top.
#include "ForcePlot.h"

#include <gtest/gtest.h>

namespace
{
using proxima::shell::ForcePlot;

TEST(ForcePlot, MapsTheLastSecondsOfForceIntoItsBox)
{
  ForcePlot plot(2.0, 10.0);
  plot.place(0.5, 0.5, 1.0, 1.0);
  plot.add(0.0, 0.0);
  plot.add(1.0, 5.0);
  plot.add(2.0, 12.0);
  plot.update();
  ASSERT_EQ(plot.curve().size(), 3u);
  EXPECT_DOUBLE_EQ(plot.curve()[0][0], 0.5);
  EXPECT_DOUBLE_EQ(plot.curve()[0][1], 0.5);
  EXPECT_DOUBLE_EQ(plot.curve()[1][0], 0.75);
  EXPECT_DOUBLE_EQ(plot.curve()[1][1], 0.75);
  EXPECT_DOUBLE_EQ(plot.curve()[2][0], 1.0);
  EXPECT_DOUBLE_EQ(plot.curve()[2][1], 1.0); // 12 N above the 10 N clamp: at the top
  // Half a second later the first sample is older than the window and goes.
  plot.add(2.5, 2.0);
  plot.update();
  ASSERT_EQ(plot.curve().size(), 3u);
  EXPECT_DOUBLE_EQ(plot.curve()[0][0], 0.625);
  EXPECT_DOUBLE_EQ(plot.curve()[2][1], 0.6);
}

TEST(ForcePlot, ATimeThatGoesBackRestartsIt)
{
  // A looped path's replay starts its clock again.
  ForcePlot plot(5.0, 10.0);
  plot.add(3.0, 1.0);
  plot.add(4.0, 2.0);
  plot.add(0.1, 3.0);
  plot.update();
  ASSERT_EQ(plot.curve().size(), 1u);
}

} // namespace
