#include "Tissue/BoxTetMesh.h"

#include <utility>

namespace proxima
{

TetMesh makeBoxTetMesh(const Vec3& lower, const Vec3& upper, int nx, int ny, int nz)
{
  TetMesh mesh;
  const auto index = [&](int i, int j, int k) {
    return static_cast<std::uint32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        mesh.points.push_back({lower.x + (upper.x - lower.x) * i / nx,
                               lower.y + (upper.y - lower.y) * j / ny,
                               lower.z + (upper.z - lower.z) * k / nz});
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

} // namespace proxima
