// Image tests of the VTK layer: the representations of a haptic state (proxy, finger, spring,
// contact discs, friction cones, force) and the sphere-tree filter's drawing, rendered offscreen
// at 400x300 and compared with the baselines in Baselines/ (metric in ImageComparison.h). The
// states come from lockstep runs, so the pictures are the same on every run. Each case also
// checks the physics it draws (stuck or slipping, how many contacts), so a baseline cannot
// enshrine a wrong state.
#include "ImageComparison.h"
#include "VtkTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "VTK/LockstepStates.h"
#include "VTK/ScenePolyData.h"
#include "VTK/vtkHapticStateRepresentation.h"
#include "VTK/vtkHapticSphereTreeFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace
{
using namespace proxima;
using proxima::vtk::testing::compareWithBaseline;
using proxima::vtk::testing::linearPath;

const std::string kBaselines = std::string(PROXIMA_SOURCE_DIR) + "/Library/VTK/Testing/Baselines";
const std::string kOutput = PROXIMA_IMAGE_OUTPUT_DIR;

// Three squares meeting in a concave corner at the origin (floor z = 0, walls x = 0 and y = 0),
// each side `size`: pressing into the corner gives three constraint planes.
TriangleSoup concaveCorner(double size)
{
  TriangleSoup soup;
  auto square = [&](const Vec3& origin, const Vec3& u, const Vec3& v) {
    const auto first = static_cast<std::uint32_t>(soup.points.size());
    soup.points.push_back(origin);
    soup.points.push_back(origin + u * size);
    soup.points.push_back(origin + u * size + v * size);
    soup.points.push_back(origin + v * size);
    soup.triangles.push_back({first, first + 1, first + 2});
    soup.triangles.push_back({first, first + 2, first + 3});
  };
  square({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  square({0, 0, 0}, {0, 1, 0}, {0, 0, 1});
  square({0, 0, 0}, {0, 0, 1}, {1, 0, 0});
  return soup;
}

CollisionScene sceneOf(const TriangleSoup& soup, const SurfaceMaterial& material)
{
  CollisionScene scene;
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(soup, error));
  scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
  return scene;
}

// The first state for which `stop` is true (or the path's last).
HapticState stateWhere(const CollisionScene& scene, const FingerPath& path,
                       const std::function<bool(const HapticState&)>& stop)
{
  ProxyParameters parameters;
  parameters.radius = 0.001;
  parameters.timeStep = 0.001;
  ServoParameters servo;
  HapticState last;
  proxima::vtk::playLockstepStates(scene, parameters, servo, path, 1000.0,
                                   [&](const HapticState& state) {
                                     last = state;
                                     return !stop(state);
                                   });
  return last;
}

// One offscreen window with the scene's surface and the state drawn, seen from `eye`.
class StateImage
{
public:
  StateImage(const CollisionScene& scene, const HapticState& state, const Vec3& eye,
             const Vec3& focus)
  {
    m_mapper->SetInputData(proxima::vtk::scenePolyData(scene));
    m_surface->SetMapper(m_mapper);
    m_surface->GetProperty()->SetColor(0.75, 0.72, 0.68);
    m_renderer->AddActor(m_surface);
    m_representation->SetState(state);
    m_representation->SetForceScale(0.002);
    m_representation->AddToRenderer(m_renderer);
    m_renderer->SetBackground(0.12, 0.14, 0.18);
    m_renderer->GetActiveCamera()->SetPosition(eye.x, eye.y, eye.z);
    m_renderer->GetActiveCamera()->SetFocalPoint(focus.x, focus.y, focus.z);
    m_renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
    m_renderer->GetActiveCamera()->SetViewAngle(30.0);
    m_renderer->ResetCameraClippingRange();
    m_window->SetOffScreenRendering(1);
    m_window->SetMultiSamples(0);
    m_window->SetSize(400, 300);
    m_window->AddRenderer(m_renderer);
  }

  vtkRenderWindow* window() { return m_window; }
  vtkHapticStateRepresentation* representation() { return m_representation; }

private:
  vtkNew<vtkPolyDataMapper> m_mapper;
  vtkNew<vtkActor> m_surface;
  vtkNew<vtkRenderer> m_renderer;
  vtkNew<vtkRenderWindow> m_window;
  vtkNew<vtkHapticStateRepresentation> m_representation;
};

void expectMatches(vtkRenderWindow* window, const std::string& name)
{
  const auto comparison = compareWithBaseline(window, name, kBaselines, kOutput);
  EXPECT_TRUE(comparison.matches) << comparison.message;
}

SurfaceMaterial frictional()
{
  SurfaceMaterial material;
  material.staticFriction = 0.6;
  material.dynamicFriction = 0.4;
  return material;
}

TEST(RepresentationImages, StickingContactShowsAClosedCone)
{
  const CollisionScene scene = sceneOf(makeGrid(0.04, 8), frictional());
  // Press 2 mm in, then lean 0.4 mm sideways: tan = 0.2, inside the static cone (0.6).
  const FingerPath path = linearPath({{0, 0, 0.004}, {0, 0, -0.002}, {0.0004, 0, -0.002}}, 0.2);
  const HapticState state = stateWhere(scene, path, [](const HapticState&) { return false; });
  ASSERT_EQ(state.numContacts, 1);
  EXPECT_TRUE(state.conditions.has(TickCondition::stuck));
  StateImage image(scene, state, {0.012, -0.022, 0.012}, {0, 0, 0});
  expectMatches(image.window(), "sticking-contact");
}

TEST(RepresentationImages, SlippingContactShowsAnOpenCone)
{
  const CollisionScene scene = sceneOf(makeGrid(0.04, 8), frictional());
  // Press in, then drag 8 mm. With mu_s above mu_d the proxy sticks and slips in turn (each slip
  // leaves the finger on the dynamic cone, inside the static one): take the first slip of the
  // drag's second half.
  const FingerPath path = linearPath({{0, 0, 0.004}, {0, 0, -0.002}, {0.008, 0, -0.002}}, 0.2);
  const HapticState state = stateWhere(scene, path, [](const HapticState& s) {
    return s.time > 0.3 && s.numContacts == 1 && !s.conditions.has(TickCondition::stuck);
  });
  EXPECT_GT(state.time, 0.3);
  ASSERT_EQ(state.numContacts, 1);
  EXPECT_FALSE(state.conditions.has(TickCondition::stuck));
  // Sliding with dynamic friction: the finger rides the dynamic cone's rim, its offset along
  // the surface mu_d times its depth below the proxy (paper 4.2).
  EXPECT_NEAR(state.finger.x - state.proxy.x, 0.4 * (state.proxy.z - state.finger.z), 1e-5);
  StateImage image(scene, state, {0.012, -0.022, 0.012}, {0.006, 0, 0});
  expectMatches(image.window(), "slipping-contact");
}

TEST(RepresentationImages, ConcaveCornerShowsThreeContactPlanes)
{
  const CollisionScene scene = sceneOf(concaveCorner(0.02), SurfaceMaterial{});
  const FingerPath path = linearPath({{0.008, 0.008, 0.008}, {-0.001, -0.001, -0.001}}, 0.3);
  const HapticState state = stateWhere(scene, path, [](const HapticState&) { return false; });
  ASSERT_EQ(state.numContacts, 3);
  EXPECT_NEAR(state.proxy.x, 0.001, 1e-6);
  EXPECT_NEAR(state.proxy.y, 0.001, 1e-6);
  EXPECT_NEAR(state.proxy.z, 0.001, 1e-6);
  StateImage image(scene, state, {0.016, 0.012, 0.01}, {0.001, 0.001, 0.001});
  expectMatches(image.window(), "concave-corner");
}

TEST(RepresentationImages, SphereTreeLevelCoversTheMesh)
{
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(proxima::vtk::testing::polyDataOf(makeIcosphere(3, 0.01)));
  filter->SetLevel(4);
  filter->Update();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(filter->GetOutputPort());
  mapper->SetScalarRange(filter->GetOutput()->GetCellData()->GetScalars()->GetRange());
  vtkNew<vtkActor> spheres;
  spheres->SetMapper(mapper);
  spheres->GetProperty()->SetOpacity(0.5);
  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputData(proxima::vtk::testing::polyDataOf(makeIcosphere(3, 0.01)));
  vtkNew<vtkActor> surface;
  surface->SetMapper(surfaceMapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(surface);
  renderer->AddActor(spheres);
  renderer->SetBackground(0.12, 0.14, 0.18);
  renderer->GetActiveCamera()->SetPosition(0.03, -0.04, 0.03);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  expectMatches(window, "sphere-tree-level-4");
}

} // namespace
