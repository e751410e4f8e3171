#include "Net/Private/ModelAssembly.h"

#include "IO/InputChecks/ParameterRanges.h"

#include <cmath>

namespace proxima::detail
{

namespace
{
// As a scene file's: |coordinate| at most 1e6 m, finite.
bool coordinatesFine(const google::protobuf::RepeatedField<double>& values)
{
  for (const double v : values)
  {
    if (!std::isfinite(v) || std::abs(v) > 1e6)
    {
      return false;
    }
  }
  return true;
}

bool inRange(double value, double low, double high)
{
  return std::isfinite(value) && value >= low && value <= high;
}
} // namespace

std::string ModelAssembly::shapeName(std::size_t shape) const
{
  const std::string& name = shape < m_shapes.size() ? m_shapes[shape].name : std::string();
  return "shape " + std::to_string(shape) + (name.empty() ? "" : " ('" + name + "')");
}

bool ModelAssembly::add(const net::ShapePart& part, std::string& error)
{
  const std::size_t index = part.shape();
  if (index == m_shapes.size())
  {
    // A new shape: its name and material come with its first part.
    Shape shape;
    shape.name = part.name();
    const net::ShapeMaterial& material = part.material();
    // Friction and viscosity in a scene file's ranges; the stiffness factor 0 (unset, 1) to 100.
    if (!inRange(material.stiffness(), 0.0, 100.0) ||
        !kFrictionRange.contains(material.static_friction()) ||
        !kFrictionRange.contains(material.dynamic_friction()) ||
        !kViscosityRange.contains(material.viscosity()))
    {
      error = "shape " + std::to_string(index) +
              ": material out of range (stiffness 0 to 100, friction 0 to 10, viscosity 0 to "
              "1e4 N s/m)";
      return false;
    }
    shape.material.stiffness = material.stiffness() > 0.0 ? material.stiffness() : 1.0;
    shape.material.staticFriction = material.static_friction();
    shape.material.dynamicFriction = material.dynamic_friction();
    shape.material.viscosity = material.viscosity();
    m_shapes.push_back(std::move(shape));
  }
  else if (m_shapes.empty() || index != m_shapes.size() - 1)
  {
    error = "shape " + std::to_string(index) + ": parts must come in order (expected shape " +
            std::to_string(m_shapes.size()) + (m_shapes.empty() ? "" : " or the one before") + ")";
    return false;
  }
  Shape& shape = m_shapes[index];
  if (part.points_size() % 3 != 0 || part.normals_size() % 3 != 0 ||
      part.texture_coordinates_size() % 2 != 0 || part.triangles_size() % 3 != 0)
  {
    error = shapeName(index) + ": points and normals come as x, y, z, texture coordinates as u, "
                               "v and triangles as three indices";
    return false;
  }
  if (!coordinatesFine(part.points()) || !coordinatesFine(part.normals()) ||
      !coordinatesFine(part.texture_coordinates()))
  {
    error = shapeName(index) + ": a coordinate is not finite or beyond 1e6";
    return false;
  }
  m_points += static_cast<std::uint64_t>(part.points_size() / 3);
  m_triangles += static_cast<std::uint64_t>(part.triangles_size() / 3);
  if (m_points > m_limits.maxPoints || m_triangles > m_limits.maxTriangles)
  {
    error = shapeName(index) + ": the model is larger than this server takes (" +
            std::to_string(m_limits.maxTriangles) + " triangles, " +
            std::to_string(m_limits.maxPoints) + " points)";
    return false;
  }
  TriangleSoup& soup = shape.soup;
  for (int i = 0; i + 2 < part.points_size(); i += 3)
  {
    soup.points.push_back(Vec3{part.points(i), part.points(i + 1), part.points(i + 2)});
  }
  for (int i = 0; i + 2 < part.normals_size(); i += 3)
  {
    soup.pointNormals.push_back(Vec3{part.normals(i), part.normals(i + 1), part.normals(i + 2)});
  }
  for (int i = 0; i + 1 < part.texture_coordinates_size(); i += 2)
  {
    soup.texCoords.push_back(
      TexCoord{part.texture_coordinates(i), part.texture_coordinates(i + 1)});
  }
  for (int i = 0; i + 2 < part.triangles_size(); i += 3)
  {
    soup.triangles.push_back({part.triangles(i), part.triangles(i + 1), part.triangles(i + 2)});
  }
  return true;
}

bool ModelAssembly::build(CollisionScene& scene, std::string& error)
{
  if (m_shapes.empty())
  {
    error = "the model has no shapes";
    return false;
  }
  for (std::size_t index = 0; index < m_shapes.size(); ++index)
  {
    Shape& shape = m_shapes[index];
    shape.material.shading = !shape.soup.pointNormals.empty();
    TriangleMesh mesh;
    MeshError meshError;
    if (!mesh.build(std::move(shape.soup), meshError))
    {
      error = shapeName(index) + ": " + meshError.message;
      return false;
    }
    scene.addObject(std::move(mesh), SphereTreeOptions{}, shape.material);
  }
  return true;
}

} // namespace proxima::detail
