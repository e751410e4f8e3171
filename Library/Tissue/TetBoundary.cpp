#include "Tissue/TetBoundary.h"

#include <algorithm>
#include <tuple>

namespace proxima
{
std::vector<std::array<std::uint32_t, 3>> boundaryTriangles(const TetMesh& mesh)
{
  // Each face once per tetrahedron, keyed by its sorted corners; a key seen twice is interior.
  // A positively oriented tetrahedron (a, b, c, d) faces out through (a, c, b), (a, b, d),
  // (a, d, c) and (b, c, d).
  struct Face
  {
    std::array<std::uint32_t, 3> key;
    std::array<std::uint32_t, 3> outward;
    std::size_t order;
  };
  std::vector<Face> faces;
  faces.reserve(mesh.tets.size() * 4);
  for (const auto& tet : mesh.tets)
  {
    const std::array<std::array<std::uint32_t, 3>, 4> outward = {{{tet[0], tet[2], tet[1]},
                                                                  {tet[0], tet[1], tet[3]},
                                                                  {tet[0], tet[3], tet[2]},
                                                                  {tet[1], tet[2], tet[3]}}};
    for (const auto& face : outward)
    {
      std::array<std::uint32_t, 3> key = face;
      std::sort(key.begin(), key.end());
      faces.push_back(Face{key, face, faces.size()});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& f, const Face& g) {
    return std::tie(f.key, f.order) < std::tie(g.key, g.order);
  });
  std::vector<std::pair<std::size_t, std::array<std::uint32_t, 3>>> kept;
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
    {
      ++j;
    }
    if (j - i == 1)
    {
      kept.emplace_back(faces[i].order, faces[i].outward);
    }
    i = j;
  }
  std::sort(kept.begin(), kept.end(),
            [](const auto& f, const auto& g) { return f.first < g.first; });
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(kept.size());
  for (const auto& [order, triangle] : kept)
  {
    triangles.push_back(triangle);
  }
  return triangles;
}

TriangleSoup boundarySoup(const TetMesh& mesh)
{
  TriangleSoup soup;
  soup.points = mesh.points;
  soup.triangles = boundaryTriangles(mesh);
  return soup;
}
} // namespace proxima
