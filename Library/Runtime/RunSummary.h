// Statistics of a run, gathered tick by tick: what `proxima run --summary` reports.
#pragma once

#include "Runtime/HapticState.h"

#include <cstdint>
#include <map>
#include <vector>

namespace proxima
{

/// Counts and quantiles of a run's ticks, fed one HapticState at a time. For one thread: even the
/// const quantile queries sort their samples in place.
class RunSummary
{
public:
  /// Counts one tick's state; keeps its solve time (and dynamics time, when above 0).
  void add(const HapticState& record);

  /// Ticks added.
  std::uint64_t ticks() const { return m_ticks; }
  /// Ticks with at least one active contact.
  std::uint64_t contactTicks() const { return m_contactTicks; }
  /// Move/update iterations of all ticks added.
  std::uint64_t totalIterations() const { return m_totalIterations; }
  /// The most iterations one tick took.
  int maxIterations() const { return m_maxIterations; }
  /// Ticks that hit the solver's iteration cap (TickCondition::hitIterationCap).
  std::uint64_t iterationCapTicks() const { return m_capTicks; }
  /// Ticks whose sample held no usable finger (TickCondition::fingerRefused).
  std::uint64_t refusedTicks() const { return m_refusedTicks; }
  /// Ticks with more primitives in reach than the solver's buffers hold
  /// (TickCondition::contactOverflow).
  std::uint64_t overflowTicks() const { return m_overflowTicks; }
  /// Ticks whose force was clamped to the limit (TickCondition::forceClamped).
  std::uint64_t clampedTicks() const { return m_clampedTicks; }
  /// Ticks whose force was fading (proxy stall, lost device, or back in after either).
  std::uint64_t fadingTicks() const { return m_fadingTicks; }
  /// Ticks the device reported itself disconnected (TickCondition::deviceLost).
  std::uint64_t deviceLostTicks() const { return m_deviceLostTicks; }
  /// Ticks static friction held the proxy where it began (TickCondition::stuck).
  std::uint64_t stuckTicks() const { return m_stuckTicks; }
  /// Ticks dynamic or viscous friction shortened the proxy's slide
  /// (TickCondition::frictionLimited).
  std::uint64_t frictionLimitedTicks() const { return m_frictionLimitedTicks; }
  /// Ticks whose proxy began at a start moved out of a closed object (HapticState).
  std::uint64_t startedOutsideTicks() const { return m_startedOutsideTicks; }
  /// The largest force magnitude commanded (N).
  double maxForce() const { return m_maxForce; }
  /// Quantile q in [0, 1] of the per-tick solve time in nanoseconds (nearest rank).
  double solveNanosecondsQuantile(double q) const;
  /// Triangles tested per tick, on average (0 with no ticks).
  double meanTrianglesTested() const;
  /// Ticks a moving body pushed the proxy (TickCondition::pushedByObject).
  std::uint64_t pushedTicks() const { return m_pushedTicks; }
  /// Quantile q in [0, 1] of the dynamics step's time per tick (ticks of a scene with bodies; 0
  /// without).
  double dynamicsNanosecondsQuantile(double q) const;

  /// Ticks the work budget stopped before the proxy settled (TickCondition::budgetLimited).
  std::uint64_t budgetLimitedTicks() const { return m_budgetLimitedTicks; }
  /// The distance in metres between where a budget-limited tick ended and where the same tick
  /// ends without a budget (measured by the caller, e.g. BudgetResidualProbe); one per call.
  void addBudgetResidual(double metres);
  /// How many residuals were added.
  std::uint64_t budgetResiduals() const { return m_budgetResiduals.size(); }
  /// Quantile q in [0, 1] of those residuals (nearest rank), 0 with none.
  double budgetResidualQuantile(double q) const;
  /// Recovery: each run of consecutive budget-limited ticks took as many ticks as it is long
  /// until the first tick that is not limited. recoveries() counts the runs that did recover;
  /// a run still going when the records end is unrecoveredLimitedTicks() long.
  std::uint64_t recoveries() const { return m_recoveryTicks.size(); }
  /// Length of the run of budget-limited ticks still going at the last record (0: none).
  std::uint64_t unrecoveredLimitedTicks() const { return m_limitedRun; }
  /// Quantile q in [0, 1] of the recovered runs' lengths in ticks (nearest rank), 0 with none.
  double recoveryTicksQuantile(double q) const;
  /// How many recovered runs took each number of ticks.
  std::map<std::uint64_t, std::uint64_t> recoveryHistogram() const;

private:
  std::uint64_t m_ticks = 0;
  std::uint64_t m_contactTicks = 0;
  std::uint64_t m_totalIterations = 0;
  int m_maxIterations = 0;
  std::uint64_t m_capTicks = 0;
  std::uint64_t m_refusedTicks = 0;
  std::uint64_t m_overflowTicks = 0;
  std::uint64_t m_clampedTicks = 0;
  std::uint64_t m_fadingTicks = 0;
  std::uint64_t m_deviceLostTicks = 0;
  std::uint64_t m_stuckTicks = 0;
  std::uint64_t m_frictionLimitedTicks = 0;
  std::uint64_t m_startedOutsideTicks = 0;
  std::uint64_t m_trianglesTested = 0;
  double m_maxForce = 0.0;
  std::uint64_t m_budgetLimitedTicks = 0;
  /// Length of the run of budget-limited ticks that the last record belongs to (0: not limited).
  std::uint64_t m_limitedRun = 0;
  mutable std::vector<std::uint64_t> m_recoveryTicks;
  mutable std::vector<double> m_budgetResiduals;
  mutable std::vector<std::int64_t> m_solveNanoseconds;
  mutable std::vector<std::int64_t> m_dynamicsNanoseconds;
  mutable bool m_dynamicsSorted = true;
  std::uint64_t m_pushedTicks = 0;
  mutable bool m_sorted = true;
};

} // namespace proxima
