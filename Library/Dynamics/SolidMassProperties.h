// Mass, centre of mass and inertia of a solid bounded by a closed triangle mesh (the divergence
// theorem over the signed tetrahedra the triangles make with the origin): what a scene body's
// "density" gives its dynamics, and what a stated "mass" is spread by. Plain C++.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"

#include <string>

namespace proxima
{

/// The mass properties of a homogeneous solid, in the frame of the mesh that bounds it.
struct SolidMassProperties
{
  /// Enclosed volume in cubic metres (positive for an outward-oriented mesh).
  double volume = 0.0;
  /// Mass in kilograms: the density times `volume`.
  double mass = 0.0;
  /// Centre of mass, in the mesh's frame.
  Vec3 centroid;
  /// Inertia tensor about the centre of mass, in the mesh's axes (kg m^2): Ixx, Iyy, Izz, Ixy,
  /// Ixz, Iyz (the products with their sign in the tensor: Ixy = -integral of x y dm).
  double inertia[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

/// Why `mesh` bounds no solid, or empty when it does: an edge not shared by exactly two
/// triangles in opposite directions (an open or non-manifold surface), or a volume that is not
/// positive (inside out, or flat).
std::string closedSolidDefect(const TriangleMesh& mesh);

/// The properties of the solid `mesh` bounds, at `density` kg/m^3. Throws std::invalid_argument
/// (closedSolidDefect's words) when it bounds none.
SolidMassProperties solidMassProperties(const TriangleMesh& mesh, double density);

/// The same properties with the mass `mass` spread evenly through the solid.
SolidMassProperties solidMassPropertiesWithMass(const TriangleMesh& mesh, double mass);

} // namespace proxima
