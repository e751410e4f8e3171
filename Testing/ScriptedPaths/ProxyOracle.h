// The oracle of the proxy tests (DESIGN.md section 4), written apart from the solver and from
// the SphereTree so that a test never checks the kernel against itself:
// - candidate triangles come from CGAL's AABB tree over the triangles' bounding boxes (a box is
//   never wrong about a triangle, degenerate or not), and every distance is then computed in
//   128-bit floating point in the frame of the query point, where differences and products of
//   the doubles are (nearly) exact: slivers, zero-area triangles and a 1 km coordinate offset
//   cost no accuracy;
// - crossings are CGAL's exact predicates (Epick) on the input doubles;
// - the cone projection of the local-minimum check is CGAL's quadratic-program solver in exact
//   arithmetic (Gmpzf), not the dual-space Gilbert solve of the kernel.
// Used by the ProxySolver unit tests (Library/Proxy/Testing) and the scripted-path suites.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/MoveRecord.h"
#include "Proxy/ProxyParameters.h"
#include "Proxy/ProxySolver.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace proxima::oracle
{

/// A double printed with 17 significant digits, so that a message reproduces the input exactly.
std::string str(double value);
std::string str(const Vec3& v);

/// The exact solution of min |x - v| subject to n_i . x >= 0 (i < count), rounded to double: the
/// feasible step nearest the finger when the proxy is at the origin of the constraint planes.
/// Normals need not be unit. Solved by CGAL's QP solver with exact Gmpzf arithmetic.
Vec3 projectOntoCone(const Vec3& v, const Vec3* normals, int count);

/// The triangles of a scene with a search structure of its own, and exact-enough distances.
class MeshOracle
{
public:
  struct Near
  {
    std::uint32_t triangle = 0;
    Vec3 closest;
    /// The query point minus the closest point, computed in 128 bits (exact direction).
    Vec3 away;
    double distance = 0.0;
  };

  explicit MeshOracle(std::vector<TriangleCorners> triangles);
  /// Over every triangle of `mesh` as it is now (a moved or deformed copy, say).
  explicit MeshOracle(const TriangleMesh& mesh);
  /// All triangles of all objects of `scene`.
  explicit MeshOracle(const CollisionScene& scene);
  ~MeshOracle();
  MeshOracle(const MeshOracle&) = delete;
  MeshOracle& operator=(const MeshOracle&) = delete;

  std::size_t numTriangles() const;
  /// Bounding box of all triangles.
  Aabb bounds() const;
  /// Bounding-box diagonal of all triangles: the scene's length scale.
  double diagonal() const;

  /// Distance from `p` to the nearest triangle if one is within `cap`, else `cap` (+inf: all).
  double distance(const Vec3& p, double cap = std::numeric_limits<double>::infinity()) const;
  /// Distance from segment [a, b] to the nearest triangle if one is within `cap`, else `cap`.
  double segmentDistance(const Vec3& a, const Vec3& b,
                         double cap = std::numeric_limits<double>::infinity()) const;
  /// True if every triangle is at least `reach` from segment [a, b] (stops at the first that is
  /// not).
  bool segmentClearOf(const Vec3& a, const Vec3& b, double reach) const;
  /// Whether segment [a, b] touches any triangle (exact predicates; touching counts).
  bool segmentTouchesAny(const Vec3& a, const Vec3& b) const;
  /// Every triangle within `radius` of `p`, with its closest point and distance.
  std::vector<Near> within(const Vec3& p, double radius) const;

  /// Exact-enough single-triangle queries (128-bit arithmetic in the frame of the query).
  static double pointTriangleDistance(const Vec3& p, const TriangleCorners& t,
                                      Vec3* closest = nullptr, Vec3* away = nullptr);
  static double segmentTriangleDistance(const Vec3& a, const Vec3& b, const TriangleCorners& t);
  static bool segmentTouchesTriangle(const Vec3& a, const Vec3& b, const TriangleCorners& t);

private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/// Tolerances of DESIGN.md section 4 for a scene; never loosen these to make a test pass.
struct OracleSettings
{
  /// Penetration allowance: max(1e-9 m, 1e-9 x the scene diagonal).
  double penetrationTolerance = 1e-9;
  /// A feasible step along the contact planes may bring the proxy at most this much nearer.
  double residualTolerance = 1e-9;
  /// In contact, the proxy is at most this far beyond radius from the surface.
  double gapTolerance = 1e-9;
  /// Where the path proxy -> finger is free, the proxy is at the finger to this distance.
  double freePathTolerance = 1e-9;
  /// Constraint planes of the residual check: triangles within radius + this of the proxy.
  double gatherTolerance = 1e-9;
  /// A path counts as free when it stays this far beyond radius from every triangle (a few skins:
  /// the solver's contact reach is 2 skins).
  double freePathMargin = 0.0;
  /// Every tick is checked where it ended, capped or not (section 4 holds at the default cap). A
  /// tick that hit the cap is also replayed with this cap, to tell slow convergence (reported:
  /// iterations needed, distance from the capped end) from a loop that never terminates
  /// (a failure).
  int uncappedIterations = 20000;
  /// Budgeted ticks (issue 31): once the finger rests (the same position tick after tick), a run
  /// must stop being budget-limited within this many ticks, reaching the local minimum that every
  /// unlimited tick is checked against. A budget-limited tick later than this into a rest fails.
  int maxRestingLimitedTicks = 20;

  static OracleSettings forScene(double diagonal, double skin);
};

/// The worst margins seen over a run, and the violations (the first few with a reproducer).
struct InvariantStats
{
  std::uint64_t ticks = 0;
  std::uint64_t contactTicks = 0;
  std::uint64_t refusedTicks = 0;
  std::uint64_t capTicks = 0;
  /// Ticks the work budget stopped early: checked for (a), (b), (e)-(g) like any tick, but not
  /// for (c) and (d), which are about where a tick settles (the next ticks go on from there).
  std::uint64_t budgetLimitedTicks = 0;
  std::uint64_t overflowTicks = 0;
  std::uint64_t moveSegments = 0;
  std::uint64_t freePathChecks = 0;
  std::uint64_t residualChecks = 0;
  int maxIterations = 0;
  /// min over ticks of distance(proxy, mesh) - radius (a: no penetration).
  double minClearance = std::numeric_limits<double>::infinity();
  /// min over move segments of distance(segment, mesh) - radius (b: no tunnelling).
  double minSweepClearance = std::numeric_limits<double>::infinity();
  /// max over ticks of the local-minimum residual (d).
  double maxResidual = 0.0;
  /// max over ticks of |x*|, the length of the best feasible step the oracle finds: how far the
  /// proxy could still slide (reported; (d) bounds the distance that step gains, not its length).
  double maxSlide = 0.0;
  /// max iterations the capped ticks needed to converge when replayed without the cap, and how
  /// far from the capped end they converged.
  int maxUncappedIterations = 0;
  double maxCapLag = 0.0;
  /// max over contact ticks of distance - radius (f).
  double maxGap = -std::numeric_limits<double>::infinity();
  /// max |proxy - finger| over ticks whose path proxy -> finger was free (c).
  double maxFreePathError = 0.0;
  /// max distance between a tick's end and the same tick replayed by a fresh (cold) solver.
  double maxReplayDiscrepancy = 0.0;
  /// max relative force error (e), filled by the runtime harness.
  double maxForceError = 0.0;

  std::uint64_t penetrations = 0;
  std::uint64_t crossings = 0;
  std::uint64_t tunnels = 0;
  std::uint64_t freePathFailures = 0;
  std::uint64_t residualFailures = 0;
  std::uint64_t gapFailures = 0;
  std::uint64_t forceFailures = 0;
  /// A trace that is not every tick of its path at the run's rate (ticks, times or fingers).
  std::uint64_t coverageFailures = 0;
  std::uint64_t refusalFailures = 0;
  std::uint64_t replayFailures = 0;
  /// A move stage that carried the proxy farther from the finger: each goal is the feasible point
  /// nearest the finger, so along the move the distance can only shrink (eq. 2).
  std::uint64_t approachFailures = 0;
  /// Ticks whose move/update loop never stops (still moving after uncappedIterations).
  std::uint64_t nonTerminating = 0;
  /// Budget-limited ticks more than maxRestingLimitedTicks into a rest of the finger.
  std::uint64_t settleFailures = 0;
  /// The most ticks into a rest of the finger that a tick was still budget-limited.
  std::uint64_t maxRestingLimitedTick = 0;
  std::vector<std::string> messages;
  /// Reproducers of the first few capped ticks that do converge (information).
  std::vector<std::string> notes;

  std::uint64_t failures() const
  {
    return penetrations + crossings + tunnels + freePathFailures + residualFailures + gapFailures +
           forceFailures + coverageFailures + refusalFailures + replayFailures + approachFailures +
           nonTerminating + settleFailures;
  }
  void fail(std::uint64_t& counter, const std::string& message);
  /// One line per measure, for the test output.
  std::string summary(const std::string& name) const;
};

/// One tick's force as the servo commanded it (ServoForce), with what it is made from.
struct ForceTick
{
  Vec3 proxy;
  Vec3 finger;
  Vec3 force;
  /// The force of the tick before (zero before the first).
  Vec3 previousForce;
  bool refused = false;
  bool clamped = false;
  /// The servo ramped the force (rate limit after a start outside or a scene change, or a fade):
  /// it is then bounded by the clamp but is not the spring's.
  bool ramped = false;
  /// False where a surface material may scale kp at the contact (a stiffness other than 1, a
  /// stiffness map or region) and the trace does not say by how much: in contact only the
  /// direction and the clamp are checked.
  bool knownStiffness = true;
  bool inContact = false;
};

/// (e) Force: kp (proxy - finger), computed in long double, clamped to `maxForce` (and flagged
/// clamped exactly when it is); a refused finger holds the previous force, bit for bit; a ramped
/// force stays within the clamp. Counts into stats.forceFailures.
void checkServoForce(InvariantStats& stats, const std::string& where, const ForceTick& tick,
                     double stiffness, double maxForce);

/// Checks every tick of a proxy run against the oracle. The chain of segments a tick moved along
/// is recovered by replaying it once from the previous proxy with the solver's move record on
/// (ProxySolver::recordMoves) and the iteration cap at the live tick's count: the solver is
/// deterministic, so the replay makes the same moves and stops where the live tick stopped.
class TickChecker
{
public:
  TickChecker(const MeshOracle& oracle, const CollisionScene& scene,
              const ProxyParameters& parameters, const OracleSettings& settings);

  /// The proxy position before the first tick.
  void reset(const Vec3& proxy);

  /// One tick: `finger` as given to update(), `result` as it returned.
  void check(std::uint64_t tick, const Vec3& finger, const ProxyTickResult& result);
  /// The same from what a trace row holds.
  void check(std::uint64_t tick, const Vec3& finger, const Vec3& proxy, int iterations,
             int contacts, bool refused, bool hitCap, bool overflow, bool budgetLimited = false);

  const Vec3& proxy() const { return m_proxy; }
  InvariantStats& stats() { return m_stats; }
  const InvariantStats& stats() const { return m_stats; }
  const OracleSettings& settings() const { return m_settings; }

  /// Residual of the local-minimum check at `proxy` for `finger` (|v| - |v - x*|); `slide`
  /// receives |x*|.
  double residual(const Vec3& proxy, const Vec3& finger, double* slide = nullptr) const;

private:
  /// The point the solver seeks for `finger`: the finger, or where the ray to it leaves the
  /// solver's documented reach (ProxySolver::reachRadius).
  Vec3 sought(const Vec3& finger) const;
  /// (c) and (d) at the end of a tick.
  void checkEnd(const std::string& where, const Vec3& proxy, const Vec3& finger, int iterations);

  const MeshOracle& m_oracle;
  const CollisionScene& m_scene;
  ProxyParameters m_parameters;
  OracleSettings m_settings;
  std::unique_ptr<ProxySolver> m_replay;
  /// More points than any tick records: the uncapped replay's 20,000 moves, with their retraces.
  static constexpr std::size_t kMaxRecordedPoints = 65536;
  std::unique_ptr<MoveRecord> m_moveRecord;
  Vec3 m_proxy;
  /// The finger of the previous tick, and how many ticks in a row it has not moved.
  Vec3 m_restingFinger;
  std::uint64_t m_restingTicks = 0;
  bool m_hasRestingFinger = false;
  InvariantStats m_stats;
};

} // namespace proxima::oracle
