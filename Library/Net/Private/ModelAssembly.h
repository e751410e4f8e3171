// A model uploaded to the live server (proxima_haptic.proto's UploadModel), part by part, checked
// as a file would be: every number finite and in range, every index inside its shape, no more
// triangles than the server takes. Nothing here touches the runtime: the service swaps the
// built scene in only when the whole upload is good and committed.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Proxy/SurfaceMaterial.h"

#include "proxima_haptic.pb.h"

#include <cstdint>
#include <string>
#include <vector>

namespace proxima::detail
{

struct ModelLimits
{
  /// Over all shapes of one model.
  std::uint64_t maxTriangles = 20'000'000;
  std::uint64_t maxPoints = 20'000'000;
};

class ModelAssembly
{
public:
  explicit ModelAssembly(const ModelLimits& limits)
    : m_limits(limits)
  {}

  /// Adds a part; false with `error` (naming the shape) for one that breaks the protocol or holds
  /// a bad number.
  bool add(const net::ShapePart& part, std::string& error);
  /// Builds each shape's mesh and sphere tree into `scene` (in shape order: shape i is object
  /// i); false with `error` for a shape TriangleMesh::build refuses (no triangles, an index out
  /// of range, normals or texture coordinates not one per point). O(triangles log triangles);
  /// allocates.
  bool build(CollisionScene& scene, std::string& error);

  std::size_t numShapes() const { return m_shapes.size(); }
  std::uint64_t numTriangles() const { return m_triangles; }

private:
  struct Shape
  {
    std::string name;
    SurfaceMaterial material;
    TriangleSoup soup;
  };
  std::string shapeName(std::size_t shape) const;

  ModelLimits m_limits;
  std::vector<Shape> m_shapes;
  std::uint64_t m_triangles = 0;
  std::uint64_t m_points = 0;
};

} // namespace proxima::detail
