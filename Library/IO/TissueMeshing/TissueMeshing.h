// An organ's surface made into a solid for the tissue model: the surface, a soup as organ files
// are (parts, holes, self-intersections), is wrapped into a closed, manifold, outward-oriented
// surface (CGAL's 3D alpha wrapping), and that surface is filled with tetrahedra of a given size
// and a bounded shape (CGAL's Mesh_3, then sliver exudation). CGAL stays in the .cpp file.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "Tissue/TetMesh.h"

#include <string>

namespace proxima
{

/// How a surface is made into tetrahedra.
struct TissueMeshingOptions
{
  /// The tetrahedra's target edge size (m): Mesh_3's cell and facet size. The wrap's alpha is the
  /// same length, so that the wrap keeps no detail finer than the elements could follow.
  double tetSize = 0.005;
  /// Mesh_3's bound on a tetrahedron's circumradius over its shortest edge (2 is the best
  /// Delaunay refinement guarantees; 3 its usual setting). Slivers pass it; exudation removes
  /// most of them.
  double radiusEdgeRatio = 3.0;
};

/// What meshing a surface made, and how long each part took.
struct TissueMeshingResult
{
  /// The tetrahedra, positively oriented.
  TetMesh tets;
  /// The closed surface the tetrahedra fill (the wrap), outward-oriented.
  TriangleSoup wrapped;
  /// The volume the wrap encloses (m^3), from its faces alone.
  double wrappedVolume = 0.0;
  /// Wall time of the wrap (s).
  double wrapSeconds = 0.0;
  /// Wall time of the filling, exudation included (s).
  double fillSeconds = 0.0;
};

/// Wraps `surface` and fills the wrap with tetrahedra. Throws InputError naming `name` (the
/// surface's file) for a surface with no triangle, a coordinate that is not finite, a tet size
/// that is not a finite length above 0, or one larger than the object (than the smallest side of
/// the surface's bounding box).
TissueMeshingResult meshTissue(const TriangleSoup& surface, const TissueMeshingOptions& options,
                               const std::string& name);

/// The volume a closed, outward-oriented triangle surface encloses (m^3): the divergence theorem,
/// a sum of signed tetrahedra from the origin over the faces.
double enclosedVolume(const TriangleSoup& surface);

} // namespace proxima
