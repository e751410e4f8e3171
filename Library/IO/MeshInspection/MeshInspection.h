// What a CAD engineer asks of a mesh before it goes to a printer or a simulator
// (`proxima inspect`): is it closed, where are its holes, its non-manifold and misoriented edges,
// its degenerate and duplicate triangles, how many pieces it has. Counts are of the file's own
// geometry: corners are the same vertex only where their coordinates are identical (bit for bit,
// but for the sign of zero), as an STL file repeats them; nothing is welded at a tolerance.
//
// Definitions (Documentation/CadInspector.md):
//   - an edge is an unordered pair of distinct vertices used by some triangle;
//   - a boundary edge is used by one triangle, a non-manifold edge by three or more;
//   - a boundary loop (a hole, or an open rim) is a connected group of boundary edges;
//   - an edge used by two triangles is misoriented when both traverse it the same way;
//   - a collapsed triangle has two corners on the same vertex; a zero-area triangle three distinct
//     vertices whose cross product is exactly zero in double precision; both are degenerate;
//   - a sliver triangle is not degenerate but has an angle below a threshold (1 degree unless
//     told otherwise);
//   - a duplicate triangle has the same three vertices as an earlier one, in any order;
//   - components are the pieces connected through shared vertices;
//   - a self-intersection is a pair of triangles that share no vertex and meet (touching counts),
//     decided exactly (CGAL's exact predicates; collapsed and collinear triangles left out);
//   - a fold is a pair of neighbours, sharing a vertex or an edge (but not all three vertices: a
//     duplicate), that meet anywhere beyond what they share, decided exactly too; a
//     self-intersection and a fold together are what CGAL's Polygon Mesh Processing calls a
//     self-intersection;
//   - the mesh is closed when it has triangles and no boundary or non-manifold edge.
// Over the kernel's TriangleSoup: linear in the triangles, with hash maps, but for the
// self-intersections (CGAL's box intersection for the candidate pairs, then its exact test).
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleSoup.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace proxima
{

/// A defect's place: a triangle (its index in the file) or an edge (its two vertices), and a
/// point on it to look at.
struct DefectLocation
{
  /// The triangle's index in the soup; for an edge, the first triangle (in file order) that
  /// uses it; for a pair, the lower of the two.
  std::uint32_t triangle = 0;
  /// Where to look: the triangle's centroid, or the edge's midpoint.
  Vec3 point;
  /// For a pair of triangles (self-intersections): the other one (always above `triangle`).
  std::uint32_t other = 0;
  /// For an edge: its first end (the window draws the edge between its two ends).
  Vec3 edgeStart;
  /// For an edge: its second end.
  Vec3 edgeEnd;
};

/// A count and the places of its first few instances (MeshInspectionOptions::locationsKept).
struct DefectCount
{
  /// How many there are in all, however many places are kept.
  std::size_t count = 0;
  /// The places of the first ones found, at most MeshInspectionOptions::locationsKept.
  std::vector<DefectLocation> first;
};

/// What inspectMesh() finds in a mesh: its size, and each kind of defect counted and located
/// (the kinds as Documentation/CadInspector.md defines them).
struct MeshInspection
{
  /// Triangles in the soup, degenerate ones included.
  std::size_t triangles = 0;
  /// Distinct corner positions.
  std::size_t vertices = 0;
  /// Distinct edges: unordered pairs of vertices used by a triangle that is not collapsed.
  std::size_t edges = 0;
  /// Edges used by one triangle only.
  DefectCount boundaryEdges;
  /// One location per loop: its first edge's midpoint; with the loop's edge count.
  DefectCount boundaryLoops;
  /// The number of edges of every boundary loop (not only the located ones), in the order of
  /// boundaryLoops.
  std::vector<std::size_t> boundaryLoopEdges;
  /// Edges used by three or more triangles.
  DefectCount nonManifoldEdges;
  /// Edges used by two triangles that both traverse them the same way.
  DefectCount misorientedEdges;
  /// Triangles with two corners on the same vertex.
  DefectCount collapsedTriangles;
  /// Triangles with three distinct vertices whose cross product is exactly zero.
  DefectCount zeroAreaTriangles;
  /// Triangles that are not degenerate but whose smallest angle is below
  /// MeshInspectionOptions::sliverAngleDegrees.
  DefectCount sliverTriangles;
  /// Triangles with the same three vertices as an earlier one, in any order.
  DefectCount duplicateTriangles;
  /// Pairs listed in the order of their first, then second, triangle.
  DefectCount selfIntersections;
  /// Neighbours (sharing a vertex or an edge) that meet beyond what they share, listed as pairs.
  DefectCount folds;
  /// Pieces connected through shared vertices (collapsed triangles join nothing).
  std::size_t components = 0;
  /// True if the mesh has triangles that are not collapsed and no boundary or non-manifold edge.
  bool closed = false;
};

/// How inspectMesh() works: how many places it keeps, what a sliver is, whom it tells of progress.
struct MeshInspectionOptions
{
  /// Places kept per kind of defect (DefectCount::first); the counts are complete regardless.
  std::size_t locationsKept = 10;
  /// A triangle that is not degenerate is a sliver when its smallest angle, in degrees, is below
  /// this.
  double sliverAngleDegrees = 1.0;
  /// Called with the fraction done (0 to 1) between phases, for progress on long work.
  std::function<void(double)> progress;
};

/// The vertex of each of the soup's points: points on identical coordinates (but for the sign of
/// zero) are one vertex, numbered in the order of their first point. `vertexCount` is set to the
/// number of vertices.
std::vector<std::uint32_t> mergeIdenticalCorners(const TriangleSoup& soup,
                                                 std::size_t& vertexCount);

/// The self-intersecting and the folded pairs of a soup, as findCrossingPairs() gives them.
struct CrossingPairs
{
  /// Pairs that share no vertex and meet (MeshInspection::selfIntersections).
  DefectCount selfIntersections;
  /// Neighbours that meet beyond what they share (MeshInspection::folds).
  DefectCount folds;
};
/// The self-intersecting and the folded pairs of `soup` (as MeshInspection::selfIntersections
/// and MeshInspection::folds), its corners merged into the vertices `vertexOfPoint` gives; at
/// most `locationsKept` places of each kind are kept.
CrossingPairs findCrossingPairs(const TriangleSoup& soup,
                                const std::vector<std::uint32_t>& vertexOfPoint,
                                std::size_t locationsKept);

/// Counts and locates the defects of `soup`, as MeshInspection defines them; calls
/// `options.progress`, if set, between phases.
MeshInspection inspectMesh(const TriangleSoup& soup, const MeshInspectionOptions& options = {});

/// `soup` with corners closer than `tolerance` (metres, in the soup's units) moved onto one
/// position: corners within the tolerance of each other, transitively (a chain of close corners
/// becomes one vertex), take the position of the first of them in the file. What
/// `proxima inspect --weld` inspects beside the file's own geometry.
TriangleSoup weldCorners(const TriangleSoup& soup, double tolerance);

} // namespace proxima
