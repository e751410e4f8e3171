// The deadline clock's counting, on made-up wake-up times (no real clock, so nothing here depends
// on the machine), and the floor loop's report on the real clock for a few milliseconds, checked
// only for being consistent with itself.
#include "Runtime/DeadlineClock.h"

#include <gtest/gtest.h>

namespace proxima
{
namespace
{
constexpr Nanoseconds kMicrosecond = 1000;

TEST(DeadlineSchedule, CountsLateWakeUpsAndMissedDeadlinesFromWakeUpTimes)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(4000.0); // 250 us period
  const Nanoseconds start = 1000000000;
  DeadlineSchedule schedule(start, 4000.0, recorder);
  EXPECT_EQ(schedule.period(), 250 * kMicrosecond);

  // Tick 0 wakes 10 us late: on time.
  EXPECT_EQ(schedule.nextDeadline(), start);
  EXPECT_EQ(schedule.wokeAt(start + 10 * kMicrosecond), 0u);
  // Tick 1 wakes 200 us late: more than half a period, a missed deadline, but not a late wake-up.
  EXPECT_EQ(schedule.nextDeadline(), start + 250 * kMicrosecond);
  EXPECT_EQ(schedule.wokeAt(start + 450 * kMicrosecond), 1u);
  // Tick 2 wakes 600 us late: a late wake-up; the two deadlines that passed meanwhile are
  // skipped and missed, and the loop runs tick 4.
  EXPECT_EQ(schedule.nextDeadline(), start + 500 * kMicrosecond);
  EXPECT_EQ(schedule.wokeAt(start + 1100 * kMicrosecond), 4u);
  // Then tick 5 on time.
  EXPECT_EQ(schedule.nextDeadline(), start + 1250 * kMicrosecond);
  EXPECT_EQ(schedule.wokeAt(start + 1251 * kMicrosecond), 5u);
  schedule.workDoneAt(start + 1300 * kMicrosecond);

  const LoopStatistics statistics = recorder.snapshot();
  EXPECT_EQ(statistics.wakeUps, 4u);
  EXPECT_EQ(statistics.ticks, 3u); // periods between the four wake-ups
  EXPECT_EQ(statistics.lateWakeUps, 1u);
  EXPECT_EQ(statistics.missedDeadlines, 1u + 1u + 2u);
  EXPECT_EQ(statistics.maxWakeLatencyNanoseconds, 600 * kMicrosecond);
  EXPECT_EQ(statistics.maxWorkNanoseconds, 49 * kMicrosecond);
  EXPECT_EQ(statistics.wakeLatencyHistogram[10], 1u);
  EXPECT_EQ(statistics.wakeLatencyHistogram[200], 1u);
  EXPECT_EQ(statistics.wakeLatencyHistogram[600], 1u);
  EXPECT_EQ(statistics.wakeLatencyHistogram[1], 1u);
  // Quantiles at the bins' upper edges.
  EXPECT_EQ(statistics.wakeLatencyQuantileNanoseconds(0.5), 11000.0);
  EXPECT_EQ(statistics.wakeLatencyQuantileNanoseconds(1.0), 601000.0);
}

TEST(DeadlineSchedule, AFirstWakeUpPastHalfAPeriodIsMissed)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(1000.0);
  DeadlineSchedule schedule(0, 1000.0, recorder);
  EXPECT_EQ(schedule.wokeAt(600 * kMicrosecond), 0u);
  const LoopStatistics statistics = recorder.snapshot();
  EXPECT_EQ(statistics.ticks, 0u);
  EXPECT_EQ(statistics.wakeUps, 1u);
  EXPECT_EQ(statistics.missedDeadlines, 1u);
  EXPECT_EQ(statistics.lateWakeUps, 0u);
}

TEST(DeadlineSchedule, WakeUpsBeyondTheHistogramReportTheLatest)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(1000.0);
  DeadlineSchedule schedule(0, 1000.0, recorder);
  schedule.wokeAt(20000 * kMicrosecond); // 20 ms late: past the 8 ms histogram
  const LoopStatistics statistics = recorder.snapshot();
  EXPECT_EQ(statistics.wakeLatencyHistogram[LoopStatistics::kWakeBins - 1], 1u);
  EXPECT_EQ(statistics.wakeLatencyQuantileNanoseconds(0.5), 20000000.0);
  EXPECT_EQ(statistics.lateWakeUps, 1u);
  EXPECT_EQ(statistics.missedDeadlines, 1u + 20u); // woke late, and 20 deadlines skipped
}

TEST(DeadlineFloor, RunsForItsDurationAndReportsConsistently)
{
  DeadlineFloorSettings settings;
  settings.rate = 2000.0;
  settings.duration = 0.02;
  const DeadlineFloorReport report = measureDeadlineFloor(settings);
  const LoopStatistics& statistics = report.statistics;
  EXPECT_FALSE(report.scheduling.empty());
  EXPECT_EQ(statistics.rate, 2000.0);
  // However late the wake-ups, the loop ends at the first tick past 20 ms (tick 41 or later), and
  // every wake-up but the first ends a period.
  EXPECT_GE(statistics.wakeUps, 1u);
  EXPECT_LE(statistics.wakeUps, 42u);
  EXPECT_EQ(statistics.ticks + 1, statistics.wakeUps);
  EXPECT_LE(statistics.lateWakeUps, statistics.wakeUps);
  EXPECT_GE(statistics.missedDeadlines, statistics.lateWakeUps);
  std::uint64_t histogramTotal = 0;
  for (const std::uint64_t count : statistics.wakeLatencyHistogram)
  {
    histogramTotal += count;
  }
  EXPECT_EQ(histogramTotal, statistics.wakeUps);
  EXPECT_LE(statistics.wakeLatencyQuantileNanoseconds(0.5),
            statistics.wakeLatencyQuantileNanoseconds(1.0));
}

} // namespace
} // namespace proxima
