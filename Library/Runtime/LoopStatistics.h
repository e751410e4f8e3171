// Period and deadline statistics of a fixed-rate loop: a histogram of the time between the starts
// of consecutive ticks, written by the loop's own thread with relaxed atomics and read from any
// thread while it runs.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace proxima
{

/// A copy of a loop's statistics at one moment.
struct LoopStatistics
{
  /// Histogram bin width in nanoseconds, and the number of bins; the last bin holds everything
  /// longer.
  static constexpr std::int64_t kBinNanoseconds = 1000;
  static constexpr int kBins = 2048;

  double rate = 0.0;
  std::uint64_t ticks = 0;
  /// Deadlines missed: ticks that woke more than half a period after their deadline, plus the
  /// deadlines a late loop skipped (it then goes on from the next deadline in the future rather
  /// than bunching ticks).
  std::uint64_t missedDeadlines = 0;
  std::int64_t minPeriodNanoseconds = 0;
  std::int64_t maxPeriodNanoseconds = 0;
  /// Longest time a tick's work took (from wake-up to done), in nanoseconds, and the ticks whose
  /// work took longer than one nominal period (over budget).
  std::int64_t maxWorkNanoseconds = 0;
  std::uint64_t overBudgetTicks = 0;
  std::array<std::uint64_t, kBins> periodHistogram{};

  /// Quantile q in [0, 1] of the tick period in nanoseconds, at the bin's upper edge.
  double periodQuantileNanoseconds(double q) const;
  /// Quantile q of |period - nominal period| in nanoseconds: the loop's jitter.
  double jitterQuantileNanoseconds(double q) const;
};

/// The writer side, owned by one loop thread.
class LoopStatisticsRecorder
{
public:
  void reset(double rate);
  /// A tick started `periodNanoseconds` after the previous one; `missed`: it started more than
  /// half a period after its deadline.
  void record(std::int64_t periodNanoseconds, bool missed);
  /// A tick's work took `workNanoseconds`.
  void recordWork(std::int64_t workNanoseconds);
  /// Deadlines that passed while the loop was late, whose ticks were skipped.
  void recordMissed(std::uint64_t count);
  LoopStatistics snapshot() const;

private:
  std::atomic<double> m_rate{0.0};
  std::atomic<std::uint64_t> m_ticks{0};
  std::atomic<std::uint64_t> m_missed{0};
  std::atomic<std::int64_t> m_minPeriod{0};
  std::atomic<std::int64_t> m_maxPeriod{0};
  std::atomic<std::int64_t> m_maxWork{0};
  std::atomic<std::uint64_t> m_overBudget{0};
  std::array<std::atomic<std::uint64_t>, LoopStatistics::kBins> m_histogram{};
};

} // namespace proxima
