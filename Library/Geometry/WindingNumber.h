// Inside or outside a triangle soup: the generalized winding number (Jacobson, Kavan and
// Sorkine-Hornung, "Robust Inside-Outside Segmentation using Generalized Winding Numbers", 2013).
// Each triangle adds the signed solid angle it subtends at the point (van Oosterom and Strackee,
// "The Solid Angle of a Plane Triangle", 1983) over 4 pi: 1 inside a closed, outward-oriented
// surface, 0 outside, and a smooth fraction near the holes of an open one, so gaps, duplicates
// and stray sheets move it a little instead of flipping it the way a ray's parity flips. O(n) in
// the triangles, exact over all of them: for the start of a run and for scene installs, never
// for a proxy tick (Documentation/Kernel.md, "Starting outside").
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"

namespace proxima
{

/// The signed solid angle in steradians that triangle (a, b, c) subtends at `point`: positive
/// when the point sees the triangle's corners clockwise, i.e. it is behind the side that the
/// right-hand normal (b - a) x (c - a) points to. In (-2 pi, 2 pi]; 0 for a degenerate triangle
/// or a point in the triangle's plane outside it.
double triangleSolidAngle(const Vec3& point, const Vec3& a, const Vec3& b, const Vec3& c);

/// The generalized winding number of `mesh` at `point`: the sum of the triangles' solid angles
/// over 4 pi. A point on the surface itself gets a value between the two sides'.
double windingNumber(const TriangleMesh& mesh, const Vec3& point);

/// Inside by the winding number: above a half, the midpoint between outside (0) and inside (1)
/// of a surface whose faces face out of their object, as mesh files mean them to. A surface
/// wound the other way round all over gives -1 inside, and counts only that near a whole turn
/// (below -0.9): the faces of an open concave corner look at a point in front of them and wind
/// up to 7/8 of a turn that way (three walls of a box's inside corner), and that is free space.
inline bool isInsideByWindingNumber(double windingNumber)
{
  return windingNumber > 0.5 || windingNumber < -0.9;
}

} // namespace proxima
