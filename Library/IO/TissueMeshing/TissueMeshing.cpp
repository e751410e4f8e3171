#include "IO/TissueMeshing/TissueMeshing.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace proxima
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Domain = CGAL::Polyhedral_mesh_domain_3<Surface, Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

/// The wrap's offset as a fraction of its alpha: CGAL's documented default ratio (an offset of a
/// thirtieth of alpha keeps the wrap close without making its triangles tiny).
constexpr double kWrapOffsetPerAlpha = 1.0 / 30.0;
/// Mesh_3's facet criteria: the smallest angle of a boundary triangle (degrees; 30 is the most
/// its refinement is proved to reach) and the largest distance from a boundary triangle's centre
/// to the wrap, as a fraction of the tet size.
constexpr double kFacetAngle = 25.0;
constexpr double kFacetDistancePerTetSize = 0.1;
/// Sliver exudation's time limit (s): it stops early on large meshes rather than run for minutes.
constexpr double kExudeSeconds = 30.0;

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void checkSurface(const TriangleSoup& surface, const TissueMeshingOptions& options,
                  const std::string& name)
{
  if (surface.triangles.empty())
  {
    throw InputError(name, "the surface has no triangles to fill");
  }
  Vec3 lower{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
             std::numeric_limits<double>::max()};
  Vec3 upper = -lower;
  for (const Vec3& p : surface.points)
  {
    if (!isFinite(p))
    {
      throw InputError(name, "a point of the surface is not finite");
    }
    lower = {std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z)};
    upper = {std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z)};
  }
  if (!(std::isfinite(options.tetSize) && options.tetSize > 0.0))
  {
    throw InputError("--tet-size",
                     "must be a finite length above 0, not " + shortNumber(options.tetSize));
  }
  const double smallestSide = std::min({upper.x - lower.x, upper.y - lower.y, upper.z - lower.z});
  if (options.tetSize > smallestSide)
  {
    throw InputError("--tet-size", shortNumber(options.tetSize) + " m is larger than " + name +
                                     " (its bounding box's smallest side is " +
                                     shortNumber(smallestSide) + " m)");
  }
}

Surface wrapSurface(const TriangleSoup& surface, double alpha)
{
  std::vector<Point> points;
  points.reserve(surface.points.size());
  for (const Vec3& p : surface.points)
  {
    points.emplace_back(p.x, p.y, p.z);
  }
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles)
  {
    faces.push_back({t[0], t[1], t[2]});
  }
  Surface wrap;
  CGAL::alpha_wrap_3(points, faces, alpha, alpha * kWrapOffsetPerAlpha, wrap);
  // The wrap is closed and manifold; face it outward, as Mesh_3's inside test and the haptic
  // surface both read it.
  if (!CGAL::Polygon_mesh_processing::is_outward_oriented(wrap))
  {
    CGAL::Polygon_mesh_processing::reverse_face_orientations(wrap);
  }
  return wrap;
}

TriangleSoup soupOf(const Surface& surface)
{
  TriangleSoup soup;
  std::unordered_map<std::size_t, std::uint32_t> index;
  for (const auto vertex : surface.vertices())
  {
    index[static_cast<std::size_t>(vertex)] = static_cast<std::uint32_t>(soup.points.size());
    const Point& p = surface.point(vertex);
    soup.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  for (const auto face : surface.faces())
  {
    std::array<std::uint32_t, 3> triangle{};
    int corner = 0;
    for (const auto vertex : CGAL::vertices_around_face(surface.halfedge(face), surface))
    {
      triangle[static_cast<std::size_t>(corner++)] = index.at(static_cast<std::size_t>(vertex));
    }
    soup.triangles.push_back(triangle);
  }
  return soup;
}

TetMesh tetsOf(const Complex& complex)
{
  TetMesh mesh;
  // Keyed by the vertex's address: a triangulation's vertices stay where they are.
  std::unordered_map<const void*, std::uint32_t> index;
  const auto indexOf = [&](Triangulation::Vertex_handle vertex) {
    const auto [found, added] =
      index.try_emplace(&*vertex, static_cast<std::uint32_t>(mesh.points.size()));
    if (added)
    {
      const auto p = complex.triangulation().point(vertex).point();
      mesh.points.push_back(
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    return found->second;
  };
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell)
  {
    std::array<std::uint32_t, 4> tet{indexOf(cell->vertex(0)), indexOf(cell->vertex(1)),
                                     indexOf(cell->vertex(2)), indexOf(cell->vertex(3))};
    // A triangulation's cells are positively oriented in its own predicate; keep the rule in
    // double too, where a near-flat element's rounding could differ.
    if (signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                        mesh.points[tet[3]]) < 0.0)
    {
      std::swap(tet[2], tet[3]);
    }
    mesh.tets.push_back(tet);
  }
  return mesh;
}

} // namespace

double enclosedVolume(const TriangleSoup& surface)
{
  double volume = 0.0;
  for (const auto& t : surface.triangles)
  {
    const Vec3& a = surface.points[t[0]];
    const Vec3& b = surface.points[t[1]];
    const Vec3& c = surface.points[t[2]];
    volume += dot(a, cross(b, c)) / 6.0;
  }
  return volume;
}

TissueMeshingResult meshTissue(const TriangleSoup& surface, const TissueMeshingOptions& options,
                               const std::string& name)
{
  checkSurface(surface, options, name);
  TissueMeshingResult result;
  const auto wrapStart = std::chrono::steady_clock::now();
  const Surface wrap = wrapSurface(surface, options.tetSize);
  result.wrapped = soupOf(wrap);
  result.wrappedVolume = enclosedVolume(result.wrapped);
  result.wrapSeconds = secondsSince(wrapStart);

  const auto fillStart = std::chrono::steady_clock::now();
  const Domain domain(wrap);
  namespace parameters = CGAL::parameters;
  // CGAL 5.5's Mesh_3 takes these as Boost named parameters (name = value).
  const Criteria criteria(parameters::facet_angle = kFacetAngle,
                          parameters::facet_size = options.tetSize,
                          parameters::facet_distance = kFacetDistancePerTetSize * options.tetSize,
                          parameters::cell_radius_edge_ratio = options.radiusEdgeRatio,
                          parameters::cell_size = options.tetSize);
  const Complex complex =
    CGAL::make_mesh_3<Complex>(domain, criteria, parameters::no_perturb(),
                               parameters::exude(parameters::time_limit = kExudeSeconds));
  result.tets = tetsOf(complex);
  result.fillSeconds = secondsSince(fillStart);
  if (result.tets.tets.empty())
  {
    throw InputError(name, "no tetrahedron fits inside the wrapped surface at --tet-size " +
                             shortNumber(options.tetSize) + " m (give a smaller size)");
  }
  return result;
}

} // namespace proxima
