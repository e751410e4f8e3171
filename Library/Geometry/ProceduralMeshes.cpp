#include "Geometry/ProceduralMeshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace proxima
{

TriangleSoup makeIcosphere(std::uint32_t subdivisions, double radius, const Vec3& center)
{
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                            {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                            {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vec3& p : unit)
  {
    p = normalizedOrZero(p);
  }
  std::vector<std::array<std::uint32_t, 3>> faces = {
    {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (std::uint32_t level = 0; level < subdivisions; ++level)
  {
    // Each edge's midpoint is made once and shared by both faces, so the sphere stays closed.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
      const auto key = std::minmax(i, j);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      unit.push_back(normalizedOrZero((unit[i] + unit[j]) * 0.5));
      const auto index = static_cast<std::uint32_t>(unit.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces)
    {
      const std::uint32_t ab = midpoint(f[0], f[1]);
      const std::uint32_t bc = midpoint(f[1], f[2]);
      const std::uint32_t ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  TriangleSoup soup;
  soup.points.reserve(unit.size());
  soup.pointNormals = unit;
  for (const Vec3& p : unit)
  {
    soup.points.push_back(center + p * radius);
  }
  soup.triangles = std::move(faces);
  return soup;
}

TriangleSoup makeBox(const Vec3& h, const Vec3& center)
{
  TriangleSoup soup;
  for (int i = 0; i < 8; ++i)
  {
    soup.points.push_back(center +
                          Vec3{(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
  }
  // Quads with outward winding (counter-clockwise seen from outside).
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
  {
    soup.triangles.push_back({q[0], q[1], q[2]});
    soup.triangles.push_back({q[0], q[2], q[3]});
  }
  return soup;
}

TriangleSoup makeGrid(double size, std::uint32_t cells, double height)
{
  TriangleSoup soup;
  const double step = size / cells;
  for (std::uint32_t j = 0; j <= cells; ++j)
  {
    for (std::uint32_t i = 0; i <= cells; ++i)
    {
      soup.points.push_back({-0.5 * size + i * step, -0.5 * size + j * step, height});
      soup.pointNormals.push_back({0, 0, 1});
    }
  }
  const std::uint32_t row = cells + 1;
  for (std::uint32_t j = 0; j < cells; ++j)
  {
    for (std::uint32_t i = 0; i < cells; ++i)
    {
      const std::uint32_t v = j * row + i;
      soup.triangles.push_back({v, v + 1, v + row + 1});
      soup.triangles.push_back({v, v + row + 1, v + row});
    }
  }
  return soup;
}

TriangleSoup makePrism(std::uint32_t sides, double radius, double height, const Vec3& center)
{
  TriangleSoup soup;
  const double pi = std::acos(-1.0);
  for (std::uint32_t i = 0; i < sides; ++i)
  {
    const double angle = 2.0 * pi * i / sides;
    const Vec3 radial{std::cos(angle), std::sin(angle), 0.0};
    for (double z : {-0.5 * height, 0.5 * height})
    {
      soup.points.push_back(center + radial * radius + Vec3{0.0, 0.0, z});
      soup.pointNormals.push_back(radial);
    }
  }
  for (std::uint32_t i = 0; i < sides; ++i)
  {
    const std::uint32_t bottom = 2 * i;
    const std::uint32_t next = 2 * ((i + 1) % sides);
    soup.triangles.push_back({bottom, next, next + 1});
    soup.triangles.push_back({bottom, next + 1, bottom + 1});
  }
  return soup;
}

TriangleSoup makeSliverCylinder(std::uint32_t sides, double radius, double height,
                                const Vec3& center)
{
  TriangleSoup soup;
  sides = std::max<std::uint32_t>(sides, 3);
  const double pi = std::acos(-1.0);
  // Rim points: bottom ring at 2i, top ring at 2i + 1.
  for (std::uint32_t i = 0; i < sides; ++i)
  {
    const double angle = 2.0 * pi * i / sides;
    const Vec3 radial{std::cos(angle), std::sin(angle), 0.0};
    soup.points.push_back(center + radial * radius + Vec3{0.0, 0.0, -0.5 * height});
    soup.points.push_back(center + radial * radius + Vec3{0.0, 0.0, 0.5 * height});
  }
  for (std::uint32_t i = 0; i < sides; ++i)
  {
    const std::uint32_t bottom = 2 * i;
    const std::uint32_t next = 2 * ((i + 1) % sides);
    soup.triangles.push_back({bottom, next, next + 1});
    soup.triangles.push_back({bottom, next + 1, bottom + 1});
  }
  // The caps: fans from rim point 0, the bottom seen from below, the top from above.
  for (std::uint32_t i = 1; i + 1 < sides; ++i)
  {
    soup.triangles.push_back({0, 2 * (i + 1), 2 * i});
    soup.triangles.push_back({1, 2 * i + 1, 2 * (i + 1) + 1});
  }
  return soup;
}

} // namespace proxima
