// The inspector's window under Xvfb (QTest):
//   - on the cracked CAD part (featuretype.STL, shared), the defects found off the window's
//     thread are drawn, every one the headless inspection counts, and where a 1 mm tool cannot
//     reach;
//   - on two blocks with a 2 mm slot (gap-blocks.obj), a finger path replayed through the threaded
//     runtime probes the slot: markers dropped on the facing walls are 2 mm apart, the narrowest
//     gap passed through is 2 mm, and the export writes the report with its screenshot (and
//     nothing when it cannot);
//   - a tool wider than the slot cannot reach its walls: the four facing triangles are drawn;
//     the sphere tree shows at a level.
// Nothing here asserts on speed: waits have generous deadlines and end as soon as the state is
// reached.
#include "InspectorWindow.h"

#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Overlay/SphereTreeLevelActor.h"
#include "WindowTesting.h"

#include <QAction>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTest>
#include <QVTKOpenGLNativeWidget.h>

#include <nlohmann/json.hpp>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <set>

namespace
{
using namespace proxima;
using namespace proxima::inspector;
using proxima::shell::testing::waitUntil;
using proxima::shell::testing::writePathAsRecording;

const std::string kTesting = PROXIMA_SOURCE_DIR "/Apps/inspector/Testing";
const std::string kOutput = PROXIMA_TEST_OUTPUT;
const std::string kFeaturetype = PROXIMA_SHARED_MESHES "/featuretype.STL";

std::unique_ptr<InspectorWindow> openPart(const std::string& file, double scale, double radius)
{
  InspectorPart part{file, scale, readMeshFile(file, scale)};
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(part.soup, error))
  {
    return nullptr;
  }
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(std::move(mesh));
  shell::HapticWindowSettings settings;
  settings.title = "inspector test";
  settings.scene = scene;
  settings.radius = radius;
  settings.stiffness = 1000.0;
  settings.width = 800;
  settings.height = 600;
  auto window = std::make_unique<InspectorWindow>(std::move(part), settings);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get()))
  {
    return nullptr;
  }
  return window;
}

// With PROXIMA_INSPECTOR_FIGURES=FOLDER the window is also saved as FOLDER/NAME: the pictures of
// Documentation/CadInspector.md come from these runs.
void saveFigure(QWidget* window, const char* name)
{
  proxima::shell::testing::saveFigure(window, "PROXIMA_INSPECTOR_FIGURES", name);
}

// gap-probe.csv as a device recording at 1 kHz, for a replay device; empty if not written.
std::string slotProbeRecording()
{
  const std::string file = kOutput + "/gap-probe-recording.csv";
  std::string error;
  return writePathAsRecording(readFingerPathFile(kTesting + "/gap-probe.csv"), 1000.0, file, error)
           ? file
           : std::string();
}
} // namespace

class InspectorWindowTest : public QObject
{
  Q_OBJECT

private slots:
  void drawsEveryDefectOfTheCrackedPart()
  {
    // Shipped (Data/Meshes): absent is a broken tree, not a skip.
    QVERIFY2(std::filesystem::exists(kFeaturetype), "featuretype.STL is absent from the test data");
    auto window = openPart(kFeaturetype, 0.01, 0.001);
    QVERIFY(window != nullptr);
    QVERIFY2(waitUntil([&] { return window->analysisReady(); }, 120.0), "no analysis");
    // The headless inspection of the same file, with every place listed.
    MeshInspectionOptions all;
    all.locationsKept = ~std::size_t{0};
    const MeshInspection expected = inspectMesh(readMeshFile(kFeaturetype, 0.01), all);
    const MeshInspection& found = *window->inspection();
    QCOMPARE(found.boundaryEdges.count, expected.boundaryEdges.count);
    QVERIFY(expected.boundaryEdges.count > 0);
    QCOMPARE(found.selfIntersections.count, expected.selfIntersections.count);
    const DefectOverlay::Drawn drawn = window->drawnDefects();
    QCOMPARE(static_cast<std::size_t>(drawn.boundaryEdges), expected.boundaryEdges.count);
    QCOMPARE(static_cast<std::size_t>(drawn.nonManifoldEdges), expected.nonManifoldEdges.count);
    QCOMPARE(static_cast<std::size_t>(drawn.misorientedEdges), expected.misorientedEdges.count);
    std::set<std::uint32_t> crossing;
    for (const DefectCount* pairs : {&expected.selfIntersections, &expected.folds})
    {
      for (const DefectLocation& pair : pairs->first)
      {
        crossing.insert(pair.triangle);
        crossing.insert(pair.other);
      }
    }
    QCOMPARE(static_cast<std::size_t>(drawn.selfIntersectingTriangles), crossing.size());
    QCOMPARE(static_cast<std::size_t>(drawn.unreachableTriangles),
             window->reach()->unreachableTriangles.size());
    QVERIFY(drawn.unreachableTriangles > 0);
    // The HUD shows it from the next frame on.
    const std::string holes =
      "holes (" + std::to_string(expected.boundaryEdges.count) + " boundary edges)";
    QVERIFY2(waitUntil([&] { return window->hudText().find(holes) != std::string::npos; }, 5.0),
             window->hudText().c_str());
    QTest::qWait(200);
    saveFigure(window.get(), "inspector-window-reach.png");
    auto* showReach = window->findChild<QAction*>("showReach");
    QVERIFY(showReach != nullptr);
    showReach->setChecked(false);
    // Its holes' cracked rims and crossing triangles are on its underside: seen from below.
    vtkCamera* camera =
      window->view()->renderWindow()->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
    double position[3];
    double focus[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focus);
    camera->SetPosition(position[0], position[1], 2.0 * focus[2] - position[2]);
    camera->OrthogonalizeViewUp();
    QTest::qWait(200);
    saveFigure(window.get(), "inspector-window-defects.png");
  }

