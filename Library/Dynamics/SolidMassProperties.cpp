#include "Dynamics/SolidMassProperties.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace proxima
{
namespace
{
// Corner ids by exact position: a soup that repeats its corners per triangle (STL) is closed when
// its positions meet, whatever its indices say.
std::vector<std::array<std::uint32_t, 3>> weldedTriangles(const TriangleMesh& mesh)
{
  std::map<std::tuple<double, double, double>, std::uint32_t> ids;
  std::vector<std::array<std::uint32_t, 3>> triangles(mesh.numTriangles());
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const TriangleCorners& c = mesh.corners(t);
    const Vec3* corners[3] = {&c.a, &c.b, &c.c};
    for (int k = 0; k < 3; ++k)
    {
      const auto key = std::make_tuple(corners[k]->x, corners[k]->y, corners[k]->z);
      triangles[t][k] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
  }
  return triangles;
}

// The integrals over the solid, per unit density, in a frame centred on `origin`: volume, first
// moments and second moments (xx, yy, zz, xy, xz, yz).
struct Moments
{
  double volume = 0.0;
  Vec3 first;
  double second[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

Moments moments(const TriangleMesh& mesh, const Vec3& origin)
{
  Moments m;
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const TriangleCorners& c = mesh.corners(t);
    const Vec3 a = c.a - origin;
    const Vec3 b = c.b - origin;
    const Vec3 d = c.c - origin;
    // The tetrahedron (origin, a, b, d), signed: det / 6 is its volume.
    const double det = dot(a, cross(b, d));
    m.volume += det / 6.0;
    const Vec3 sum = a + b + d;
    m.first = m.first + sum * (det / 24.0);
    // Integral of x_i x_j over the tetrahedron: det / 120 (sum_k v_ki v_kj + s_i s_j), s = a+b+d.
    const auto second = [&](double Vec3::*i, double Vec3::*j) {
      return det / 120.0 * (a.*i * a.*j + b.*i * b.*j + d.*i * d.*j + sum.*i * sum.*j);
    };
    m.second[0] += second(&Vec3::x, &Vec3::x);
    m.second[1] += second(&Vec3::y, &Vec3::y);
    m.second[2] += second(&Vec3::z, &Vec3::z);
    m.second[3] += second(&Vec3::x, &Vec3::y);
    m.second[4] += second(&Vec3::x, &Vec3::z);
    m.second[5] += second(&Vec3::y, &Vec3::z);
  }
  return m;
}
} // namespace

std::string closedSolidDefect(const TriangleMesh& mesh)
{
  if (mesh.numTriangles() < 4)
  {
    return "a closed solid needs at least 4 triangles, the mesh has " +
           std::to_string(mesh.numTriangles());
  }
  // Each directed edge once, and its reverse once: a closed, consistently oriented surface.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& triangle : weldedTriangles(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{triangle[k], triangle[(k + 1) % 3]}];
    }
  }
  std::uint64_t open = 0;
  std::uint64_t misoriented = 0;
  for (const auto& [edge, count] : directed)
  {
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end())
    {
      ++open;
    }
    else if (count != 1 || reverse->second != 1)
    {
      ++misoriented;
    }
  }
  if (open > 0)
  {
    return "the mesh is not closed (" + std::to_string(open) +
           " edges border one triangle only): it bounds no volume to give a mass";
  }
  if (misoriented > 0)
  {
    return "the mesh is not a consistently oriented closed surface (" +
           std::to_string(misoriented) + " edges are shared the wrong way or by more than two " +
           "triangles)";
  }
  const Moments m = moments(mesh, mesh.bounds().center());
  if (!(m.volume > 0.0))
  {
    return "the enclosed volume is not positive (the mesh is inside out, or flat)";
  }
  return {};
}

SolidMassProperties solidMassProperties(const TriangleMesh& mesh, double density)
{
  if (!(density > 0.0) || !std::isfinite(density))
  {
    throw std::invalid_argument("the density must be above 0 kg/m^3");
  }
  const std::string defect = closedSolidDefect(mesh);
  if (!defect.empty())
  {
    throw std::invalid_argument(defect);
  }
  // Integrated about the bounds' centre, where the coordinates are small: a part far from the
  // origin keeps its digits.
  const Vec3 origin = mesh.bounds().center();
  const Moments m = moments(mesh, origin);
  SolidMassProperties p;
  p.volume = m.volume;
  p.mass = density * m.volume;
  const Vec3 local = m.first * (1.0 / m.volume);
  p.centroid = origin + local;
  // Second moments about the centre of mass (parallel axes), then the tensor.
  const double xx = m.second[0] - m.volume * local.x * local.x;
  const double yy = m.second[1] - m.volume * local.y * local.y;
  const double zz = m.second[2] - m.volume * local.z * local.z;
  const double xy = m.second[3] - m.volume * local.x * local.y;
  const double xz = m.second[4] - m.volume * local.x * local.z;
  const double yz = m.second[5] - m.volume * local.y * local.z;
  p.inertia[0] = density * (yy + zz);
  p.inertia[1] = density * (xx + zz);
  p.inertia[2] = density * (xx + yy);
  p.inertia[3] = -density * xy;
  p.inertia[4] = -density * xz;
  p.inertia[5] = -density * yz;
  return p;
}

SolidMassProperties solidMassPropertiesWithMass(const TriangleMesh& mesh, double mass)
{
  if (!(mass > 0.0) || !std::isfinite(mass))
  {
    throw std::invalid_argument("the mass must be above 0 kg");
  }
  // The solid at unit density, scaled: the density is mass / volume.
  const SolidMassProperties unit = solidMassProperties(mesh, 1.0);
  return solidMassProperties(mesh, mass / unit.volume);
}

} // namespace proxima
