// Finger paths for tests and demos, sampled at a fixed rate. Each generator is parameterised in
// SI units; makeDefaultPath picks parameters from a mesh's bounding box so that any mesh gets a
// sensible path of each kind.
#pragma once

#include "Core/Aabb.h"
#include "Runtime/FingerPath.h"

#include <string>
#include <vector>

namespace proxima
{

/// Straight line from `from` to `to` at constant speed over `duration` seconds.
FingerPath makeSlidePath(const Vec3& from, const Vec3& to, double duration, double rate);

struct PressAndStroke
{
  /// A point on (or near) the surface, and the direction from it into the object.
  Vec3 surfacePoint;
  Vec3 inward{0, 0, -1};
  /// Start this far outside the surface point, press this deep past it.
  double approachHeight = 0.01;
  double depth = 0.003;
  /// Stroke along this direction (made tangent to `inward`) for this length, then lift.
  Vec3 strokeDirection{1, 0, 0};
  double strokeLength = 0.02;
  double speed = 0.05; // metres per second along the whole path
};
FingerPath makePressAndStrokePath(const PressAndStroke& p, double rate);

/// The paper's Figure 6 path: `revolutions` turns of a circle of `radius` about `axis` through
/// `center`, counter-clockwise seen from the axis' tip, starting at center + radius * startDir.
FingerPath makeCirclePath(const Vec3& center, const Vec3& axis, const Vec3& startDir,
                          double radius, double revolutions, double duration, double rate);

struct Jabs
{
  Vec3 target;
  /// Directions from which the finger strikes (each normalised); one jab per direction.
  std::vector<Vec3> fromDirections;
  /// The finger starts this far from the target and drives this far past it.
  double standoff = 0.02;
  double overshoot = 0.005;
  double speed = 10.0; // m/s: a hard strike
  double pause = 0.01; // seconds held out between jabs
};
FingerPath makeJabPath(const Jabs& jabs, double rate);

/// Concatenates paths, shifting times so each starts one sample after the previous one ends.
FingerPath concatenatePaths(const std::vector<FingerPath>& parts, double rate);

/// The kinds known to makeDefaultPath: slide, press-stroke, circle, jab, wander.
const std::vector<std::string>& defaultPathKinds();

/// A path of `kind` suited to an object with `bounds` and a proxy of `radius`: press-stroke
/// presses into the top and strokes across; slide skims the top; circle runs a horizontal circle
/// inside the object at mid-height; jab strikes the top centre at 10 m/s from five directions;
/// wander drives straight through the object. Throws std::invalid_argument for an unknown kind.
FingerPath makeDefaultPath(const std::string& kind, const Aabb& bounds, double radius,
                           double rate);

} // namespace proxima
