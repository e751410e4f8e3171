// First contact of a sphere moving along a segment with one triangle (its edges and corners
// included): the exact low-level test of the move stage (paper 2.1).
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"

namespace proxima
{

/// Whether and when a swept sphere first touches a triangle.
struct SweepResult
{
  /// True when the sphere touches the triangle at some t in [0, 1].
  bool hit = false;
  /// Fraction of the motion travelled at first contact; 1 when there is no hit.
  double t = 1.0;
};

/// Earliest t in [0, 1] at which a sphere of `radius` centred at start + t * motion comes within
/// `radius` of the triangle, found as the entry of the segment into the triangle swept by the
/// sphere (two offset faces, three edge cylinders, three corner spheres; the earliest valid
/// entry). A start already within `radius` is a hit at t = 0 only if the motion approaches the
/// triangle; motion along or away from a touching triangle is free.
SweepResult sweepSphereTriangle(const Vec3& start, const Vec3& motion, double radius,
                                const TriangleCorners& triangle);

/// The move stage's contact rule with a skin of width `skin` (see Documentation/Epsilons.md):
/// a triangle farther than radius + 1.5 skin from the start stops the sphere when it comes within
/// radius + skin; a triangle already nearer (distance d0) stops it only at max(radius, d0 - skin/2),
/// so sliding along a touching triangle is never blocked by rounding, and no stop is ever closer
/// than `radius`. A start already at the radius (or a rounding inside it, down to radius - skin/2)
/// is blocked only by motion heading into the triangle steeper than 1e-12 of its length.
/// With skin = 0 this is sweepSphereTriangle.
SweepResult sweepSphereTriangleWithSkin(const Vec3& start, const Vec3& motion, double radius,
                                        double skin, const TriangleCorners& triangle);

/// A triangle's closest point to a point and its squared distance, as closestPointOnTriangle
/// gives them.
struct KnownClosestPoint
{
  /// The triangle's point nearest the sweep's start.
  Vec3 point;
  /// Squared distance from the start to `point`.
  double squaredDistance = 0.0;
};

/// The same, for a caller that already has the triangle's closest point to `start` (the contact
/// planes of the update stage are gathered where the next sweep starts): the answer is the same,
/// bit for bit, without asking for that point again.
SweepResult sweepSphereTriangleWithSkin(const Vec3& start, const Vec3& motion, double radius,
                                        double skin, const TriangleCorners& triangle,
                                        const KnownClosestPoint& closestToStart);

} // namespace proxima
