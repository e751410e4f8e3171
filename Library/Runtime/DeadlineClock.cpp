#include "Runtime/DeadlineClock.h"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <time.h>

#include <cerrno>
#include <cmath>
#include <cstring>

namespace proxima
{

Nanoseconds monotonicNanoseconds()
{
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<Nanoseconds>(now.tv_sec) * 1000000000 + now.tv_nsec;
}

void sleepUntilNanoseconds(Nanoseconds deadline)
{
  timespec target{};
  target.tv_sec = static_cast<time_t>(deadline / 1000000000);
  target.tv_nsec = static_cast<long>(deadline % 1000000000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &target, nullptr) == EINTR)
  {}
}

DeadlineSchedule::DeadlineSchedule(Nanoseconds start, double rate,
                                   LoopStatisticsRecorder& statistics)
  : m_start(start)
  , m_period(static_cast<Nanoseconds>(std::llround(1e9 / rate)))
  , m_statistics(statistics)
{}

Nanoseconds DeadlineSchedule::nextDeadline() const
{
  return m_start + static_cast<Nanoseconds>(m_tick) * m_period;
}

std::uint64_t DeadlineSchedule::wokeAt(Nanoseconds now)
{
  const Nanoseconds deadline = nextDeadline();
  const Nanoseconds behind = now - deadline;
  m_statistics.recordWakeUp(behind, behind > m_period);
  const bool missed = behind > m_period / 2;
  if (m_wokeOnce)
  {
    m_statistics.record(now - m_lastWake, missed);
  }
  else if (missed)
  {
    // The first wake-up has no period to record, but a late one still missed its deadline.
    m_statistics.recordMissed(1);
  }
  m_wokeOnce = true;
  m_lastWake = now;
  const std::uint64_t tick = m_tick;
  // Deadlines that passed while this tick was late are skipped, not run back to back.
  const std::uint64_t skipped =
    behind > m_period ? static_cast<std::uint64_t>(behind / m_period) : 0;
  if (skipped > 0)
  {
    m_statistics.recordMissed(skipped);
  }
  m_tick += 1 + skipped;
  return tick + skipped;
}

void DeadlineSchedule::workDoneAt(Nanoseconds now)
{
  m_statistics.recordWork(now - m_lastWake);
}

std::string requestFifoScheduling(std::thread& thread, int priority)
{
  sched_param parameters{};
  parameters.sched_priority = priority;
  const int error = pthread_setschedparam(thread.native_handle(), SCHED_FIFO, &parameters);
  return error == 0 ? std::string() : std::string(std::strerror(error));
}

std::string describeScheduling(std::thread& thread)
{
  int policy = 0;
  sched_param parameters{};
  if (pthread_getschedparam(thread.native_handle(), &policy, &parameters) != 0)
  {
    return "unknown";
  }
  switch (policy)
  {
    case SCHED_FIFO: return "SCHED_FIFO " + std::to_string(parameters.sched_priority);
    case SCHED_RR: return "SCHED_RR " + std::to_string(parameters.sched_priority);
    case SCHED_OTHER: return "SCHED_OTHER";
    default: return "policy " + std::to_string(policy);
  }
}

DeadlineFloorReport measureDeadlineFloor(const DeadlineFloorSettings& settings)
{
  LoopStatisticsRecorder recorder;
  recorder.reset(settings.rate);
  // As the runtime's start(): the first deadline a little ahead, so that the thread exists and
  // has its scheduling before it.
  const Nanoseconds start = monotonicNanoseconds() + 10000000;
  const double rate = settings.rate;
  const double duration = settings.duration;
  std::thread floor([&recorder, start, rate, duration] {
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    DeadlineClock clock(start, rate, recorder);
    while (true)
    {
      const std::uint64_t tick = clock.waitForNextTick();
      // The servo's end test, on the tick's time.
      if (static_cast<double>(tick) / rate > duration)
      {
        break;
      }
      clock.workDone();
    }
  });
  DeadlineFloorReport report;
  if (settings.realtimeScheduling)
  {
    // Refused without the privilege, as for the servo thread: describeScheduling says so.
    requestFifoScheduling(floor, settings.priority);
  }
  report.scheduling = describeScheduling(floor);
  floor.join();
  report.statistics = recorder.snapshot();
  return report;
}

} // namespace proxima
