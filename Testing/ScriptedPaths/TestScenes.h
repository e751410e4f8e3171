// Procedural scenes of the proxy tests, each the smallest mesh that holds one hard case of
// DESIGN.md section 4: a concave corner (three planes), a V-groove narrower than 90 degrees, a
// pyramid apex and a pit (four or more planes through one point), a zero-thickness sheet, and a
// soup of tiles with gaps narrower than the proxy, duplicated and intersecting triangles.
// Lengths in metres.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleSoup.h"
#include "Proxy/CollisionScene.h"

#include <memory>
#include <vector>

namespace proxima::scenes
{

/// Two triangles (a, b, c) and (a, c, d).
TriangleSoup makeQuad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// One soup holding all of `parts` (indices shifted; attributes dropped unless all have them).
TriangleSoup merge(const std::vector<TriangleSoup>& parts);
/// Every point moved by `offset`.
TriangleSoup translate(TriangleSoup soup, const Vec3& offset);

/// Floor z = 0 and walls x = 0 and y = 0, each a square of side `size` in the positive octant
/// (free space is x, y, z > 0): the proxy pressed into the corner touches three planes.
TriangleSoup makeConcaveCorner(double size);

/// Two planar faces meeting in the line y = z = 0 (along x, from -halfLength to halfLength), each
/// rising `faceWidth` along its slope, `openingDegrees` apart, symmetric about +z.
TriangleSoup makeVGroove(double openingDegrees, double halfLength, double faceWidth);

/// `sides` triangular faces meeting at the apex (0, 0, 0), with base corners on a circle of
/// `baseRadius` at height `height`: height > 0 makes a pit (a funnel, free space above),
/// height < 0 a pyramid standing on its apex's opposite side, apex up (free space above too).
TriangleSoup makePyramid(int sides, double baseRadius, double height);

/// One triangle in z = 0 with corners around the origin, `size` across: zero thickness.
TriangleSoup makeSheet(double size);

/// n x n square tiles of side `tile` in z = 0, centred on the origin, `gap` apart, each with its
/// own corner points (a soup). With `duplicates` every triangle appears twice and a tilted tile
/// cuts through the middle one.
TriangleSoup makeTiles(int n, double tile, double gap, bool duplicates);

/// A scene holding `soup` as one object; aborts the test program on an invalid soup.
std::unique_ptr<CollisionScene> makeScene(TriangleSoup soup);

} // namespace proxima::scenes
