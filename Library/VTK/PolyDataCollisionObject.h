// From vtkPolyData to one collision object of the kernel (mesh, sphere tree, material): the step
// vtkHapticSphereTreeFilter and vtkHapticScene share. The checks and triangulation are those of
// the IO layer's readers (IO/Mesh/PolyDataToSoup.h), so a poly data set is refused for the
// same defects as a file. Off the haptic thread.
#pragma once

#include "Geometry/SphereTree.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/SurfaceMaterial.h"

#include <cstdint>
#include <string>

class vtkLinearTransform;
class vtkPolyData;

namespace proxima::vtk
{

struct PolyDataObjectSettings
{
  /// Units of the poly data to metres, applied before the pose.
  double scale = 1.0;
  /// A rigid placement (rotation and translation only), or null for none. Points move; point
  /// normals turn, their lengths kept (shading weighs them as given).
  vtkLinearTransform* pose = nullptr;
  /// Force shading: uses the poly data's point normals, or makes them with `featureAngleDegrees`
  /// when it has none.
  bool shading = false;
  double featureAngleDegrees = 30.0;
  SurfaceMaterial material;
  SphereTreeOptions tree;
};

struct PolyDataObjectReport
{
  std::uint32_t numTriangles = 0;
  std::uint32_t numDegenerateTriangles = 0;
  bool computedNormals = false;
  double conversionMilliseconds = 0.0;
  double treeBuildMilliseconds = 0.0;
};

/// The object without its tree (mesh checked, posed, material set): the part that touches VTK,
/// for one thread at a time (the checks collect VTK's messages per thread). Throws as below.
CollisionObject prepareCollisionObject(vtkPolyData* data, const std::string& name,
                                       const PolyDataObjectSettings& settings,
                                       PolyDataObjectReport* report = nullptr);

/// prepareCollisionObject, then the sphere tree (plain kernel code, safe to run for several
/// objects at once). `name` says where the data came from in error messages. Throws
/// InputError for data the kernel cannot use (non-finite points, ids out of range, no
/// triangles) and std::invalid_argument for a pose that is not rigid.
CollisionObject buildCollisionObject(vtkPolyData* data, const std::string& name,
                                     const PolyDataObjectSettings& settings,
                                     PolyDataObjectReport* report = nullptr);

} // namespace proxima::vtk
