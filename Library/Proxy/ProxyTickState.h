// The state of one ProxySolver::update, each part owned by the rule that needs it: the tick's
// work budget, force shading's target, friction's viscous travel, the curvature stretch's trust
// region, and the stop rules of the move/update loop. Used only inside ProxySolver.cpp; fixed
// size, no allocation.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/GoalSolver.h"
#include "Proxy/ProxyParameters.h"

#include <algorithm>
#include <chrono>

namespace proxima
{

/// Update stages in a tick that re-shade the target (ShadedTarget).
inline constexpr int kMaxShadedIterations = 8;

/// The largest factor the curvature correction stretches a slide by. Beyond it (a finger at the
/// axis of an edge's cylinder, where the potential is flat around the edge) it does not stretch.
inline constexpr double kMaxCurvatureStretch = 64.0;

/// Moves in a row that bring the proxy no nearer the target before the tick ends: the paper's
/// loop only ever decreases that distance, so a proxy that stops getting nearer is done (or is
/// trading rounding errors between two planes, as 1 km from the origin).
inline constexpr int kMaxStalledIterations = 3;

/// Stop rule: the work budget of one tick, iterations and wall time on the steady clock (read
/// only when a time budget is set: a scene without one pays nothing for it).
class TickBudget
{
public:
  /// The budget of `parameters`; a time budget's deadline runs from now.
  explicit TickBudget(const ProxyParameters& parameters)
    : m_iterations(parameters.tickBudgetIterations)
    , m_timed(parameters.tickBudgetSeconds > 0.0)
  {
    if (m_timed)
    {
      m_deadline = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(parameters.tickBudgetSeconds));
    }
  }

  /// True once `iterations` move stages have used the budget up.
  bool spent(int iterations) const
  {
    if (m_iterations > 0 && iterations >= m_iterations)
    {
      return true;
    }
    return m_timed && iterations > 0 && std::chrono::steady_clock::now() >= m_deadline;
  }

  /// True once half an iteration budget is used: the rest is for plain slides, which never end
  /// farther from the finger, so a budget-limited tick ends nearer than it began or settles. Were
  /// stretched slides (trials, TrialChain) allowed to the end, a tick whose trials were still
  /// pending when the budget ran out walked back to where it began, and with the finger at rest
  /// every later tick did the same: on the shared bunny at r = 2 mm (probe seed 3) 253 ticks in a
  /// row were limited at 16 iterations, where one unbudgeted tick of 49 settles. By iterations
  /// only, so that a tick is a function of where it starts and the finger (a replay from the same
  /// start ends where the tick did); never true without an iteration budget.
  bool secondHalf(int iterations) const
  {
    return m_iterations > 0 && 2 * iterations >= m_iterations;
  }

private:
  int m_iterations = 0;
  bool m_timed = false;
  std::chrono::steady_clock::time_point m_deadline;
};

/// Force shading (paper section 3) in one tick: the target the plain loop seeks, the finger on a
/// plain surface and the shaded subgoal on a shaded one. Each update stage's first pass moves it
/// until it moves by less than the accuracy scale, or for kMaxShadedIterations stages:
/// re-shading after every move can chase a shaded normal that turns as the proxy slides (near a
/// sharp edge of a CAD part, 229 of 5002 ticks on fandisk ran to the cap), while the plain loop
/// toward a fixed target always settles.
class ShadedTarget
{
public:
  /// A target that starts at the finger.
  explicit ShadedTarget(const Vec3& finger)
    : m_target(finger)
  {}

  /// The point the loop seeks now: the finger, or the last shaded subgoal taken.
  const Vec3& target() const { return m_target; }
  /// A shaded plane took part in an update stage this tick.
  bool used() const { return m_used; }
  /// Whether the target may still move after `iterations` move stages, with shaded planes at
  /// the proxy (`anyShaded`).
  bool moving(bool anyShaded, int iterations) const
  {
    return anyShaded && !m_settled && iterations < kMaxShadedIterations;
  }
  /// Takes this update stage's shaded subgoal; settled once it moved by at most `tolerance`.
  void reshade(const Vec3& subgoal, double tolerance)
  {
    m_settled = m_used && distance(subgoal, m_target) <= tolerance;
    m_target = subgoal;
    m_used = true;
  }

private:
  Vec3 m_target;
  bool m_settled = false;
  bool m_used = false;
};

