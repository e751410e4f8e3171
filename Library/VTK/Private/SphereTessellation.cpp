#include "VTK/Private/SphereTessellation.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>

namespace proxima::vtk::detail
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

int ringsFor(int resolution)
{
  return std::max(2, resolution / 2);
}

// Writes sphere i's latitude-longitude tessellation into its own slice of the output arrays, so
// that vtkSMPTools can run the spheres in any order on any thread without locks.
class TessellateSpheres
{
public:
  TessellateSpheres(const std::vector<Sphere>& spheres, int resolution, double* points,
                    vtkIdType* connectivity, double* radii)
    : m_spheres(spheres)
    , m_around(resolution)
    , m_rings(ringsFor(resolution))
    , m_points(points)
    , m_connectivity(connectivity)
    , m_radii(radii)
  {}

  vtkIdType pointsPerSphere() const { return 2 + static_cast<vtkIdType>(m_rings - 1) * m_around; }
  vtkIdType trianglesPerSphere() const
  {
    return 2 * static_cast<vtkIdType>(m_rings - 1) * m_around;
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType i = begin; i < end; ++i)
    {
      tessellate(i);
    }
  }

private:
  void tessellate(vtkIdType sphere) const
  {
    const Sphere& s = m_spheres[static_cast<std::size_t>(sphere)];
    const vtkIdType firstPoint = sphere * pointsPerSphere();
    double* p = m_points + 3 * firstPoint;
    auto put = [&](double x, double y, double z) {
      *p++ = s.center.x + s.radius * x;
      *p++ = s.center.y + s.radius * y;
      *p++ = s.center.z + s.radius * z;
    };
    put(0.0, 0.0, 1.0);
    for (int ring = 1; ring < m_rings; ++ring)
    {
      const double polar = kPi * ring / m_rings;
      for (int k = 0; k < m_around; ++k)
      {
        const double azimuth = 2.0 * kPi * k / m_around;
        put(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
            std::cos(polar));
      }
    }
    put(0.0, 0.0, -1.0);

    const vtkIdType north = firstPoint;
    const vtkIdType south = firstPoint + pointsPerSphere() - 1;
    auto ringPoint = [&](int ring, int k) {
      return firstPoint + 1 + static_cast<vtkIdType>(ring - 1) * m_around + (k % m_around);
    };
    vtkIdType* c = m_connectivity + 3 * sphere * trianglesPerSphere();
    for (int k = 0; k < m_around; ++k)
    {
      *c++ = north;
      *c++ = ringPoint(1, k);
      *c++ = ringPoint(1, k + 1);
    }
    for (int ring = 1; ring + 1 < m_rings; ++ring)
    {
      for (int k = 0; k < m_around; ++k)
      {
        *c++ = ringPoint(ring, k);
        *c++ = ringPoint(ring + 1, k);
        *c++ = ringPoint(ring + 1, k + 1);
        *c++ = ringPoint(ring, k);
        *c++ = ringPoint(ring + 1, k + 1);
        *c++ = ringPoint(ring, k + 1);
      }
    }
    for (int k = 0; k < m_around; ++k)
    {
      *c++ = ringPoint(m_rings - 1, k + 1);
      *c++ = ringPoint(m_rings - 1, k);
      *c++ = south;
    }
    for (vtkIdType t = 0; t < trianglesPerSphere(); ++t)
    {
      m_radii[sphere * trianglesPerSphere() + t] = s.radius;
    }
  }

  const std::vector<Sphere>& m_spheres;
  int m_around;
  int m_rings;
  double* m_points;
  vtkIdType* m_connectivity;
  double* m_radii;
};
} // namespace

vtkIdType pointsPerSphere(int resolution)
{
  return 2 + static_cast<vtkIdType>(ringsFor(resolution) - 1) * resolution;
}

vtkIdType trianglesPerSphere(int resolution)
{
  return 2 * static_cast<vtkIdType>(ringsFor(resolution) - 1) * resolution;
}

void tessellateSpheres(const std::vector<Sphere>& spheres, int resolution, double* points,
                       vtkIdType* connectivity, double* radii)
{
  TessellateSpheres fill(spheres, resolution, points, connectivity, radii);
  // Parallel over spheres; the grain keeps a chunk worth a thread's start-up.
  vtkSMPTools::For(0, static_cast<vtkIdType>(spheres.size()), 64, fill);
}

} // namespace proxima::vtk::detail
