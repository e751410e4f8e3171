// The work budget of one proxy tick (ProxyParameters::tickBudget*), as the runtimes and the
// command line hand it around: microseconds of wall time and/or move/update iterations.
#pragma once

#include "Proxy/ProxyParameters.h"

#include <string>

namespace proxima
{

/// The budget for a proxy loop that shares a 4 kHz servo's machine: a 4 kHz servo has 250 us per
/// period and runs on its own thread (paper section 8), so a proxy tick that stops after 50 us
/// (plus the one iteration it is in) publishes a fresh proxy well within each servo period.
inline constexpr double kServoSafeTickBudgetSeconds = 50e-6;

struct TickWorkBudget
{
  /// Wall time in seconds (0: no time budget). Not deterministic: a lockstep run with a time
  /// budget is reproducible only while no tick hits it.
  double seconds = 0.0;
  /// Move/update iterations (0: no iteration budget). Deterministic.
  int iterations = 0;

  bool none() const { return !(seconds > 0.0) && iterations <= 0; }

  /// The budget of a proxy loop beside a 4 kHz servo (kServoSafeTickBudgetSeconds).
  static TickWorkBudget servoSafe() { return TickWorkBudget{kServoSafeTickBudgetSeconds, 0}; }

  /// Sets the solver's budget fields to this budget.
  void applyTo(ProxyParameters& parameters) const
  {
    parameters.tickBudgetSeconds = seconds > 0.0 ? seconds : 0.0;
    parameters.tickBudgetIterations = iterations > 0 ? iterations : 0;
  }

  /// The command line's spelling: "none", "50us", "40it" or "50us,40it".
  std::string text() const;
};

/// The largest --tick-budget terms taken: a proxy tick of more than a second, or of more than a
/// million iterations, is a typo, not a budget.
inline constexpr double kMaxTickBudgetMicroseconds = 1e6;
inline constexpr long kMaxTickBudgetIterations = 1000000;

/// Parses a --tick-budget value: `none`, or one or two comma-separated terms `<N>us` (microseconds
/// of wall time, N > 0, fractions allowed) and `<N>it` (move/update iterations, a whole N > 0),
/// each at most once: `50us`, `40it`, `50us,40it`. Returns why `text` is refused, empty when it
/// is taken (and `budget` holds it).
std::string parseTickBudget(const std::string& text, TickWorkBudget& budget);

} // namespace proxima
