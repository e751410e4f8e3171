// The knobs of the proxy solver, with the tolerance policy of Documentation/Epsilons.md.
#pragma once

namespace proxima
{

struct ProxyParameters
{
  /// Proxy sphere radius in metres.
  double radius = 0.001;
  /// Contact skin in metres: fresh contacts stop this far outside the radius. 0 picks it from
  /// the scene (resolveSkin). Must be far above rounding and far below what a hand can feel.
  double skin = 0.0;
  /// Move/update iterations allowed in one tick; hitting it is reported.
  int maxIterations = 256;
  /// The work budget of one tick (0: none). The tick stops before the move stage that would
  /// exceed it, with the proxy where it is (every move is swept, so that is always feasible);
  /// the next tick goes on from there. Iterations are deterministic; wall time is not, so a
  /// lockstep run stays reproducible bit for bit only while no tick hits a time budget.
  int tickBudgetIterations = 0;
  double tickBudgetSeconds = 0.0;
  /// Temporal coherence: keep the triangles within radius + margin of the proxy and answer the
  /// tick's queries from them while the proxy stays within half the margin. Exact either way.
  bool temporalCoherence = true;
  /// The margin in metres; 0 means one proxy radius.
  double coherenceMargin = 0.0;
  /// The servo's spring stiffness kp (N/m) and tick (s): viscous friction (paper eq. 21) turns
  /// the spring's force into a speed, and the speed into a travel per tick.
  double stiffness = 1000.0;
  double timeStep = 0.001;
};

/// The skin used for a scene whose bounding-box diagonal is `diagonal` and whose coordinates
/// reach `maxAbsCoordinate`: 4e-12 of the length scale, but never under 256 units in the last
/// place of the coordinates, so that rounding never reaches through it.
double resolveSkin(const ProxyParameters& parameters, double diagonal, double maxAbsCoordinate);

} // namespace proxima
