// How far a budget-limited tick stopped from where it was going: the tick replayed from its start
// on a second solver on the same scene with no budget. For lockstep runs, outside the timed
// region, and only on the ticks the budget limited (a replay costs a whole unbudgeted tick).
#pragma once

#include "Proxy/ProxySolver.h"

namespace proxima
{

/// Measures how far a budget-limited tick stopped from where it was going, by replaying it on a
/// solver of its own with no budget. For one thread; outside timed regions.
class BudgetResidualProbe
{
public:
  /// `scene` must outlive the probe; `parameters` are the run's, whose budget the probe drops.
  BudgetResidualProbe(const CollisionScene& scene, const ProxyParameters& parameters);

  /// The distance in metres between `limitedEnd`, where a budget-limited tick that began at
  /// `start` with `finger` ended, and where the same tick ends without a budget.
  double residual(const Vec3& start, const Vec3& finger, const Vec3& limitedEnd);

private:
  ProxySolver m_solver;
};

} // namespace proxima
