#include "Runtime/TickReplay.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace proxima
{

std::int64_t TickReplay::workNanoseconds(const Vec3& finger)
{
  if (!replayable())
  {
    return -1;
  }
  std::int64_t least = std::numeric_limits<std::int64_t>::max();
  for (int repeat = 0; repeat < m_repeats; ++repeat)
  {
    m_replica = m_start;
    // Timed as stepProxy times the tick itself: the update alone.
    const auto begin = std::chrono::steady_clock::now();
    m_lastReplay = m_replica.update(finger);
    const auto end = std::chrono::steady_clock::now();
    least = std::min<std::int64_t>(
      least, std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count());
  }
  return least;
}

ProxyTickResult TickReplay::settledWithoutBudget(const Vec3& finger)
{
  m_replica = m_start;
  m_replica.setTickBudget(0, 0.0);
  return m_replica.update(finger);
}

} // namespace proxima
