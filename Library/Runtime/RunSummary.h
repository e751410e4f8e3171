// Statistics of a run, gathered tick by tick: what `proxima run --summary` reports.
#pragma once

#include "Runtime/ServoTick.h"

#include <cstdint>
#include <vector>

namespace proxima
{

class RunSummary
{
public:
  void add(const TickRecord& record);

  std::uint64_t ticks() const { return m_ticks; }
  std::uint64_t contactTicks() const { return m_contactTicks; }
  std::uint64_t totalIterations() const { return m_totalIterations; }
  int maxIterations() const { return m_maxIterations; }
  std::uint64_t iterationCapTicks() const { return m_capTicks; }
  std::uint64_t refusedTicks() const { return m_refusedTicks; }
  std::uint64_t overflowTicks() const { return m_overflowTicks; }
  std::uint64_t clampedTicks() const { return m_clampedTicks; }
  /// Ticks whose force was fading (proxy stall, lost device, or back in after either), and ticks
  /// with the device lost.
  std::uint64_t fadingTicks() const { return m_fadingTicks; }
  std::uint64_t deviceLostTicks() const { return m_deviceLostTicks; }
  std::uint64_t stuckTicks() const { return m_stuckTicks; }
  std::uint64_t frictionLimitedTicks() const { return m_frictionLimitedTicks; }
  double maxForce() const { return m_maxForce; }
  /// Quantile q in [0, 1] of the per-tick solve time in nanoseconds (nearest rank).
  double solveNanosecondsQuantile(double q) const;
  double meanTrianglesTested() const;

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
  std::uint64_t m_trianglesTested = 0;
  double m_maxForce = 0.0;
  mutable std::vector<std::int64_t> m_solveNanoseconds;
  mutable bool m_sorted = true;
};

} // namespace proxima
