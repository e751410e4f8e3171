// The summary's budget statistics on hand-made records: limited ticks, the length of each run of
// consecutive limited ticks (the ticks it took to recover), a run still open at the end, and the
// residual quantiles.
#include "Runtime/RunSummary.h"

#include <gtest/gtest.h>

#include <initializer_list>

namespace proxima
{
namespace
{
RunSummary summaryOf(std::initializer_list<bool> limited)
{
  RunSummary summary;
  std::uint64_t tick = 0;
  for (const bool budgetLimited : limited)
  {
    HapticState record;
    record.tick = tick++;
    record.conditions.set(TickCondition::budgetLimited, budgetLimited);
    summary.add(record);
  }
  return summary;
}

TEST(RunSummaryBudget, CountsEachRunOfLimitedTicksByItsLength)
{
  // Runs of 1, 3 and 1 limited ticks, each followed by a settled tick.
  const RunSummary summary =
    summaryOf({false, true, false, true, true, true, false, false, true, false});
  EXPECT_EQ(summary.ticks(), 10u);
  EXPECT_EQ(summary.budgetLimitedTicks(), 5u);
  EXPECT_EQ(summary.recoveries(), 3u);
  EXPECT_EQ(summary.unrecoveredLimitedTicks(), 0u);
  EXPECT_EQ(summary.recoveryTicksQuantile(1.0), 3.0);
  EXPECT_EQ(summary.recoveryTicksQuantile(0.5), 1.0);
  const auto histogram = summary.recoveryHistogram();
  ASSERT_EQ(histogram.size(), 2u);
  EXPECT_EQ(histogram.at(1), 2u);
  EXPECT_EQ(histogram.at(3), 1u);
}

TEST(RunSummaryBudget, ARunStillLimitedAtTheEndHasNotRecovered)
{
  const RunSummary summary = summaryOf({true, true, false, true, true, true, true});
  EXPECT_EQ(summary.budgetLimitedTicks(), 6u);
  EXPECT_EQ(summary.recoveries(), 1u);
  EXPECT_EQ(summary.recoveryTicksQuantile(1.0), 2.0);
  EXPECT_EQ(summary.unrecoveredLimitedTicks(), 4u);
}

TEST(RunSummaryBudget, NoLimitedTicksGiveZeros)
{
  const RunSummary summary = summaryOf({false, false, false});
  EXPECT_EQ(summary.budgetLimitedTicks(), 0u);
  EXPECT_EQ(summary.recoveries(), 0u);
  EXPECT_EQ(summary.recoveryTicksQuantile(0.99), 0.0);
  EXPECT_TRUE(summary.recoveryHistogram().empty());
  EXPECT_EQ(summary.budgetResidualQuantile(1.0), 0.0);
}

TEST(RunSummaryBudget, ResidualQuantilesAreNearestRank)
{
  RunSummary summary;
  for (const double metres : {4e-6, 1e-6, 3e-6, 2e-6})
  {
    summary.addBudgetResidual(metres);
  }
  EXPECT_EQ(summary.budgetResiduals(), 4u);
  EXPECT_EQ(summary.budgetResidualQuantile(1.0), 4e-6);
  EXPECT_EQ(summary.budgetResidualQuantile(0.5), 2e-6);
}

} // namespace
} // namespace proxima
