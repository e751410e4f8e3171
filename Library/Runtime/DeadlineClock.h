// The absolute-deadline clock of a fixed-rate loop, shared by the threaded runtime's loops and by
// the bare floor loop, and the floor loop itself. The floor loop is the servo loop with the work
// taken out: same thread scheduling, same clock, same sleep, same counting, nothing in between.
// What it measures is the platform's floor (DESIGN.md section 5): late wake-ups and missed
// deadlines that the servo would have on this machine under this load even if it did nothing, so
// that the servo's own figures can be read against it.
#pragma once

#include "Runtime/LoopStatistics.h"

#include <cstdint>
#include <string>
#include <thread>

namespace proxima
{

/// A CLOCK_MONOTONIC time or a duration, in nanoseconds.
using Nanoseconds = std::int64_t;

/// CLOCK_MONOTONIC now, in nanoseconds.
Nanoseconds monotonicNanoseconds();

/// Sleeps until the absolute CLOCK_MONOTONIC time `deadline` (clock_nanosleep, TIMER_ABSTIME): a
/// fixed deadline does not drift the way a sleep for one period after the work would.
void sleepUntilNanoseconds(Nanoseconds deadline);

/// The counting half of a loop clock, apart from any sleeping so that it can be fed made-up
/// wake-up times: deadlines `start + k * period`, and for each wake-up the latency from its
/// deadline, late wake-ups (more than one period after the deadline), missed deadlines (woke more
/// than half a period after the deadline, plus the deadlines that passed meanwhile, which are
/// skipped rather than run back to back) and the period since the previous wake-up.
class DeadlineSchedule
{
public:
  /// Deadlines from `start` (tick 0) at `rate` ticks per second (Hz, above 0), counted into
  /// `statistics`, which must outlive the schedule.
  DeadlineSchedule(Nanoseconds start, double rate, LoopStatisticsRecorder& statistics);

  /// The deadline the loop should sleep to next.
  Nanoseconds nextDeadline() const;
  /// The loop woke at `now` from its sleep to nextDeadline(): counts it, and returns the tick
  /// number to run (past any skipped deadlines).
  std::uint64_t wokeAt(Nanoseconds now);
  /// The tick's work ended at `now`.
  void workDoneAt(Nanoseconds now);
  /// The nominal period: 1e9 / rate rounded to whole nanoseconds.
  Nanoseconds period() const { return m_period; }

private:
  Nanoseconds m_start;
  Nanoseconds m_period;
  LoopStatisticsRecorder& m_statistics;
  std::uint64_t m_tick = 0;
  Nanoseconds m_lastWake = 0;
  bool m_wokeOnce = false;
};

/// A DeadlineSchedule on the real clock: sleeps to each deadline and counts the wake-up.
class DeadlineClock
{
public:
  /// A clock whose first deadline is `start` (CLOCK_MONOTONIC) at `rate` ticks per second (Hz),
  /// counted into `statistics`, which must outlive the clock.
  DeadlineClock(Nanoseconds start, double rate, LoopStatisticsRecorder& statistics)
    : m_schedule(start, rate, statistics)
  {}

  /// Waits for the next tick's deadline; returns its tick number.
  std::uint64_t waitForNextTick()
  {
    sleepUntilNanoseconds(m_schedule.nextDeadline());
    return m_schedule.wokeAt(monotonicNanoseconds());
  }
  /// The tick's work ended now: counts the time since the wake-up as its work.
  void workDone() { m_schedule.workDoneAt(monotonicNanoseconds()); }
  /// The nominal period in nanoseconds.
  Nanoseconds period() const { return m_schedule.period(); }

private:
  DeadlineSchedule m_schedule;
};

/// Asks for SCHED_FIFO at `priority` for `thread`: the error text when refused, empty when
/// granted.
std::string requestFifoScheduling(std::thread& thread, int priority);
/// The policy and priority `thread` actually runs with, e.g. "SCHED_FIFO 80" or "SCHED_OTHER".
std::string describeScheduling(std::thread& thread);

/// What the floor loop does: the servo's rate, duration and scheduling request.
struct DeadlineFloorSettings
{
  /// Ticks per second (Hz): the servo's rate.
  double rate = 4000.0;
  /// Seconds of deadlines; the loop ends at the first deadline past it, as the servo does.
  double duration = 1.0;
  /// Whether to ask for SCHED_FIFO for the loop's thread; a refusal is no error, and shows in the
  /// report's `scheduling`.
  bool realtimeScheduling = true;
  /// SCHED_FIFO priority asked for when `realtimeScheduling`.
  int priority = 80;
};

/// What the floor loop measured, to read the servo's figures against.
struct DeadlineFloorReport
{
  /// The loop's period, deadline and wake-up statistics at its end.
  LoopStatistics statistics;
  /// What the floor thread ran with (describeScheduling): SCHED_FIFO when asked for and
  /// permitted, else the normal policy, as the servo thread then gets.
  std::string scheduling;
};

/// Runs the bare loop on a thread of its own for `settings.duration` and waits for it.
DeadlineFloorReport measureDeadlineFloor(const DeadlineFloorSettings& settings);

} // namespace proxima
