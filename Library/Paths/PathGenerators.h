// Finger paths for tests and demos, sampled at a fixed rate. Each generator is parameterised in
// SI units; makeDefaultPath picks parameters from a mesh's bounding box so that any mesh gets a
// sensible path of each kind.
#pragma once

#include "Core/Aabb.h"
#include "Geometry/SphereTree.h"
#include "Geometry/TriangleMesh.h"
#include "Runtime/FingerPath.h"

#include <cstdint>
#include <string>
#include <vector>

namespace proxima
{

/// Straight line from `from` to `to` at constant speed over `duration` seconds.
FingerPath makeSlidePath(const Vec3& from, const Vec3& to, double duration, double rate);

/// A press into a surface and a straight stroke along it: in from `approachHeight` outside the
/// surface point to `depth` past it, the stroke, then out to `approachHeight` outside the surface
/// again. Lengths in metres, world frame.
struct PressAndStroke
{
  /// A point on (or near) the surface.
  Vec3 surfacePoint;
  /// The direction from the surface point into the object (normalised by the generator).
  Vec3 inward{0, 0, -1};
  /// Start this far outside the surface point (m).
  double approachHeight = 0.01;
  /// Press this deep past the surface point (m).
  double depth = 0.003;
  /// Stroke along this direction (made tangent to `inward`) for `strokeLength`, then lift.
  Vec3 strokeDirection{1, 0, 0};
  /// Length of the stroke (m).
  double strokeLength = 0.02;
  double speed = 0.05; ///< Metres per second along the whole path.
};
/// The path `p` describes, sampled at `rate` rows per second from time 0.
FingerPath makePressAndStrokePath(const PressAndStroke& p, double rate);

/// The paper's Figure 6 path: `revolutions` turns of a circle of `radius` about `axis` through
/// `center`, counter-clockwise seen from the axis' tip, starting at center + radius * startDir.
FingerPath makeCirclePath(const Vec3& center, const Vec3& axis, const Vec3& startDir, double radius,
                          double revolutions, double duration, double rate);

/// Straight strikes at one point from several directions: each jab holds at `standoff` from the
/// target for `pause`, drives in to `overshoot` past it and comes back out. Lengths in metres.
struct Jabs
{
  /// The point struck (m, world frame).
  Vec3 target;
  /// Directions from which the finger strikes (each normalised); one jab per direction.
  std::vector<Vec3> fromDirections;
  /// The finger starts this far from the target (m).
  double standoff = 0.02;
  /// The finger drives this far past the target (m).
  double overshoot = 0.005;
  double speed = 10.0; ///< Speed in and out (m/s): a hard strike.
  double pause = 0.01; ///< Seconds held at the standoff before each jab.
};
/// The jabs of `jabs`, one after the other, sampled at `rate` rows per second from time 0.
FingerPath makeJabPath(const Jabs& jabs, double rate);

/// Concatenates paths, shifting times so each starts one sample after the previous one ends.
FingerPath concatenatePaths(const std::vector<FingerPath>& parts, double rate);

/// The kinds known to makeDefaultPath: slide, press-stroke, circle, jab, wander.
const std::vector<std::string>& defaultPathKinds();

/// A path of `kind` suited to an object with `bounds` and a proxy of `radius`: press-stroke
/// presses into the top and strokes across; slide skims the top; circle runs a horizontal circle
/// inside the object at mid-height; jab strikes the top centre at 10 m/s from five directions;
/// wander drives straight through the object. Throws std::invalid_argument for an unknown kind.
FingerPath makeDefaultPath(const std::string& kind, const Aabb& bounds, double radius, double rate);

/// A person-like probing session (DESIGN.md section 5, "the tail is the headline"): episodes
/// at random surface points, each one of
///   - press: approach along the outward normal from `approachDistance` out, press
///     `pressDepth` below the surface, stroke `strokeLength` in a random tangent direction at
///     `strokeSpeed` following the surface (every stroke row is the surface point nearest the
///     straight tangent line, pushed `pressDepth` in along the local normal), dwell, retract;
///   - jab: the same approach line driven in and back out at `jabSpeed`;
///   - wander: from outside straight in along the normal and through the whole object.
/// Between episodes the finger moves straight when that line crosses no triangle, else out along
/// the last outward direction to a sphere around the whole mesh, over it, and in.
/// Surface points are drawn area-weighted; a point is used only if the line along its normal
/// on one side crosses no triangle (the point is visible from outside along that normal, which
/// is then the outward side) and the approach start keeps half the approach distance from every
/// triangle. Nothing assumes that z is up. Lengths in metres, speeds in m/s, times in seconds.
/// Each Min/Max pair is a range, 0 <= min <= max (speeds above 0), that a value is drawn from
/// uniformly where an episode needs it.
struct ProbeOptions
{
  /// Seed of the random draws: the same seed gives the same path.
  std::uint64_t seed = 1;
  /// Episodes are added until the path is at least this long; the last one is finished.
  double duration = 8.0;
  /// Rows per second (Hz), above 0: row k is at k / rate.
  double rate = 1000.0;
  /// Distance out along the normal where an episode starts, least.
  double approachDistanceMin = 0.01;
  /// Distance out along the normal where an episode starts, greatest.
  double approachDistanceMax = 0.02;
  /// Speed of a press's approach and retract, least.
  double approachSpeedMin = 0.05;
  /// Speed of a press's approach and retract, greatest.
  double approachSpeedMax = 0.3;
  /// Depth below the surface of a press or a jab, least.
  double pressDepthMin = 0.0005;
  /// Depth below the surface of a press or a jab, greatest.
  double pressDepthMax = 0.005;
  /// Length of a stroke, least (a stroke that cannot follow the surface ends sooner).
  double strokeLengthMin = 0.01;
  /// Length of a stroke, greatest.
  double strokeLengthMax = 0.03;
  /// Speed of a stroke, least.
  double strokeSpeedMin = 0.05;
  /// Speed of a stroke, greatest.
  double strokeSpeedMax = 0.5;
  /// Time held still after a stroke, least.
  double dwellMin = 0.1;
  /// Time held still after a stroke, greatest.
  double dwellMax = 0.5;
  /// Speed of a jab, in and out, least.
  double jabSpeedMin = 1.0;
  /// Speed of a jab, in and out, greatest.
  double jabSpeedMax = 10.0;
  /// Speed of a wander through the object, least.
  double wanderSpeedMin = 0.2;
  /// Speed of a wander through the object, greatest.
  double wanderSpeedMax = 1.0;
  /// Speed of the moves between episodes, least.
  double transitSpeedMin = 0.2;
  /// Speed of the moves between episodes, greatest.
  double transitSpeedMax = 1.0;
  /// Fraction of the episodes that are jabs.
  double jabFraction = 0.15;
  /// Fraction of the episodes that are wanders; the rest, after the jabs, are presses
  /// (jabFraction + wanderFraction is at most 1).
  double wanderFraction = 0.1;
};

/// What the finger is doing on one row of a probe path (for tests and plots).
enum class ProbePhase : std::uint8_t
{
  Transit,
  Approach,
  Stroke,
  Dwell,
  Retract,
  Jab,
  Wander
};

/// One mesh of a probing session and its tree (for nearest-point queries).
struct ProbeSurface
{
  /// The mesh, not owned: it must outlive the call it is passed to.
  const TriangleMesh* mesh = nullptr;
  /// The sphere tree built on `mesh`, not owned.
  const SphereTree* tree = nullptr;
};

/// A probe path over `surfaces`, the same for the same options on every platform (its own
/// uniform mapping of a std::mt19937_64). Rows are at exactly k / rate. When `phases` is given,
/// it receives one phase per row. Throws std::invalid_argument for empty surfaces, a mesh
/// without area, or options out of order (a minimum above its maximum, a rate not positive).
FingerPath makeProbePath(const std::vector<ProbeSurface>& surfaces, const ProbeOptions& options,
                         std::vector<ProbePhase>* phases = nullptr);

/// The same on one mesh, building its tree first.
FingerPath makeProbePath(const TriangleMesh& mesh, const ProbeOptions& options,
                         std::vector<ProbePhase>* phases = nullptr);

/// What `proxima path KIND` makes on a mesh or scene: a path that does what its name says,
/// placed by the surface as the probe's episodes are (nothing assumes that z is up), at any
/// scale. Lengths follow the surfaces' size d (the diagonal of their bounds) and the proxy
/// radius r; `stretch` is the spring's stretch (proxy to finger) while pressing, so that the
/// force stays kp stretch whatever r is:
///   - press-stroke: approach along the normal, press to `stretch`, stroke min(2 cm, 0.3 d) in
///     one second following the surface, dwell, retract;
///   - slide: the same at a stretch of r / 2 (a skim) over min(4 cm, 0.5 d) in two seconds;
///   - circle: press to `stretch`, then one lap of a circle of radius min(1 cm, 0.05 d) on the
///     surface in two seconds;
///   - jab: five jabs to `stretch` at 1 m/s at one surface point, from close above it;
///   - wander: in along a normal and straight through the whole object (the force saturates:
///     the finger is inside).
/// A press or slide whose stroke cannot follow the surface for half its length (an edge, a
/// crease, a thin part) is tried at other points; when none of 24 serves, throws
/// std::runtime_error saying so. `stretch` defaults to min(3 mm, 0.05 d): 3 N at 1000 N/m.
struct SurfacePathOptions
{
  /// Proxy radius r (m): a press holds the finger `stretch` - r below the surface, so that the
  /// proxy, resting r above it, is `stretch` from the finger.
  double radius = 0.001;
  /// Rows per second (Hz), above 0.
  double rate = 1000.0;
  /// Seed of the random choice of surface points and directions.
  std::uint64_t seed = 1;
  /// 0: the default above.
  double stretch = 0.0;
};
/// The path of `kind` (one of defaultPathKinds()) described above, on `surfaces`. Throws
/// std::invalid_argument for an unknown kind, no surfaces or a surface without its mesh or tree.
FingerPath makeSurfacePath(const std::string& kind, const std::vector<ProbeSurface>& surfaces,
                           const SurfacePathOptions& options);

} // namespace proxima
