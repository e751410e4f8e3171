// Meshes the project generates itself, for tests, benchmarks and the bundled default scene.
#pragma once

#include "Geometry/TriangleSoup.h"

#include <cstdint>

namespace proxima
{

/// A sphere made by subdividing an icosahedron `subdivisions` times: 20 * 4^subdivisions
/// triangles (5: 20,480; 7: 327,680; 8: 1,310,720), with outward unit normals per point.
TriangleSoup makeIcosphere(std::uint32_t subdivisions, double radius, const Vec3& center = Vec3{});

/// An axis-aligned box of the given half-extents, two triangles per face, outward winding.
TriangleSoup makeBox(const Vec3& halfExtents, const Vec3& center = Vec3{});

/// The sides of a regular prism about the z axis (an open tube, no caps): `sides` faces of two
/// triangles each, corners at `radius` from the axis, z from -height/2 to height/2 about
/// `center`, outward winding, and radial unit normals per point: the faceted cylinder of the
/// paper's Figure 6, whose normals stand for the round one.
TriangleSoup makePrism(std::uint32_t sides, double radius, double height,
                       const Vec3& center = Vec3{});

/// A closed cylinder about the z axis triangulated as CAD exporters write one: each of the `sides`
/// side faces is two slivers the cylinder's height long and one facet wide, and each cap is a fan
/// of sides - 2 slivers from a single rim point, so that every cap triangle shares that corner
/// and the longest reach from it across the cap. Outward winding, no normals. The sliver-fan
/// stress mesh of the benchmarks: a sliver's bounding sphere is far larger than the triangle.
TriangleSoup makeSliverCylinder(std::uint32_t sides, double radius, double height,
                                const Vec3& center = Vec3{});

/// A square of side `size` in the plane z = height, split into 2 * cells^2 triangles, normal +z.
TriangleSoup makeGrid(double size, std::uint32_t cells, double height = 0.0);

} // namespace proxima
