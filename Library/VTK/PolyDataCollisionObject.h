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

/// How prepareCollisionObject and buildCollisionObject make an object of poly data: its scale,
/// pose, shading, material and tree options.
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
  /// The feature angle (degrees, 0 to 180) of the normals made for shading: edges sharper than
  /// it stay sharp (IO/MeshPreparation/PointNormals.h).
  double featureAngleDegrees = 30.0;
  /// The object's material; its `shading` is replaced by `shading` above.
  SurfaceMaterial material;
  /// The sphere tree's options, for buildCollisionObject (prepareCollisionObject builds none).
  SphereTreeOptions tree;
};

/// What making an object found and how long it took, for a caller that reports it.
struct PolyDataObjectReport
{
  /// Triangles of the object's mesh, after the poly data's polygons and strips were
  /// triangulated.
  std::uint32_t numTriangles = 0;
  /// Of those, the triangles of zero area (collinear or coincident corners).
  std::uint32_t numDegenerateTriangles = 0;
  /// True when the point normals were made here (shading on, and the poly data had none).
  bool computedNormals = false;
  /// Wall time of the checks, conversion, normals and pose (ms).
  double conversionMilliseconds = 0.0;
  /// Wall time of the sphere tree's build (ms); set by buildCollisionObject only.
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
