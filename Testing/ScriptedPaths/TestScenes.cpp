#include "TestScenes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace proxima::scenes
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
}

TriangleSoup makeQuad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  TriangleSoup soup;
  soup.points = {a, b, c, d};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  return soup;
}

TriangleSoup merge(const std::vector<TriangleSoup>& parts)
{
  TriangleSoup all;
  bool normals = true;
  for (const TriangleSoup& part : parts)
  {
    normals = normals && part.pointNormals.size() == part.points.size();
  }
  for (const TriangleSoup& part : parts)
  {
    const auto base = static_cast<std::uint32_t>(all.points.size());
    all.points.insert(all.points.end(), part.points.begin(), part.points.end());
    if (normals)
    {
      all.pointNormals.insert(all.pointNormals.end(), part.pointNormals.begin(),
                              part.pointNormals.end());
    }
    for (const auto& t : part.triangles)
    {
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
  }
  return all;
}

TriangleSoup translate(TriangleSoup soup, const Vec3& offset)
{
  for (Vec3& p : soup.points)
  {
    p += offset;
  }
  return soup;
}

TriangleSoup makeConcaveCorner(double size)
{
  const double s = size;
  return merge({makeQuad({0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}),
                makeQuad({0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}),
                makeQuad({0, 0, 0}, {0, 0, s}, {s, 0, s}, {s, 0, 0})});
}

TriangleSoup makeVGroove(double openingDegrees, double halfLength, double faceWidth)
{
  const double half = 0.5 * openingDegrees * kPi / 180.0;
  const Vec3 up{0, std::sin(half) * faceWidth, std::cos(half) * faceWidth};
  const Vec3 upOther{0, -up.y, up.z};
  const Vec3 a{-halfLength, 0, 0};
  const Vec3 b{halfLength, 0, 0};
  return merge({makeQuad(a, b, b + up, a + up), makeQuad(b, a, a + upOther, b + upOther)});
}

TriangleSoup makePyramid(int sides, double baseRadius, double height)
{
  TriangleSoup soup;
  soup.points.push_back({0, 0, 0});
  for (int i = 0; i < sides; ++i)
  {
    const double angle = 2.0 * kPi * i / sides;
    soup.points.push_back({baseRadius * std::cos(angle), baseRadius * std::sin(angle), height});
  }
  for (int i = 0; i < sides; ++i)
  {
    const auto b = static_cast<std::uint32_t>(1 + i);
    const auto c = static_cast<std::uint32_t>(1 + (i + 1) % sides);
    soup.triangles.push_back({0, b, c});
  }
  return soup;
}

TriangleSoup makeSheet(double size)
{
  TriangleSoup soup;
  const double s = 0.5 * size;
  soup.points = {{-s, -s, 0}, {s, -0.8 * s, 0}, {0.1 * s, s, 0}};
  soup.triangles = {{0, 1, 2}};
  return soup;
}

TriangleSoup makeTiles(int n, double tile, double gap, bool duplicates)
{
  std::vector<TriangleSoup> parts;
  const double pitch = tile + gap;
  const double first = -0.5 * (n * pitch - gap);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = first + i * pitch;
      const double y = first + j * pitch;
      TriangleSoup quad =
        makeQuad({x, y, 0}, {x + tile, y, 0}, {x + tile, y + tile, 0}, {x, y + tile, 0});
      parts.push_back(quad);
      if (duplicates)
      {
        parts.push_back(quad);
      }
    }
  }
  if (duplicates)
  {
    // A tilted tile through the middle: intersecting triangles, as in real soups.
    const double h = 0.5 * tile;
    parts.push_back(
      makeQuad({-h, -h, -0.3 * h}, {h, -h, 0.3 * h}, {h, h, 0.3 * h}, {-h, h, -0.3 * h}));
  }
  return merge(parts);
}

std::unique_ptr<CollisionScene> makeScene(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(std::move(soup), error))
  {
    std::fprintf(stderr, "invalid test scene: %s\n", error.message.c_str());
    std::abort();
  }
  auto scene = std::make_unique<CollisionScene>();
  scene->addObject(std::move(mesh));
  return scene;
}

} // namespace proxima::scenes
