// libFuzzer target: the proxy solver on random soups and finger paths. The bytes become a soup
// of up to 32 triangles with corners on a 16-bit grid 10 cm across (so duplicated, zero-area,
// coplanar and sliver triangles come up all the time), a proxy radius from 0.1 to 100 mm, and a
// finger path whose samples may be NaN, infinite or 1e300 m away. After every tick: a refused
// tick is exactly a non-finite finger, the proxy is finite, and no triangle is nearer than the
// radius (less the tolerance of DESIGN.md section 4), by a brute-force scan of every triangle
// (the solver answers through its sphere tree, swept spheres and goal solver).
#include "Geometry/ClosestPoint.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/ProxySolver.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace
{
using namespace proxima;

class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size)
    : m_data(data)
    , m_size(size)
  {}
  bool empty() const { return m_at >= m_size; }
  std::uint8_t byte() { return m_at < m_size ? m_data[m_at++] : 0; }
  std::int16_t word()
  {
    const auto low = byte();
    const auto high = byte();
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(low | (high << 8)));
  }

private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_at = 0;
};

double coordinate(std::int16_t value, double half)
{
  return half * value / 32768.0;
}

// A finger coordinate: the grid, or one of the values a broken device sends.
double fingerCoordinate(std::int16_t value)
{
  switch (value)
  {
    case -32768: return std::numeric_limits<double>::quiet_NaN();
    case 32767: return std::numeric_limits<double>::infinity();
    case 32766: return -std::numeric_limits<double>::infinity();
    case 32765: return 1e300;
    default: return coordinate(value, 0.1);
  }
}

[[noreturn]] void finding(const char* what, std::uint64_t tick)
{
  std::fprintf(stderr, "tick %llu: %s\n", static_cast<unsigned long long>(tick), what);
  std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes bytes(data, size);
  TriangleSoup soup;
  const int triangles = 1 + bytes.byte() % 32;
  for (int t = 0; t < triangles; ++t)
  {
    const auto base = static_cast<std::uint32_t>(soup.points.size());
    for (int k = 0; k < 3; ++k)
    {
      const double x = coordinate(bytes.word(), 0.05);
      const double y = coordinate(bytes.word(), 0.05);
      const double z = coordinate(bytes.word(), 0.05);
      soup.points.push_back({x, y, z});
    }
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(std::move(soup), error))
  {
    return 0; // finite points and valid indices always build; a refusal is not the solver's
  }
  CollisionScene scene;
  scene.addObject(std::move(mesh));
  ProxyParameters parameters;
  parameters.radius = 1e-4 * std::pow(10.0, 3.0 * bytes.byte() / 255.0);
  ProxySolver solver;
  solver.setScene(&scene, parameters);
  // Start above everything: the grid ends at 5 cm, the largest proxy is 10 cm.
  solver.resetProxy({0.0, 0.0, 0.2});
  const CollisionObject& object = scene.objects.front();
  const double tolerance = std::max(1e-9, 1e-9 * scene.diagonal());
  for (std::uint64_t tick = 0; !bytes.empty() && tick < 256; ++tick)
  {
    const Vec3 finger{fingerCoordinate(bytes.word()), fingerCoordinate(bytes.word()),
                      fingerCoordinate(bytes.word())};
    const ProxyTickResult result = solver.update(finger);
    if (result.conditions.has(TickCondition::fingerRefused) != !isFinite(finger))
    {
      finding("a finite finger was refused, or a non-finite one taken", tick);
    }
    if (!isFinite(result.proxy))
    {
      finding("the proxy is not finite", tick);
    }
    for (std::uint32_t t = 0; t < object.mesh.numTriangles(); ++t)
    {
      const TriangleCorners& c = object.mesh.corners(t);
      const ClosestPointResult nearest = closestPointOnTriangle(result.proxy, c.a, c.b, c.c);
      if (distance(nearest.point, result.proxy) < parameters.radius - tolerance)
      {
        finding("the proxy is inside a triangle's radius", tick);
      }
    }
  }
  return 0;
}
