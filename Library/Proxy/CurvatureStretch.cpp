// The update stage's curvature correction (Kernel.md, step 3): where the active plane is the
// tangent plane of an edge's cylinder or a corner's sphere in configuration space, the planar
// slide undershoots, and a Newton step stretches it by the curvature. ProxySolver's members; the
// trust region that decides whether and how far to stretch is StretchTrustRegion
// (ProxyTickState.h).
#include "Proxy/ProxySolver.h"

#include "Proxy/ProxyTickState.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxima
{
namespace
{
// How far a crease's stretched slide may reach, as a fraction of the curved surface's radius.
constexpr double kCreaseStretchReach = 0.25;

// A stretched slide may cross a plane by this fraction of the finger distance (the goal
// solver's feasibility tolerance): rounding, not a heading into the plane.
constexpr double kStretchFeasibility = 1e-12;

// The edge of `feature` as its two corners, or false for a vertex or the face.
bool edgeOf(const TriangleCorners& corners, TriangleFeature feature, Vec3& from, Vec3& to)
{
  switch (feature)
  {
    case TriangleFeature::EdgeAB:
      from = corners.a;
      to = corners.b;
      return true;
    case TriangleFeature::EdgeBC:
      from = corners.b;
      to = corners.c;
      return true;
    case TriangleFeature::EdgeCA:
      from = corners.c;
      to = corners.a;
      return true;
    default: return false;
  }
}
} // namespace

Vec3 ProxySolver::curvatureCorrectedStep(const GoalSolution& solution, const Vec3& toFinger,
                                         double creaseStretchLimit) const
{
  // The stretch is worked out for the active plane alone, but the slide it stretches stays above
  // the other planes only by the goal solve: stretched, it may head into one it merely touches.
  // The sweep then blocks it at once (the proxy touches that triangle), and the next update stage,
  // at the same point, stretches the same slide again. The liver corner (ProxySolverFound.
  // StretchedSlideIntoATouchedPlaneFallsBackToThePlaneSlide) ended so, 1.6e-7 m short of its
  // minimum. A stretched step that crosses any plane gives way to the feasible planar slide.
  const Vec3 stretched = stretchedSlide(solution, toFinger, creaseStretchLimit);
  if (stretched == solution.displacement)
  {
    return stretched;
  }
  const double tolerance = kStretchFeasibility * norm(toFinger);
  for (int k = 0; k < m_numPlanes; ++k)
  {
    if (dot(m_normals[k], stretched) < -tolerance)
    {
      return solution.displacement;
    }
  }
  return stretched;
}

namespace
{
// The radius of a plane's curved configuration-space surface (the distance from the proxy to the
// touched edge or corner), or infinity on a face.
double curvedRadius(const ContactPlane& plane)
{
  return plane.curved ? std::sqrt(plane.closest.squaredDistance)
                      : std::numeric_limits<double>::infinity();
}
} // namespace

double ProxySolver::curvatureAlong(const ContactPlane& plane, const Vec3& direction) const
{
  if (!plane.curved)
  {
    return 0.0; // a face: its configuration-space surface is its plane
  }
  const double rho = std::sqrt(plane.closest.squaredDistance);
  if (!(rho > 0.0))
  {
    return 0.0;
  }
  Vec3 from;
  Vec3 to;
  const TriangleCorners& corners = placedMesh(plane.object).corners(plane.triangle);
  if (!edgeOf(corners, plane.closest.feature, from, to) || !(squaredNorm(to - from) > 0.0))
  {
    return 1.0 / rho; // a corner's sphere bends the same way in every tangent direction
  }
  // An edge's cylinder is straight along its axis and bends by 1 / rho across it.
  const double along = dot(direction, to - from);
  return (1.0 - along * along / squaredNorm(to - from)) / rho;
}

Vec3 ProxySolver::stretchedCreaseSlide(const GoalSolution& solution, double stretchLimit) const
{
  // Two active planes: the planar slide runs along their crease line, the tangent of the curve
  // where the two configuration-space surfaces meet. Where one of them is an edge's cylinder or
  // a corner's sphere that curve bends, and tangent slides followed by the fall back onto it
  // creep along it: with the finger near the curve's centre of curvature (deep under an edge,
  // the bunny and liver probe paths) each cycle of two iterations advanced a few micrometres,
  // and ticks ran to 170-216 iterations. The Newton step along the crease divides the slide by
  // the Lagrangian's curvature there, 1 - sum mu_k kappa_k (mu_k: the depths, kappa_k: each
  // surface's curvature along the crease), capped at `stretchLimit` where that curvature
  // vanishes or turns.
  const Vec3 planar = solution.displacement;
  const ContactPlane& first = m_planes[solution.active[0]];
  const ContactPlane& second = m_planes[solution.active[1]];
  if (!first.curved && !second.curved)
  {
    return planar; // two faces meet in a straight line: the slide is exact
  }
  const double length = norm(planar);
  if (!(length > 0.0))
  {
    return planar;
  }
  const Vec3 crease = planar / length;
  const double hessian = 1.0 - solution.depth[0] * curvatureAlong(first, crease) -
                         solution.depth[1] * curvatureAlong(second, crease);
  if (!(stretchLimit > 1.0))
  {
    return planar;
  }
  double stretch = hessian > 1.0 / stretchLimit ? 1.0 / hessian : stretchLimit;
  // The tangent model holds near the proxy only: a stretched slide may go at most a quarter of
  // the smaller curved surface's radius (it then leaves that surface by a 32nd of the radius).
  // Unbounded, a 64-fold slide of 5 mm left the edge's neighbourhood for another local minimum,
  // and the tick ended farther from the finger than it began (shared bunny, wander path).
  const double reach = kCreaseStretchReach * std::min(curvedRadius(first), curvedRadius(second));
  if (length * stretch > reach)
  {
    stretch = std::max(1.0, reach / length);
  }
  return planar * stretch;
}

Vec3 ProxySolver::stretchedSlide(const GoalSolution& solution, const Vec3& toFinger,
                                 double creaseStretchLimit) const
{
  const Vec3 planar = solution.displacement;
  if (solution.numActive == 2)
  {
    return stretchedCreaseSlide(solution, creaseStretchLimit);
  }
  if (solution.numActive != 1)
  {
    return planar;
  }
  const ContactPlane& plane = m_planes[solution.active[0]];
  if (!plane.curved)
  {
    return planar; // a face's configuration-space surface is its plane: the slide is exact
  }
  // An edge or a corner: the configuration-space surface is a cylinder or a sphere of radius rho
  // about it, and the tangent plane's goal undershoots. The Lagrangian's Hessian along the curved
  // directions is 1 - h / rho (h: the finger's depth below the plane, the multiplier), so the
  // Newton step stretches the slide by 1 / (1 - h / rho): the slide then ends on the ray from the
  // edge (or corner) through the finger, and the next move falls onto the minimum.
  const double rho = std::sqrt(plane.closest.squaredDistance);
  const double depth = -dot(toFinger, plane.normal);
  if (!(rho > 0.0) || !(depth > 0.0))
  {
    return planar;
  }
  Vec3 from;
  Vec3 to;
  const TriangleCorners& corners = placedMesh(plane.object).corners(plane.triangle);
  Vec3 along;
  if (edgeOf(corners, plane.closest.feature, from, to))
  {
    along = to - from;
  }
  const double alongSquared = squaredNorm(along);
  // Along an edge the cylinder is straight: only the part across it is stretched (a corner, or
  // an edge of zero length, is curved in every tangent direction).
  const Vec3 straight = alongSquared > 0.0 ? along * (dot(planar, along) / alongSquared) : Vec3{};
  const double hessian = 1.0 - depth / rho;
  if (hessian > 1.0 / kMaxCurvatureStretch)
  {
    return straight + (planar - straight) * (1.0 / hessian);
  }
  // The finger is near the edge's axis (the corner itself), where the Hessian vanishes and the
  // quadratic model says nothing. Inside the cylinder (ball) the minimum is still where the ray
  // from the axis through the finger meets it: slide to that ray's crossing of the tangent plane
  // (where the stretched slide would end), so that the next move falls onto it. Without this
  // the plain slides creep: a finger 5 um from the apex of a narrow concave corner, the proxy
  // touching only the apex, took 2752 iterations (stress seed 6010).
  Vec3 across = toFinger + plane.normal * rho; // the finger seen from the touched feature
  if (alongSquared > 0.0)
  {
    across = across - along * (dot(across, along) / alongSquared);
  }
  const double offAxis = norm(across);
  if (!(offAxis < rho) || !(offAxis > 0.0))
  {
    // Past the axis no minimum lies on this arc, and on it every point is one: the plain slide
    // rolls the proxy over.
    return planar;
  }
  const Vec3 ray = across / offAxis;
  const double cosine = dot(ray, plane.normal);
  if (!(cosine > 1.0 / kMaxCurvatureStretch))
  {
    return planar; // the ray leaves on the far side of the axis, or nearly along the plane
  }
  return straight + ray * (rho / cosine) - plane.normal * rho;
}

} // namespace proxima
