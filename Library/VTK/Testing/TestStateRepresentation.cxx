// vtkHapticStateRepresentation without a window: the geometry of each part checked against the
// state it draws (the cone's apex and half-angle, the disc on the contact plane, the arrow along
// the force, the spring between finger and proxy), and parts without a subject hidden.
#include "VTK/vtkHapticStateRepresentation.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkLinearTransform.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkProp3D.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace proxima;

vtkPolyData* geometryOf(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  mapper->GetInputAlgorithm()->Update();
  return vtkPolyData::SafeDownCast(mapper->GetInputAlgorithm()->GetOutputDataObject(0));
}

HapticState contactState(bool stuck)
{
  HapticState state;
  state.proxyRadius = 0.001;
  state.proxy = {0.0, 0.0, 0.001};
  state.finger = {0.0003, 0.0, -0.002};
  state.force = (state.proxy - state.finger) * 1000.0;
  state.numContacts = 1;
  state.contacts[0].point = {0.0, 0.0, 0.0};
  const double s = std::sqrt(0.5);
  state.contacts[0].normal = {0.0, s, s};
  state.contacts[0].staticFriction = 0.6;
  state.contacts[0].dynamicFriction = 0.3;
  state.conditions.set(TickCondition::stuck, stuck);
  return state;
}

// The largest angle between the normal and (point - apex), over the cone's points off the apex.
double largestAngle(vtkPolyData* cone, const Vec3& apex, const Vec3& normal, int& apexPoints)
{
  double largest = 0.0;
  apexPoints = 0;
  for (vtkIdType i = 0; i < cone->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cone->GetPoint(i, p);
    const Vec3 d = Vec3{p[0], p[1], p[2]} - apex;
    if (norm(d) < 1e-12)
    {
      ++apexPoints;
      continue;
    }
    largest = std::max(largest, std::acos(std::clamp(dot(d, normal) / norm(d), -1.0, 1.0)));
  }
  return largest;
}

TEST(StateRepresentation, StickingConeIsClosedAtTheStaticAngle)
{
  vtkNew<vtkHapticStateRepresentation> representation;
  const HapticState state = contactState(true);
  representation->SetState(state);
  vtkActor* cone = representation->GetFrictionConeActor(0);
  ASSERT_TRUE(cone->GetVisibility());
  vtkPolyData* geometry = geometryOf(cone);
  int apexPoints = 0;
  const double angle =
    largestAngle(geometry, state.contacts[0].point, state.contacts[0].normal, apexPoints);
  EXPECT_EQ(apexPoints, 1);
  EXPECT_NEAR(angle, std::atan(0.6), 1e-9);
  // Closed: a cap polygon beside the side triangles.
  EXPECT_EQ(geometry->GetNumberOfPolys(), 32 + 1);
}

TEST(StateRepresentation, SlippingConeIsOpenAtTheDynamicAngle)
{
  vtkNew<vtkHapticStateRepresentation> representation;
  const HapticState state = contactState(false);
  representation->SetState(state);
  vtkPolyData* geometry = geometryOf(representation->GetFrictionConeActor(0));
  int apexPoints = 0;
  EXPECT_NEAR(largestAngle(geometry, state.contacts[0].point, state.contacts[0].normal, apexPoints),
              std::atan(0.3), 1e-9);
  EXPECT_EQ(geometry->GetNumberOfPolys(), 32);
}

TEST(StateRepresentation, DiscLiesOnTheContactPlane)
{
  vtkNew<vtkHapticStateRepresentation> representation;
  representation->SetContactDiscRadius(0.005);
  const HapticState state = contactState(true);
  representation->SetState(state);
  vtkPolyData* disc = geometryOf(representation->GetContactDiscActor(0));
  ASSERT_GT(disc->GetNumberOfPoints(), 8);
  for (vtkIdType i = 0; i < disc->GetNumberOfPoints(); ++i)
  {
    double p[3];
    disc->GetPoint(i, p);
    const Vec3 d = Vec3{p[0], p[1], p[2]} - state.contacts[0].point;
    // On the plane, but for the lift of 2% of a proxy radius that keeps it out of the surface.
    EXPECT_NEAR(dot(d, state.contacts[0].normal), 0.02 * state.proxyRadius, 1e-12);
    const Vec3 inPlane = d - state.contacts[0].normal * dot(d, state.contacts[0].normal);
    EXPECT_NEAR(norm(inPlane), 0.005, 1e-9);
  }
}

TEST(StateRepresentation, ArrowRunsAlongTheForceFromTheProxy)
{
  vtkNew<vtkHapticStateRepresentation> representation;
  representation->SetForceScale(0.001);
  const HapticState state = contactState(true);
  representation->SetState(state);
  vtkActor* arrow = representation->GetForceActor();
  ASSERT_TRUE(arrow->GetVisibility());
  // The arrow's unit +x, carried by the actor's transform, lands at proxy + scale * force.
  vtkLinearTransform* transform = vtkLinearTransform::SafeDownCast(arrow->GetUserTransform());
  ASSERT_NE(transform, nullptr);
  double origin[3];
  double tip[3];
  const double zero[3] = {0, 0, 0};
  const double unitX[3] = {1, 0, 0};
  transform->TransformPoint(zero, origin);
  transform->TransformPoint(unitX, tip);
  const Vec3 expectedTip = state.proxy + state.force * 0.001;
  EXPECT_NEAR(origin[0], state.proxy.x, 1e-12);
  EXPECT_NEAR(origin[2], state.proxy.z, 1e-12);
  EXPECT_NEAR(tip[0], expectedTip.x, 1e-12);
  EXPECT_NEAR(tip[1], expectedTip.y, 1e-12);
  EXPECT_NEAR(tip[2], expectedTip.z, 1e-12);
}

TEST(StateRepresentation, PartsWithoutASubjectAreHidden)
{
  vtkNew<vtkHapticStateRepresentation> representation;
  HapticState state = contactState(true);
  state.contacts[0].staticFriction = 0.0;
  state.contacts[0].dynamicFriction = 0.0;
  representation->SetState(state);
  EXPECT_TRUE(representation->GetContactDiscActor(0)->GetVisibility());
  EXPECT_FALSE(representation->GetFrictionConeActor(0)->GetVisibility());
  EXPECT_FALSE(representation->GetContactDiscActor(1)->GetVisibility());

  HapticState free;
  free.proxyRadius = 0.001;
  free.proxy = free.finger = {0.01, 0.02, 0.03};
  representation->SetState(free);
  EXPECT_TRUE(representation->GetProxyActor()->GetVisibility());
  EXPECT_FALSE(representation->GetSpringActor()->GetVisibility());
  EXPECT_FALSE(representation->GetForceActor()->GetVisibility());
  EXPECT_FALSE(representation->GetContactDiscActor(0)->GetVisibility());
  vtkPolyData* proxy = geometryOf(representation->GetProxyActor());
  double bounds[6];
  proxy->GetBounds(bounds);
  EXPECT_NEAR(0.5 * (bounds[0] + bounds[1]), 0.01, 1e-9);
  EXPECT_NEAR(bounds[5] - bounds[4], 0.002, 1e-5);
}

} // namespace
