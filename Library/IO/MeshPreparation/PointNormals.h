// Point normals for force shading of meshes whose files carry none: smooth across gentle bends,
// split at edges sharper than a feature angle, so a CAD part's creases stay sharp under the
// finger while a scan's facets feel round. No OpenMesh type appears in this header.
#pragma once

#include "Geometry/TriangleSoup.h"

namespace proxima
{

/// Returns `soup` with point normals computed with a feature angle, points split where the
/// normals of their corners differ. Any normals `soup` has are ignored and replaced.
///
/// Definition (the tests hold an independent brute-force implementation of exactly this):
/// - Face normal of triangle t = (p0, p1, p2): normalise((p1 - p0) x (p2 - p0)). A triangle whose
///   cross product is exactly zero (collinear or coincident corners, repeated indices) is
///   zero-area: it has no face normal and contributes to no corner normal.
/// - Corner angle of t at p0: the angle between p1 - p0 and p2 - p0 (likewise at p1, p2).
/// - Corner normal of a corner (t, v) of a non-zero-area t: the normalised sum, over the
///   non-zero-area triangles f that use point v and whose face normal is within
///   `featureAngleDegrees` of t's (the angle between them <= the feature angle; t itself always
///   counts), of f's face normal times f's corner angle at v. Weighting by the corner angle makes
///   the result independent of how a planar region is triangulated. If the sum cancels
///   (length <= 1e-12 times the sum of the weights, e.g. both sides of a zero-thickness sheet at
///   a large angle), the corner takes t's face normal.
/// - Corner normal of a corner (t, v) of a zero-area t: the corner normal at v of the nearest
///   non-zero-area triangle using v (nearest centroid to t's centroid; the lower triangle index
///   on a tie), so a zero-area triangle never splits a point; when no non-zero-area triangle
///   uses v, the unit vector +z (0, 0, 1).
/// - Result: one point per distinct (original point, corner normal) pair. The corners of an
///   original point are taken in triangle order; a corner whose normal agrees with that of an
///   earlier new point of the same original point to 1e-12 in every component shares it (and
///   its normal, the first one's), otherwise it makes a new point. New points are ordered by
///   original point, then by first use, so a mesh that splits nowhere keeps its points in their
///   order. Triangles are re-indexed in their order, pointNormals hold the normals, texCoords
///   (when present) are carried to every copy of a point. Points that no triangle uses are
///   dropped.
///
/// The two ends of the range: 180 gives every corner of a point the same normal (fully smooth,
/// no split, unless a sum cancels); 0 gives every corner its own face normal (flat shading:
/// only coplanar triangles, whose normals agree to 1e-12, still share points).
///
/// Throws std::invalid_argument when `featureAngleDegrees` is not finite or outside [0, 180],
/// when a triangle refers to a point out of range, when a point is not finite, when texCoords is
/// neither empty nor one per point, or when the soup has 2^31 points or more (OpenMesh's limit).
TriangleSoup withFeatureAngleNormals(const TriangleSoup& soup, double featureAngleDegrees);

} // namespace proxima
