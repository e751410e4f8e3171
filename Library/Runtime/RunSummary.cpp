#include "Runtime/RunSummary.h"

#include <algorithm>
#include <cmath>

namespace proxima
{
namespace
{
// Nearest-rank quantile q in [0, 1] of `values`, which are sorted; 0 for none.
template <typename T>
double rankOfSorted(const std::vector<T>& values, double q)
{
  if (values.empty())
  {
    return 0.0;
  }
  const double clamped = std::clamp(q, 0.0, 1.0);
  const auto rank =
    static_cast<std::size_t>(std::ceil(clamped * static_cast<double>(values.size())));
  return static_cast<double>(values[rank == 0 ? 0 : rank - 1]);
}

// The same of `values`, sorted here in place.
template <typename T>
double nearestRank(std::vector<T>& values, double q)
{
  std::sort(values.begin(), values.end());
  return rankOfSorted(values, q);
}

// The same, sorting only when `sorted` says they are not yet (per-tick times: asked for four
// quantiles at once).
double nearestRank(std::vector<std::int64_t>& times, bool& sorted, double q)
{
  if (!sorted)
  {
    std::sort(times.begin(), times.end());
    sorted = true;
  }
  return rankOfSorted(times, q);
}
} // namespace

void RunSummary::add(const HapticState& record)
{
  ++m_ticks;
  m_contactTicks += record.numContacts > 0 ? 1 : 0;
  m_totalIterations += static_cast<std::uint64_t>(record.iterations);
  m_maxIterations = std::max(m_maxIterations, record.iterations);
  m_capTicks += record.conditions.has(TickCondition::hitIterationCap) ? 1 : 0;
  m_refusedTicks += record.conditions.has(TickCondition::fingerRefused) ? 1 : 0;
  m_overflowTicks += record.conditions.has(TickCondition::contactOverflow) ? 1 : 0;
  m_clampedTicks += record.conditions.has(TickCondition::forceClamped) ? 1 : 0;
  m_fadingTicks += record.conditions.has(TickCondition::forceFading) ? 1 : 0;
  m_deviceLostTicks += record.conditions.has(TickCondition::deviceLost) ? 1 : 0;
  m_stuckTicks += record.conditions.has(TickCondition::stuck) ? 1 : 0;
  m_frictionLimitedTicks += record.conditions.has(TickCondition::frictionLimited) ? 1 : 0;
  m_startedOutsideTicks += record.conditions.has(TickCondition::startedOutside) ? 1 : 0;
  m_trianglesTested += record.trianglesTested;
  m_maxForce = std::max(m_maxForce, norm(record.force));
  if (record.conditions.has(TickCondition::budgetLimited))
  {
    ++m_budgetLimitedTicks;
    ++m_limitedRun;
  }
  else if (m_limitedRun > 0)
  {
    // This tick is the first that settled after the run: the run took its length to recover.
    m_recoveryTicks.push_back(m_limitedRun);
    m_limitedRun = 0;
  }
  m_solveNanoseconds.push_back(record.solveNanoseconds);
  m_sorted = false;
  m_pushedTicks += record.conditions.has(TickCondition::pushedByObject) ? 1 : 0;
  if (record.dynamicsNanoseconds > 0)
  {
    m_dynamicsNanoseconds.push_back(record.dynamicsNanoseconds);
    m_dynamicsSorted = false;
  }
}

double RunSummary::dynamicsNanosecondsQuantile(double q) const
{
  return nearestRank(m_dynamicsNanoseconds, m_dynamicsSorted, q);
}

double RunSummary::solveNanosecondsQuantile(double q) const
{
  return nearestRank(m_solveNanoseconds, m_sorted, q);
}

void RunSummary::addBudgetResidual(double metres)
{
  m_budgetResiduals.push_back(metres);
}

double RunSummary::budgetResidualQuantile(double q) const
{
  return nearestRank(m_budgetResiduals, q);
}

double RunSummary::recoveryTicksQuantile(double q) const
{
  return nearestRank(m_recoveryTicks, q);
}

std::map<std::uint64_t, std::uint64_t> RunSummary::recoveryHistogram() const
{
  std::map<std::uint64_t, std::uint64_t> histogram;
  for (const std::uint64_t ticks : m_recoveryTicks)
  {
    ++histogram[ticks];
  }
  return histogram;
}

double RunSummary::meanTrianglesTested() const
{
  return m_ticks == 0 ? 0.0 : static_cast<double>(m_trianglesTested) / static_cast<double>(m_ticks);
}

} // namespace proxima
