// Loop statistics: the period histogram's quantiles and the jitter about the nominal period,
// against values worked out by hand from the recorded periods.
#include "Runtime/LoopStatistics.h"

#include <gtest/gtest.h>

namespace proxima
{
namespace
{
TEST(LoopStatistics, QuantilesOfPeriodAndJitter)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(4000.0); // 250 us nominal
  // 98 ticks on time (250.3 us), one 40 us late (290.x us), one 100 us early (150.x us).
  for (int i = 0; i < 98; ++i)
  {
    recorder.record(250300, false);
  }
  recorder.record(290400, false);
  recorder.record(150200, true);
  recorder.recordWork(1200);
  recorder.recordWork(300000); // one tick over its 250 us budget
  const LoopStatistics statistics = recorder.snapshot();
  EXPECT_EQ(statistics.ticks, 100u);
  EXPECT_EQ(statistics.missedDeadlines, 1u);
  EXPECT_EQ(statistics.minPeriodNanoseconds, 150200);
  EXPECT_EQ(statistics.maxPeriodNanoseconds, 290400);
  EXPECT_EQ(statistics.maxWorkNanoseconds, 300000);
  EXPECT_EQ(statistics.overBudgetTicks, 1u);
  EXPECT_EQ(statistics.periodHistogram[250], 98u);
  // Periods at the bins' upper edges: the median is in [250, 251) us.
  EXPECT_EQ(statistics.periodQuantileNanoseconds(0.5), 251000.0);
  EXPECT_EQ(statistics.periodQuantileNanoseconds(1.0), 291000.0);
  EXPECT_EQ(statistics.periodQuantileNanoseconds(0.0), 151000.0);
  // Jitter from bin centres: 0.5 us for the 98, 40.5 and 99.5 us for the other two.
  EXPECT_EQ(statistics.jitterQuantileNanoseconds(0.98), 500.0);
  EXPECT_EQ(statistics.jitterQuantileNanoseconds(0.99), 40500.0);
  EXPECT_EQ(statistics.jitterQuantileNanoseconds(1.0), 99500.0);
}

TEST(LoopStatistics, LongPeriodsLandInTheLastBinAndResetClears)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(1000.0);
  recorder.record(50000000, true); // 50 ms
  recorder.recordMissed(3);
  LoopStatistics statistics = recorder.snapshot();
  EXPECT_EQ(statistics.periodHistogram[LoopStatistics::kBins - 1], 1u);
  EXPECT_EQ(statistics.missedDeadlines, 4u);
  recorder.reset(1000.0);
  statistics = recorder.snapshot();
  EXPECT_EQ(statistics.ticks, 0u);
  EXPECT_EQ(statistics.missedDeadlines, 0u);
  EXPECT_EQ(statistics.periodQuantileNanoseconds(0.5), 0.0);
}

} // namespace
} // namespace proxima
