// Where a pointer on a screen puts the finger (PointerDevice): on the plane through the proxy that
// faces the camera, under the cursor, pushed `depth` behind that plane along the view. A screen has
// two dimensions and a finger three; the third is the depth, which the wheel or a held key sets.
//
// Where the plane goes through:
// - the proxy, while it touches something: the depth is then how far the finger is pressed behind
//   the surface under it;
// - free, over a surface: the point where the proxy would first touch the surface under the
//   cursor (the hover point, when the caller found one), so that the finger glides over the
//   surface at arm's length and a press goes into it, also after the pressed finger slid off
//   into free space (the hover point depends on the surface only, not on the proxy);
// - free over empty background: the proxy when not pressed in; pressed in, where it last was. A
//   plane through a free proxy, which is where the finger is, would move `depth` further away at
//   every aim.
#pragma once

#include "Core/Vec3.h"

namespace proxima
{

/// Turns a cursor's ray into a finger position, on a plane through the proxy (or the hover point)
/// facing the camera and `depth` behind it. Keeps the depth and the last plane's point; for one
/// thread (the window's).
class PointerAimPlane
{
public:
  /// How far behind the plane the finger goes, in metres (negative is taken as 0).
  void setDepth(double depth);
  /// How far behind the plane the finger goes, in metres (0 or more).
  double depth() const { return m_depth; }

  /// The finger's aim for a cursor whose ray starts at `rayOrigin` (the eye, or the near plane's
  /// point) along `rayDirection`, with the camera looking along `viewDirection` (unit), the proxy at
  /// `proxy`, touching something or not, and the hover point if the cursor's ray meets a surface
  /// (null if not). A ray parallel to the plane aims at the plane's point.
  Vec3 aim(const Vec3& rayOrigin, const Vec3& rayDirection, const Vec3& viewDirection,
           const Vec3& proxy, bool touching, const Vec3* hover = nullptr);

  /// The point the plane goes through (after the last aim).
  const Vec3& anchor() const { return m_anchor; }

private:
  double m_depth = 0.0;
  bool m_anchored = false;
  Vec3 m_anchor;
};

} // namespace proxima
