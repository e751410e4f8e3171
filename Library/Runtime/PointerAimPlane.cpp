#include "Runtime/PointerAimPlane.h"

#include <cmath>

namespace proxima
{

void PointerAimPlane::setDepth(double depth)
{
  m_depth = std::isfinite(depth) && depth > 0.0 ? depth : 0.0;
}

Vec3 PointerAimPlane::aim(const Vec3& rayOrigin, const Vec3& rayDirection,
                          const Vec3& viewDirection, const Vec3& proxy, bool touching,
                          const Vec3* hover)
{
  if (touching)
  {
    m_anchor = proxy;
  }
  else if (hover != nullptr)
  {
    // Free, pressed in or not: the surface under the cursor. It depends on the surface only, so
    // a press does not run away, and a finger that slid off into free space while pressed goes
    // back into what the cursor points at.
    m_anchor = *hover;
  }
  else if (m_depth == 0.0 || !m_anchored)
  {
    m_anchor = proxy;
  }
  m_anchored = true;
  Vec3 onPlane = m_anchor;
  const double along = dot(rayDirection, viewDirection);
  // A ray within about a thousandth of a degree of the plane meets it too far away to mean a place.
  if (std::abs(along) > 1e-5 * norm(rayDirection))
  {
    const double s = dot(m_anchor - rayOrigin, viewDirection) / along;
    onPlane = rayOrigin + rayDirection * s;
  }
  return onPlane + viewDirection * m_depth;
}

} // namespace proxima