  void probesTheSlotByTouchAndExportsTheReport()
  {
    auto window = openPart(kTesting + "/gap-blocks.obj", 0.001, 0.0005);
    QVERIFY(window != nullptr);
    const std::string recording = slotProbeRecording();
    QVERIFY(!recording.empty());
    std::string error;
    QVERIFY2(window->useDevice("replay:" + recording, error), error.c_str());
    // Pushed into the left wall, then the right one (gap-probe.csv): a marker on each. A marker
    // is the touched point of the last tick the window has measured, which lags the servo's
    // newest state by up to a frame: the press must have reached the meter too (its stop begun)
    // while the newest state is still deep in it.
    const auto pressedInto = [&](double side, std::size_t stops) {
      const HapticState state = window->latestState();
      return window->measurements().stopCount >= stops && state.numContacts > 0 &&
             side * state.proxy.x > 0.0004 && norm(state.finger - state.proxy) > 0.002;
    };
    QVERIFY2(waitUntil([&] { return pressedInto(-1.0, 1); }, 60.0), window->hudText().c_str());
    auto* marker = window->findChild<QAction*>("dropMarker");
    QVERIFY(marker != nullptr);
    QCOMPARE(marker->shortcut(), QKeySequence(Qt::Key_M));
    marker->trigger();
    QVERIFY2(waitUntil([&] { return pressedInto(1.0, 2); }, 60.0), window->hudText().c_str());
    marker->trigger();
    const ProbeMeasurements& m = window->measurements();
    QCOMPARE(m.markers.size(), std::size_t{2});
    QVERIFY2(std::abs(m.distances.at(0).distance - 0.002) < 1e-9,
             std::to_string(m.distances.at(0).distance).c_str());
    QVERIFY(std::abs(m.distances.at(0).across - 0.002) < 1e-9);
    QVERIFY(m.narrowestGap.has_value());
    QVERIFY2(std::abs(m.narrowestGap->width - 0.002) < 1e-9,
             std::to_string(m.narrowestGap->width).c_str());
    QVERIFY(m.stopCount >= 2);
    QVERIFY(waitUntil([&] { return window->analysisReady(); }, 60.0));
    QVERIFY2(waitUntil(
               [&] {
                 return window->hudText().find("last two 2.000 mm apart (across 2.000 mm)   "
                                               "narrowest gap 2.000 mm") != std::string::npos;
               },
               5.0),
             window->hudText().c_str());
    if (!qgetenv("PROXIMA_INSPECTOR_FIGURES").isEmpty())
    {
      // Closer, and from above the slot's mouth, for the figure.
      vtkCamera* camera =
        window->view()->renderWindow()->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
      camera->Elevation(20.0);
      camera->Azimuth(-25.0);
      camera->OrthogonalizeViewUp();
      camera->Dolly(1.6);
      QTest::qWait(300);
      saveFigure(window.get(), "inspector-window-clearance.png");
    }

    const std::string report = kOutput + "/slot-report.json";
    const std::string picture = kOutput + "/slot-report.png";
    std::filesystem::remove(report);
    std::filesystem::remove(picture);
    QVERIFY2(window->exportReport(report, error), error.c_str());
    std::ifstream in(report);
    const nlohmann::json json = nlohmann::json::parse(in);
    QCOMPARE(json["format"].get<std::string>(), std::string("proxima-inspector-report"));
    QVERIFY(std::abs(json["probe"]["distances"][0]["distance"].get<double>() - 0.002) < 1e-9);
    QCOMPARE(json["defects"]["closed"].get<bool>(), true);
    QCOMPARE(json["screenshot"].get<std::string>(), std::string("slot-report.png"));
    std::ifstream png(picture, std::ios::binary);
    char signature[8] = {};
    png.read(signature, 8);
    QVERIFY(std::string(signature + 1, 3) == "PNG");
    // A report that cannot be written is an error, and neither file is left.
    QVERIFY(!window->exportReport(kOutput + "/no-such-folder/report.json", error));
    QVERIFY(!std::filesystem::exists(kOutput + "/no-such-folder"));
  }

  void aToolWiderThanTheSlotCannotReachItsWalls()
  {
    auto window = openPart(kTesting + "/gap-blocks.obj", 0.001, 0.0005);
    QVERIFY(window != nullptr);
    QVERIFY(waitUntil([&] { return window->analysisReady(); }, 60.0));
    QCOMPARE(window->reach()->unreachableTriangles.size(), std::size_t{0});
    std::string error;
    QVERIFY2(window->setToolRadius(0.0012, error), error.c_str());
    QVERIFY(waitUntil([&] { return window->analysisReady(); }, 60.0));
    // The two facing walls, two triangles each.
    QCOMPARE(window->reach()->unreachableTriangles.size(), std::size_t{4});
    QCOMPARE(window->drawnDefects().unreachableTriangles, 4LL);
    QCOMPARE(window->proxyRadius(), 0.0012);
    // The tree of the same part built apart: its spheres at level 1.
    TriangleMesh mesh;
    MeshError meshError;
    QVERIFY(mesh.build(readMeshFile(kTesting + "/gap-blocks.obj", 0.001), meshError));
    SphereTree tree;
    tree.build(mesh);
    const std::size_t expected = tree.spheresAtLevel(1).size();
    QCOMPARE(window->showSphereTreeLevel(1), expected);
    QVERIFY(expected > 0);
    QCOMPARE(window->showSphereTreeLevel(-1), std::size_t{0});
  }
};

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  qputenv("PROXIMA_NO_DIALOGS", "1");
  QApplication application(argc, argv);
  std::filesystem::create_directories(kOutput);
  InspectorWindowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestInspectorWindow.moc"
