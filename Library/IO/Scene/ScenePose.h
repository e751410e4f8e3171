// Where a scene file puts an object: a rotation, then a translation, applied to the mesh after
// its scale. Points and point normals turn with the object; texture coordinates stay as they are,
// since they belong to the surface, not to space.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleSoup.h"

namespace proxima
{

/// A rotation as a unit quaternion w + x i + y j + z k (the identity by default).
struct UnitQuaternion
{
  double w = 1.0; ///< Scalar part: the cosine of half the rotation angle.
  double x = 0.0; ///< i component of the vector part.
  double y = 0.0; ///< j component of the vector part.
  double z = 0.0; ///< k component of the vector part.

  /// The rotation by `degrees` about `axis` (any length but zero; right-handed). Throws
  /// std::invalid_argument when the axis has no direction or a number is not finite.
  static UnitQuaternion fromAxisAngle(const Vec3& axis, double degrees);
  /// `(w, x, y, z)` divided by its norm. Throws std::invalid_argument when the norm is zero or a
  /// number is not finite.
  static UnitQuaternion normalized(double w, double x, double y, double z);
};

/// A rigid placement: p_world = R p + translation, n_world = R n.
struct ScenePose
{
  /// Where the object's origin goes (m), applied after the rotation.
  Vec3 translation;
  /// The rotation R, applied first.
  UnitQuaternion rotation;

  /// True if the pose leaves everything where it is: no translation, the identity rotation
  /// exactly (w = 1; a quaternion of w = -1 is not taken for one).
  bool isIdentity() const
  {
    return translation == Vec3{} && rotation.w == 1.0 && rotation.x == 0.0 && rotation.y == 0.0 &&
           rotation.z == 0.0;
  }
};

/// `v` turned by `rotation`.
Vec3 rotate(const UnitQuaternion& rotation, const Vec3& v);

/// `soup` placed by `pose`: every point moved, every point normal turned (its length kept, since
/// shading weighs the normals it interpolates as the file gave them), triangles and texture
/// coordinates unchanged.
TriangleSoup posed(TriangleSoup soup, const ScenePose& pose);

} // namespace proxima