/// Viscous friction (paper 4.2, eq. 21) in one tick: the travel the proxy has left, set by the
/// tick's first viscous contact (ProxySolver::frictionLimitedTravel) and spent by every move.
struct ViscousTravel
{
  /// Travel the proxy has left this tick (m); negative until the first viscous contact sets it.
  double budget = -1.0;

  /// Takes the length of the move from `from` to `to` off a set budget, down to 0 at least.
  void spend(const Vec3& from, const Vec3& to)
  {
    if (budget > 0.0)
    {
      budget = std::max(0.0, budget - distance(to, from));
    }
  }
};

/// The curvature stretch's trust region in one tick (ProxySolver::curvatureCorrectedStep). A
/// stretched slide is a Newton step: it must pay off with the move after it, or the tick goes on
/// with plain slides (a trust region shrunk to the paper's planar steps). A crease's stretch is
/// capped by a limit that shrinks eightfold at each stretch that did not pay off: where the
/// curvature along a crease vanishes the cap is the step, and one bad guess should not leave the
/// rest of the tick to creep.
class StretchTrustRegion
{
public:
  /// Whether slides may still be stretched this tick.
  bool allowed() const { return m_allowed; }
  /// No more stretches this tick (after a retrace: the trials led nowhere nearer).
  void forbid() { m_allowed = false; }
  /// The cap on a crease's stretch (stretchedCreaseSlide).
  double creaseLimit() const { return m_creaseLimit; }

  /// A stretched slide with `numActive` active planes was just moved along, from
  /// `distanceBefore` from the target: the next unstretched move judges it.
  void awaitPayoff(int numActive, double distanceBefore)
  {
    m_onCrease = numActive == 2;
    m_distanceBefore = distanceBefore;
  }

  /// After an unstretched move that ended `toTarget` from the target: a stretch that ended no
  /// nearer than it began (by `stepTolerance`) stops stretching, or on a crease stretches less.
  void judgePayoff(double toTarget, double stepTolerance)
  {
    if (m_distanceBefore >= 0.0 && !(toTarget < m_distanceBefore - stepTolerance))
    {
      if (m_onCrease)
      {
        m_creaseLimit /= 8.0;
      }
      else
      {
        m_allowed = false;
      }
    }
    m_distanceBefore = -1.0;
  }

private:
  bool m_allowed = true;
  double m_creaseLimit = kMaxCurvatureStretch;
  bool m_onCrease = false;
  double m_distanceBefore = -1.0; // negative: no stretch awaits its payoff
};

/// The most moves a tick makes in a row farther from the target than its last accepted point
/// (TrialChain): a retrace walks back over at most this many points.
inline constexpr int kMaxTrialChain = 32;

/// The tick's approach to the finger, kept exact in spite of the curvature stretch. A stretched
/// slide overshoots along the tangent plane so that the next move falls onto the curved surface,
/// and may end farther from the target than it began; the moves after it usually win that back.
/// So a move that ends no farther from the target than the last accepted point is accepted, and
/// one that ends farther is a trial. If the tick would stop with trials pending, or makes
/// kMaxTrialChain of them in a row, the proxy walks back along the trials' segments, which were
/// swept clear, to the accepted point (a retrace) and goes on without stretching: a tick never
/// ends farther from the finger than it began, and its accepted points approach it monotonically.
class TrialChain
{
public:
  /// A chain whose accepted point is the tick's start, `distanceToTarget` from the target.
  TrialChain(const Vec3& start, double distanceToTarget)
    : m_accepted(start)
    , m_acceptedDistance(distanceToTarget)
  {}

