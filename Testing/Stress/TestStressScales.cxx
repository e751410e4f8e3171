// Stress: scale. The same scenes with their coordinates offset by 10^-6 .. 10^4 m in a random
// direction (rounding grows with the coordinates, the scene does not), and proxy radii from
// 10^-5 to 10^-1 m on a 4 cm sphere and a box (the skin and every tolerance follow the scene).
// Random with recorded seeds; the oracle watches every tick.
#include "StressSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxima::stress
{
namespace
{
Aabb boundsOf(const TriangleSoup& soup)
{
  Aabb box;
  for (const Vec3& p : soup.points)
  {
    box.expand(p);
  }
  return box;
}

// One of a few scenes near the origin: a faceted sphere, a box, a concave corner, tiles.
TriangleSoup someScene(Random& random, std::string& name)
{
  switch (random.integer(0, 3))
  {
    case 0: name = "icosphere"; return makeIcosphere(3, 0.02);
    case 1: name = "box"; return makeBox({0.02, 0.015, 0.01});
    case 2: name = "corner"; return scenes::makeConcaveCorner(0.04);
    default: name = "tiles"; return scenes::makeTiles(4, 0.01, 0.0012, true);
  }
}

// Press-stroke and circle paths made for the scene's bounds and the proxy, and jabs at 10 m/s
// when `jabs` (not with the smallest radii: the oracle checks a 10 mm move of a 10 um proxy piece
// by piece, in 128-bit software arithmetic).
FingerPath pathsFor(const Aabb& bounds, double radius, double rate, bool jabs = true)
{
  std::vector<FingerPath> parts;
  std::vector<std::string> kinds{"press-stroke", "circle"};
  if (jabs)
  {
    kinds.push_back("jab");
  }
  for (const std::string& kind : kinds)
  {
    parts.push_back(makeDefaultPath(kind, bounds, radius, rate));
  }
  return concatenatePaths(parts, rate);
}

TEST(StressScales, CoordinatesOffsetFrom1e6To1e4Metres)
{
  runCases(7000, 12, [&](Random& random, StressCase& c) {
    c.proxy.radius = 0.001;
    std::string scene;
    TriangleSoup soup = someScene(random, scene);
    soup.pointNormals.clear();
    const double magnitude = random.logUniform(1e-6, 1e4);
    const Vec3 offset = random.direction() * magnitude;
    char label[96];
    std::snprintf(label, sizeof label, "%s/offset-%.1e-m", scene.c_str(), magnitude);
    c.name = label;
    const FingerPath path = pathsFor(boundsOf(soup), c.proxy.radius, c.rate);
    const Rotation rotation = Rotation::random(random);
    c.soup = transform(std::move(soup), rotation, offset);
    c.path = transform(path, rotation, offset);
  });
}

TEST(StressScales, ProxyRadiiFrom1e5To1e1Metres)
{
  runCases(8000, 12, [&](Random& random, StressCase& c) {
    c.proxy.radius = random.logUniform(1e-5, 1e-1);
    // The faceted sphere only under proxies smaller than a facet row: a proxy as big as the
    // sphere rolls over many facets a tick (up to the iteration cap), and the oracle replays every
    // move of such a tick (quadratic in its iterations). Bigger proxies get the box.
    const bool sphere = random.uniform() < 0.5 && c.proxy.radius < 5e-3;
    TriangleSoup soup = sphere ? makeIcosphere(3, 0.04) : makeBox({0.03, 0.02, 0.01});
    soup.pointNormals.clear();
    char label[96];
    std::snprintf(label, sizeof label, "%s/radius-%.1e-m", sphere ? "icosphere" : "box",
                  c.proxy.radius);
    c.name = label;
    const FingerPath path = pathsFor(boundsOf(soup), c.proxy.radius, c.rate, c.proxy.radius > 1e-3);
    const Rotation rotation = Rotation::random(random);
    c.soup = transform(std::move(soup), rotation);
    c.path = transform(path, rotation);
  });
}

} // namespace
} // namespace proxima::stress
