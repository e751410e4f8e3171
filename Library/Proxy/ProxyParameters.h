// The knobs of the proxy solver, with the tolerance policy of Documentation/Epsilons.md.
#pragma once

namespace proxima
{

/// What a ProxySolver is configured with: the proxy's size and skin, the loop's limits, temporal
/// coherence and the servo constants friction uses. SI units throughout.
struct ProxyParameters
{
  /// Proxy sphere radius in metres.
  double radius = 0.001;
  /// Contact skin in metres: fresh contacts stop this far outside the radius. 0 picks it from
  /// the scene (resolveSkin). Must be far above rounding and far below what a hand can feel.
  double skin = 0.0;
  /// Move/update iterations allowed in one tick; hitting it is reported.
  int maxIterations = 256;
  /// The work budget of one tick in move stages (0: none). The tick stops before the move stage
  /// that would exceed it, with the proxy where it is (every move is swept, so that is always
  /// feasible); the next tick goes on from there. Iterations are deterministic; wall time is not,
  /// so a lockstep run stays reproducible bit for bit only while no tick hits a time budget.
  int tickBudgetIterations = 0;
  /// The work budget of one tick in wall-clock seconds on the steady clock (0: none), checked as
  /// the iteration budget is; a tick always makes its first move stage.
  double tickBudgetSeconds = 0.0;
  /// Temporal coherence: keep the triangles within radius + margin of the proxy and answer the
  /// tick's queries from them while the proxy stays within half the margin. Exact either way.
  bool temporalCoherence = true;
  /// The margin in metres; 0 means one proxy radius.
  double coherenceMargin = 0.0;
  /// The servo's spring stiffness kp (N/m) and tick (s): viscous friction (paper eq. 21) turns
  /// the spring's force into a speed, and the speed into a travel per tick.
  double stiffness = 1000.0;
  /// The servo's tick (s), over which viscous friction's speed becomes a travel.
  double timeStep = 0.001;
};

/// The skin used for a scene whose bounding-box diagonal is `diagonal` and whose coordinates
/// reach `maxAbsCoordinate`: 4e-12 of the length scale, but never under 256 units in the last
/// place of the coordinates, so that rounding never reaches through it.
double resolveSkin(const ProxyParameters& parameters, double diagonal, double maxAbsCoordinate);

} // namespace proxima
