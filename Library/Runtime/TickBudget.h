// The work budget of one proxy tick (ProxyParameters::tickBudget*), as the runtimes and the
// command line hand it around: microseconds of wall time and/or move/update iterations.
#pragma once

#include "Proxy/ProxyParameters.h"

#include <string>

namespace proxima
{

/// The real-time default (`--tick-budget default`): deterministic first, so that a lockstep run
/// given it budgets every tick as the real-time loop does, bit for bit on any machine. Chosen
/// from the run time against error of the budget sweep (Documentation/Performance.md): on
/// person-like probing of real meshes the proxy settles within this many move/update iterations
/// on all but a small share of ticks, and a limited tick recovers within a few ticks.
inline constexpr int kDefaultTickBudgetIterations = 16;

/// The threaded runtime's safety cap beside the default's iterations: wall time, so it is not
/// deterministic, and set above what the default's iterations take (a few tens of microseconds)
/// so that only a tick the platform stalled, or a pathological mesh, meets it. A 4 kHz servo has
/// 250 us per period and runs on its own thread (paper section 8).
inline constexpr double kTickSafetyCapSeconds = 200e-6;

/// The work budget of one proxy tick: wall time, iterations or both, whichever ends the tick
/// first, and the threaded runtime's safety cap.
struct TickWorkBudget
{
  /// Wall time in seconds (0: no time budget). Not deterministic: a lockstep run with a time
  /// budget is reproducible only while no tick hits it.
  double seconds = 0.0;
  /// Move/update iterations (0: no iteration budget). Deterministic.
  int iterations = 0;
  /// A wall-time cap that only the threaded runtime applies (applyToRealTime), beside a
  /// deterministic budget; lockstep ignores it (0: none).
  double safetyCapSeconds = 0.0;

  /// True when neither a time nor an iteration budget is set (the safety cap aside).
  bool none() const { return !(seconds > 0.0) && iterations <= 0; }

  /// The real-time default: kDefaultTickBudgetIterations, with kTickSafetyCapSeconds in real time.
  static TickWorkBudget realtimeDefault()
  {
    return TickWorkBudget{0.0, kDefaultTickBudgetIterations, kTickSafetyCapSeconds};
  }
  /// True when every field equals realtimeDefault()'s (text() then spells it "default").
  bool isRealtimeDefault() const
  {
    const TickWorkBudget byDefault = realtimeDefault();
    return seconds == byDefault.seconds && iterations == byDefault.iterations &&
           safetyCapSeconds == byDefault.safetyCapSeconds;
  }

  /// Sets the solver's budget fields to this budget, as a lockstep run uses it (no safety cap).
  void applyTo(ProxyParameters& parameters) const
  {
    parameters.tickBudgetSeconds = seconds > 0.0 ? seconds : 0.0;
    parameters.tickBudgetIterations = iterations > 0 ? iterations : 0;
  }

  /// The same for the threaded runtime on the real clock: the safety cap where no time budget
  /// is given.
  void applyToRealTime(ProxyParameters& parameters) const
  {
    applyTo(parameters);
    if (!(seconds > 0.0) && safetyCapSeconds > 0.0)
    {
      parameters.tickBudgetSeconds = safetyCapSeconds;
    }
  }

  /// The command line's spelling: "none", "default", "50us", "40it" or "50us,40it".
  std::string text() const;
};

/// The largest --tick-budget terms taken: a proxy tick of more than a second, or of more than a
/// million iterations, is a typo, not a budget.
inline constexpr double kMaxTickBudgetMicroseconds = 1e6;
/// The largest --tick-budget iteration count taken (see kMaxTickBudgetMicroseconds).
inline constexpr long kMaxTickBudgetIterations = 1000000;

/// Parses a --tick-budget value: `none`, `default` (TickWorkBudget::realtimeDefault), or one or
/// two comma-separated terms `<N>us` (microseconds
/// of wall time, N > 0, fractions allowed) and `<N>it` (move/update iterations, a whole N > 0),
/// each at most once: `50us`, `40it`, `50us,40it`. Returns why `text` is refused, empty when it
/// is taken (and `budget` holds it).
std::string parseTickBudget(const std::string& text, TickWorkBudget& budget);

} // namespace proxima
