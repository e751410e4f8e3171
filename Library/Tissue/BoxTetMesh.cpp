#include "Tissue/BoxTetMesh.h"

#include <cmath>
#include <utility>

namespace proxima
{

TetMesh makeBoxTetMesh(const Vec3& lower, const Vec3& upper, int nx, int ny, int nz)
{
  const auto evenly = [](double from, double to, int cells) {
    std::vector<double> at;
    for (int i = 0; i <= cells; ++i)
    {
      at.push_back(from + (to - from) * i / cells);
    }
    return at;
  };
  return makeGridTetMesh(evenly(lower.x, upper.x, nx), evenly(lower.y, upper.y, ny),
                         evenly(lower.z, upper.z, nz));
}

TetMesh makeGridTetMesh(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::vector<double>& zs)
{
  TetMesh mesh;
  const int nx = static_cast<int>(xs.size()) - 1;
  const int ny = static_cast<int>(ys.size()) - 1;
  const int nz = static_cast<int>(zs.size()) - 1;
  const auto index = [&](int i, int j, int k) {
    return static_cast<std::uint32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  for (const double z : zs)
  {
    for (const double y : ys)
    {
      for (const double x : xs)
      {
        mesh.points.push_back({x, y, z});
      }
    }
  }
  // Each Kuhn tetrahedron is a path from the cell's corner 0 to its corner 7 along the three
  // axes in one of the six orders.
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        for (const auto& order : orders)
        {
          int at[3] = {i, j, k};
          std::array<std::uint32_t, 4> tet{};
          tet[0] = index(at[0], at[1], at[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++at[order[step]];
            tet[static_cast<std::size_t>(step + 1)] = index(at[0], at[1], at[2]);
          }
          if (signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                              mesh.points[tet[3]]) < 0.0)
          {
            std::swap(tet[1], tet[2]);
          }
          mesh.tets.push_back(tet);
        }
      }
    }
  }
  return mesh;
}

std::vector<double> gradedCoordinates(double from, double to, double finest, double growth)
{
  const double direction = to > from ? 1.0 : -1.0;
  const double length = std::abs(to - from);
  std::vector<double> at{from};
  double covered = 0.0;
  double cell = finest;
  while (covered + cell < length)
  {
    covered += cell;
    at.push_back(from + direction * covered);
    cell *= growth;
  }
  // The rest is shorter than the next cell would be; as a cell of its own it could be a sliver,
  // so when it is shorter than its predecessor it joins it (cells never shrink toward `to`).
  if (at.size() > 1 && length - covered < cell / growth)
  {
    at.pop_back();
  }
  at.push_back(to);
  return at;
}

} // namespace proxima
