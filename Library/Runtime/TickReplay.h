// A proxy tick's work without the platform's stalls (DESIGN.md section 5): the minimum wall time
// over repeats of the same update from the same solver state. On a shared VM a thread is stalled
// for 30-200 us many times a second, so one run of a tick measures the scheduler as much as the
// solver; a stall hits one tick in about 80, and rarely all repeats of one. For benchmarks and
// lockstep reports, outside the timed region of the run itself: each repeat copies the solver.
#pragma once

#include "Proxy/ProxySolver.h"

#include <cstdint>

namespace proxima
{

/// Replays a proxy tick from a remembered solver state, to time its work without the platform's
/// stalls or to find where it settles without a budget. For one thread, outside timed regions:
/// each replay copies the whole solver.
class TickReplay
{
public:
  /// Repeats per tick: five, as the benchmarks report.
  static constexpr int kDefaultRepeats = 5;

  /// A replayer that times `repeats` updates per tick (below 1 is taken as 1).
  explicit TickReplay(int repeats = kDefaultRepeats)
    : m_repeats(repeats > 0 ? repeats : 1)
  {}

  /// Updates timed per tick, at least 1.
  int repeats() const { return m_repeats; }

  /// Remembers `solver`'s state before its next update (a copy of it: ProxySolver's copy is a
  /// replica). Call before each tick that is to be replayed.
  void remember(const ProxySolver& solver) { m_start = solver; }

  /// Whether the remembered solver can be replayed exactly: a scene with moving or deforming
  /// objects shares its moved meshes with every copy, so replaying a tick would move them again.
  bool replayable() const { return !m_start.hasMovingObjects() && !m_start.hasDeformingObjects(); }

  /// The least wall time in nanoseconds over repeats() updates toward `finger`, each from the
  /// remembered state; -1 when the state is not replayable.
  std::int64_t workNanoseconds(const Vec3& finger);

  /// The remembered tick run again without a work budget: where a budget-limited tick would have
  /// settled. The same start, caches and all, so it differs from the budgeted tick only in work.
  ProxyTickResult settledWithoutBudget(const Vec3& finger);

  /// The result of the last replay (workNanoseconds), to check that a replay is the tick itself.
  const ProxyTickResult& lastReplay() const { return m_lastReplay; }

private:
  int m_repeats;
  ProxySolver m_start;
  ProxySolver m_replica;
  ProxyTickResult m_lastReplay;
};

} // namespace proxima
