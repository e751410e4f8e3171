// Period and deadline statistics of a fixed-rate loop: a histogram of the time between the starts
// of consecutive ticks and one of how late each wake-up came after its deadline, written by the
// loop's own thread with relaxed atomics and read from any thread while it runs. The servo loop
// and the bare floor loop (DeadlineClock.h) fill the same recorder through the same clock, so
// their figures compare one to one.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace proxima
{

/// A copy of a loop's statistics at one moment.
struct LoopStatistics
{
  /// Histogram bin width in nanoseconds (1 us), for periods and wake-up latencies alike.
  static constexpr std::int64_t kBinNanoseconds = 1000;
  /// Number of period bins (2048 us in all); the last bin holds everything longer.
  static constexpr int kBins = 2048;
  /// Wake-up latency bins (1 us each): 8 ms, because a shared virtual machine's p99.9 wake-up
  /// is a few milliseconds late; the last bin holds everything later.
  static constexpr int kWakeBins = 8192;

  /// The loop's nominal rate in ticks per second (Hz), as given to reset().
  double rate = 0.0;
  /// Periods recorded: wake-ups after the first (skipped deadlines count none).
  std::uint64_t ticks = 0;
  /// Deadlines missed: ticks that woke more than half a period after their deadline, plus the
  /// deadlines a late loop skipped (it then goes on from the next deadline in the future rather
  /// than bunching ticks).
  std::uint64_t missedDeadlines = 0;
  /// Shortest period between consecutive wake-ups, in nanoseconds (0 before the first).
  std::int64_t minPeriodNanoseconds = 0;
  /// Longest period between consecutive wake-ups, in nanoseconds (0 before the first).
  std::int64_t maxPeriodNanoseconds = 0;
  /// Longest time a tick's work took (from wake-up to done), in nanoseconds, and the ticks whose
  /// work took longer than one nominal period (over budget).
  std::int64_t maxWorkNanoseconds = 0;
  /// Ticks whose work took longer than one nominal period.
  std::uint64_t overBudgetTicks = 0;
  /// Periods per bin: bin i counts periods in [i, i + 1) times kBinNanoseconds; the last bin
  /// also counts every longer one.
  std::array<std::uint64_t, kBins> periodHistogram{};
  /// Every wake-up from a deadline sleep (one more than `ticks`, which counts periods), those
  /// that came more than one period after their deadline, the latest one, and the histogram of
  /// wake-up latency (time from the deadline to the wake-up).
  std::uint64_t wakeUps = 0;
  /// Wake-ups that came more than one period after their deadline.
  std::uint64_t lateWakeUps = 0;
  /// The latest wake-up's latency after its deadline, in nanoseconds.
  std::int64_t maxWakeLatencyNanoseconds = 0;
  /// Wake-ups per bin: bin i counts latencies in [i, i + 1) times kBinNanoseconds; the last bin
  /// also counts every later one.
  std::array<std::uint64_t, kWakeBins> wakeLatencyHistogram{};

  /// Quantile q in [0, 1] of the tick period in nanoseconds, at the bin's upper edge.
  double periodQuantileNanoseconds(double q) const;
  /// Quantile q of |period - nominal period| in nanoseconds: the loop's jitter.
  double jitterQuantileNanoseconds(double q) const;
  /// Quantile q of the wake-up latency in nanoseconds, at the bin's upper edge; in the last
  /// (open) bin, the latest wake-up, which bounds it.
  double wakeLatencyQuantileNanoseconds(double q) const;
};

/// The writer side, owned by one loop thread.
class LoopStatisticsRecorder
{
public:
  /// Clears every count for a loop at `rate` ticks per second (Hz). Call before the loop starts,
  /// not while it runs.
  void reset(double rate);
  /// A tick started `periodNanoseconds` after the previous one; `missed`: it started more than
  /// half a period after its deadline.
  void record(std::int64_t periodNanoseconds, bool missed);
  /// A tick's work took `workNanoseconds`.
  void recordWork(std::int64_t workNanoseconds);
  /// Deadlines that passed while the loop was late, whose ticks were skipped.
  void recordMissed(std::uint64_t count);
  /// The loop woke `latencyNanoseconds` after its deadline; `late`: more than one period after.
  void recordWakeUp(std::int64_t latencyNanoseconds, bool late);
  /// A copy of the counts so far; safe from any thread while the loop runs (each field is read
  /// on its own, so fields may be a tick apart).
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
  std::atomic<std::uint64_t> m_wakeUps{0};
  std::atomic<std::uint64_t> m_lateWakeUps{0};
  std::atomic<std::int64_t> m_maxWakeLatency{0};
  std::array<std::atomic<std::uint64_t>, LoopStatistics::kWakeBins> m_wakeHistogram{};
};

} // namespace proxima