  /// True when trials were made since the accepted point.
  bool pending() const { return m_numTrials > 0; }
  /// True when kMaxTrialChain trials were made in a row: the proxy must retrace.
  bool full() const { return m_numTrials == kMaxTrialChain; }
  /// The last accepted point.
  const Vec3& accepted() const { return m_accepted; }
  /// Distance from the accepted point to the target (m).
  double acceptedDistance() const { return m_acceptedDistance; }
  /// Trials made since the accepted point, 0 to kMaxTrialChain.
  int numTrials() const { return m_numTrials; }
  /// The k-th trial end since the accepted point (0: the first).
  const Vec3& trial(int k) const { return m_trials[k]; }

  /// A move ended at `end`, farther than the accepted point.
  void addTrial(const Vec3& end) { m_trials[m_numTrials++] = end; }
  /// The proxy is at `position`, no farther from the target than the accepted point (within a
  /// skin's rounding): it becomes the accepted point, `distanceToTarget` away.
  void accept(const Vec3& position, double distanceToTarget)
  {
    m_accepted = position;
    m_acceptedDistance = distanceToTarget;
    m_numTrials = 0;
  }
  /// The proxy walked back to the accepted point.
  void retraced() { m_numTrials = 0; }

private:
  Vec3 m_accepted;
  double m_acceptedDistance = 0.0;
  Vec3 m_trials[kMaxTrialChain];
  int m_numTrials = 0;
};

/// Stop rule: the last move was blocked at once (the proxy did not move) and the next goal is
/// the same: repeating it cannot help.
class RepeatedBlockedMove
{
public:
  /// A rule with no blocked move yet, and the proxy's start as the previous goal.
  explicit RepeatedBlockedMove(const Vec3& proxy)
    : m_previousGoal(proxy)
  {}

  /// True when the last move was blocked at once and `goal` is exactly the goal it had.
  bool repeats(const Vec3& goal) const { return m_blockedAtOnce && goal == m_previousGoal; }
  /// The proxy was put back where it had been (a retrace): no move was blocked there.
  void forget() { m_blockedAtOnce = false; }
  /// Records a move toward `goal` that took the proxy from `before` to `after` (blocked at once
  /// when they are equal).
  void moved(const Vec3& goal, const Vec3& before, const Vec3& after)
  {
    m_blockedAtOnce = after == before;
    m_previousGoal = goal;
  }

private:
  Vec3 m_previousGoal;
  bool m_blockedAtOnce = false;
};

/// Stop rule: kMaxStalledIterations unstretched moves in a row that bring the proxy no nearer
/// the target: rounding traded between planes, not progress.
class NoProgress
{
public:
  /// Counts one move; true when it is the kMaxStalledIterations-th in a row without progress.
  bool stalls(bool progressed)
  {
    if (progressed)
    {
      m_stalled = 0;
      return false;
    }
    return ++m_stalled == kMaxStalledIterations;
  }

private:
  int m_stalled = 0;
};

/// Everything one tick carries from one iteration of the move/update loop to the next.
struct ProxyTickState
{
  /// The state at the start of a tick: the proxy at `proxy`, the finger already brought within
  /// reach, and the solver's resolved `skin` (m).
  ProxyTickState(const ProxyParameters& parameters, const Vec3& fingerInReach, const Vec3& proxy,
                 double skin)
    : budget(parameters)
    , finger(fingerInReach)
    , start(proxy)
    , stepTolerance(0.01 * skin)
    , shading(fingerInReach)
    , trials(proxy, norm(fingerInReach - proxy))
    , blocked(proxy)
  {}

  /// The tick's work budget (stop rule).
  const TickBudget budget;
  /// The finger, brought within ProxySolver::reachRadius().
  const Vec3 finger;
  /// The proxy where the tick began.
  const Vec3 start;
  /// Steps shorter than this are rounding noise of the goal solve, not motion: 1% of the skin.
  const double stepTolerance;
  /// The last update stage's goal (what the tick reports its contacts from).
  GoalSolution solution;
  /// Force shading's target.
  ShadedTarget shading;
  /// Viscous friction's travel left.
  ViscousTravel viscous;
  /// The curvature stretch's trust region.
  StretchTrustRegion stretch;
  /// The accepted point and the trials since it.
  TrialChain trials;
  /// Stop rule: a blocked move about to repeat.
  RepeatedBlockedMove blocked;
  /// Stop rule: moves in a row without progress.
  NoProgress progress;
};

} // namespace proxima
