#include "InspectorWindow.h"

#include "IO/MeshInspection/InspectionReport.h"
#include "IO/Output/AtomicOutputFile.h"
#include "Overlay/ProbeOverlay.h"
#include "Overlay/SphereTreeLevelActor.h"
#include "Probing/ProbeReport.h"

#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <vtkActor.h>
#include <vtkRenderer.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>

namespace proxima::inspector
{
namespace
{
// The probe's meter for a tool: a stop is the finger half the tool's radius beyond the proxy.
ProbeMeterSettings meterSettings(double radius)
{
  ProbeMeterSettings settings;
  settings.stopDepth = 0.5 * radius;
  return settings;
}

// The report lists the first few of each defect, as `proxima inspect` does by default; the
// window's own inspection keeps them all to draw them.
MeshInspection firstFew(MeshInspection inspection, std::size_t kept)
{
  for (DefectCount* defect :
       {&inspection.boundaryEdges, &inspection.boundaryLoops, &inspection.nonManifoldEdges,
        &inspection.misorientedEdges, &inspection.collapsedTriangles, &inspection.zeroAreaTriangles,
        &inspection.sliverTriangles, &inspection.duplicateTriangles, &inspection.selfIntersections,
        &inspection.folds})
  {
    if (defect->first.size() > kept)
    {
      defect->first.resize(kept);
    }
  }
  return inspection;
}

std::string defectsLine(const MeshInspection& r)
{
  char line[400];
  std::snprintf(
    line, sizeof line,
    "%s, %zu triangles: %zu holes (%zu boundary edges), %zu non-manifold, %zu "
    "misoriented,\n%zu self-intersecting pairs, %zu folds, %zu degenerate, %zu duplicate",
    r.closed ? "closed" : "open", r.triangles, r.boundaryLoops.count, r.boundaryEdges.count,
    r.nonManifoldEdges.count, r.misorientedEdges.count, r.selfIntersections.count, r.folds.count,
    r.collapsedTriangles.count + r.zeroAreaTriangles.count, r.duplicateTriangles.count);
  return line;
}
} // namespace

InspectorWindow::InspectorWindow(InspectorPart part, const shell::HapticWindowSettings& settings,
                                 QWidget* parent)
  : shell::HapticWindow(settings, parent)
  , m_part(std::move(part))
  , m_defects(renderer())
  , m_probeOverlay(std::make_unique<ProbeOverlay>(renderer(), 0.6 * settings.radius))
  , m_meter(std::make_unique<ProbeMeter>(*settings.scene, meterSettings(settings.radius)))
{
  buildInspectMenu();
  connect(&m_analysisTimer, &QTimer::timeout, this, &InspectorWindow::pollAnalysis);
  m_analysisTimer.start(50);
  startAnalysis();
}

InspectorWindow::~InspectorWindow()
{
  // The analysis reads the part: it ends before the part goes.
  if (m_analysis.valid())
  {
    m_analysis.wait();
  }
}

void InspectorWindow::buildInspectMenu()
{
  QMenu* inspect = menuBar()->addMenu(tr("&Inspect"));
  QAction* marker = inspect->addAction(tr("Drop a &marker where the probe touches"));
  marker->setObjectName("dropMarker");
  marker->setShortcut(QKeySequence(Qt::Key_M));
  connect(marker, &QAction::triggered, this, [this] {
    if (!dropMarker())
    {
      statusBar()->showMessage(tr("No marker: the probe touches nothing"), 5000);
    }
  });
  QAction* clear = inspect->addAction(tr("&Clear the markers, gap and stops"));
  connect(clear, &QAction::triggered, this, &InspectorWindow::clearProbe);
  inspect->addSeparator();
  QAction* radius = inspect->addAction(tr("Tool &radius..."));
  radius->setShortcut(QKeySequence(Qt::Key_R));
  connect(radius, &QAction::triggered, this, &InspectorWindow::askToolRadius);
  QAction* defects = inspect->addAction(tr("Show the &defects"));
  defects->setObjectName("showDefects");
  defects->setCheckable(true);
  defects->setChecked(true);
  defects->setShortcut(QKeySequence(Qt::Key_D));
  connect(defects, &QAction::toggled, this,
          [this](bool visible) { m_defects.setDefectsVisible(visible); });
  QAction* reach = inspect->addAction(tr("Show where the tool cannot reac&h"));
  reach->setObjectName("showReach");
  reach->setCheckable(true);
  reach->setChecked(true);
  reach->setShortcut(QKeySequence(Qt::Key_U));
  connect(reach, &QAction::toggled, this,
          [this](bool visible) { m_defects.setReachVisible(visible); });
  QMenu* levels = inspect->addMenu(tr("Sphere &tree level"));
  auto* levelGroup = new QActionGroup(this);
  const int depth = static_cast<int>(sphereTreeDepth(*settings().scene));
  for (int level = -1; level <= std::min(depth, 16); ++level)
  {
    QAction* action = levels->addAction(level < 0 ? tr("None") : tr("Level %1").arg(level));
    action->setCheckable(true);
    action->setChecked(level < 0);
    levelGroup->addAction(action);
    connect(action, &QAction::triggered, this, [this, level] { showSphereTreeLevel(level); });
  }

  QMenu* file = menuBar()->actions().front()->menu();
  QAction* exportAction = new QAction(tr("&Export the report..."), this);
  exportAction->setShortcut(QKeySequence("Ctrl+E"));
  connect(exportAction, &QAction::triggered, this, &InspectorWindow::exportAs);
  file->insertAction(file->actions().front(), exportAction);
  QAction* open = new QAction(tr("&Open a part..."), this);
  open->setShortcut(QKeySequence("Ctrl+O"));
  connect(open, &QAction::triggered, this, &InspectorWindow::openPart);
  file->insertAction(exportAction, open);
}

void InspectorWindow::startAnalysis()
{
  if (m_analysis.valid())
  {
    // One analysis at a time: the one running gives its inspection to the next (a failure is
    // the next one's to report).
    try
    {
      Analysis previous = m_analysis.get();
      if (previous.inspection)
      {
        m_inspection = std::move(previous.inspection);
        m_defects.showDefects(m_part.soup, *m_inspection);
      }
    }
    catch (const std::exception&)
    {}
  }
  m_reach.reset();
  m_analysisDone = 0.0;
  const std::optional<MeshInspection> known = m_inspection;
  const double radius = proxyRadius();
  const TriangleSoup* soup = &m_part.soup;
  std::atomic<double>* done = &m_analysisDone;
  // The part's own mesh and tree, built once with the window's scene (one object).
  const std::shared_ptr<const CollisionScene> scene = settings().scene;
  m_analysis = std::async(std::launch::async, [soup, radius, known, done, scene] {
    Analysis analysis;
    const double share = known ? 0.0 : 0.5;
    if (!known)
    {
      MeshInspectionOptions options;
      options.locationsKept = std::numeric_limits<std::size_t>::max();
      options.progress = [done](double fraction) { *done = 0.5 * fraction; };
      analysis.inspection = inspectMesh(*soup, options);
    }
    const MeshInspection& inspection = known ? *known : *analysis.inspection;
    ToolReachOptions reach;
    reach.toolRadius = radius;
    reach.progress = [done, share](double fraction) { *done = share + (1.0 - share) * fraction; };
    const CollisionObject& part = scene->objects[0];
    analysis.reach =
      findToolReach(*soup, part.mesh, part.tree,
                    inspection.closed && inspection.misorientedEdges.count == 0, reach);
    return analysis;
  });
}

void InspectorWindow::pollAnalysis()
{
  if (!m_analysis.valid())
  {
    return;
  }
  if (m_analysis.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
  {
    statusBar()->showMessage(
      tr("Inspecting the part: %1%").arg(static_cast<int>(100.0 * m_analysisDone.load())));
    return;
  }
  try
  {
    Analysis analysis = m_analysis.get();
    if (analysis.inspection)
    {
      m_inspection = std::move(analysis.inspection);
      m_defects.showDefects(m_part.soup, *m_inspection);
    }
    m_reach = std::move(analysis.reach);
    m_defects.showReach(m_part.soup, *m_reach);
    statusBar()->showMessage(QString::fromStdString(defectsLine(*m_inspection)).replace('\n', ' '),
                             15000);
  }
  catch (const std::exception& failure)
  {
    statusBar()->showMessage(tr("The part could not be inspected: %1").arg(failure.what()));
  }
}

bool InspectorWindow::dropMarker()
{
  if (!m_ticked)
  {
    return false;
  }
  const bool dropped = m_meter->mark();
  m_probeOverlay->update(m_meter->measurements());
  return dropped;
}

void InspectorWindow::clearProbe()
{
  m_meter = std::make_unique<ProbeMeter>(*settings().scene, meterSettings(proxyRadius()));
  m_ticked = false;
  m_probeOverlay->update(m_meter->measurements());
}

bool InspectorWindow::setToolRadius(double radius, std::string& error)
{
  if (!setProxyRadius(radius, error))
  {
    return false;
  }
  // Another tool is another probing session; its reach is found again.
  m_probeOverlay->setMarkerRadius(0.6 * radius);
  clearProbe();
  startAnalysis();
  return true;
}

std::size_t InspectorWindow::showSphereTreeLevel(int level)
{
  if (m_treeLevel)
  {
    renderer()->RemoveActor(m_treeLevel);
    m_treeLevel = nullptr;
  }
  std::size_t spheres = 0;
  if (level >= 0)
  {
    m_treeLevel =
      makeSphereTreeLevelActor(*settings().scene, static_cast<std::uint32_t>(level), spheres);
    renderer()->AddActor(m_treeLevel);
  }
  return spheres;
}

void InspectorWindow::ticksArrived(const std::vector<HapticState>& ticks)
{
  for (const HapticState& tick : ticks)
  {
    m_meter->addTick(tick);
    m_ticked = true;
  }
  if (!ticks.empty())
  {
    m_probeOverlay->update(m_meter->measurements());
  }
}

void InspectorWindow::sessionRestarted()
{
  // The markers stay where they were dropped: a device change does not move the part.
}

std::string InspectorWindow::hudLines(const HapticState& /*state*/) const
{
  const ProbeMeasurements& m = m_meter->measurements();
  char line[300];
  std::string text;
  std::snprintf(line, sizeof line, "tool r %.3f mm   markers %zu", proxyRadius() * 1000.0,
                m.markers.size());
  text += line;
  if (!m.distances.empty())
  {
    std::snprintf(line, sizeof line, "   last two %.3f mm apart (across %.3f mm)",
                  m.distances.back().distance * 1000.0, m.distances.back().across * 1000.0);
    text += line;
  }
  if (m.narrowestGap)
  {
    std::snprintf(line, sizeof line, "   narrowest gap %.3f mm", m.narrowestGap->width * 1000.0);
    text += line;
  }
  std::snprintf(line, sizeof line, "   stops %zu", m.stopCount);
  text += line;
  if (m_inspection)
  {
    text += "\n" + defectsLine(*m_inspection);
  }
  if (m_reach)
  {
    std::snprintf(line, sizeof line,
                  "\na %.3f mm tool cannot touch %.2f%% of the area (%zu regions)",
                  m_reach->toolRadius * 1000.0,
                  m_reach->area > 0.0 ? 100.0 * m_reach->unreachableArea / m_reach->area : 0.0,
                  m_reach->regionCount);
    text += line;
  }
  else
  {
    std::snprintf(line, sizeof line, "\ninspecting the part: %.0f%%",
                  100.0 * m_analysisDone.load());
    text += line;
  }
  return text;
}

bool InspectorWindow::exportReport(const std::string& path, std::string& error)
{
  if (!analysisReady())
  {
    error = "the part is still being inspected: export when the status bar says it is done";
    return false;
  }
  std::filesystem::path picture(path);
  if (picture.extension() == ".png" || picture.extension() == ".PNG")
  {
    error = path + ": the report is JSON; its screenshot goes beside it as .png";
    return false;
  }
  picture.replace_extension(".png");
  try
  {
    nlohmann::ordered_json json;
    json["format"] = "proxima-inspector-report";
    json["version"] = 1;
    json["mesh"] = m_part.file;
    json["scale"] = m_part.scale;
    json["vertex_merging"] = "identical coordinates";
    json["defects"] = meshInspectionJson(firstFew(*m_inspection, 10));
    json["tool_reach"] = toolReachJson(*m_reach);
    json["probe"] = probeMeasurementsJson(m_meter->measurements());
    json["screenshot"] = picture.filename().string();
    // Both finished before either is put in place: one failing leaves neither.
    AtomicOutputFile report(path);
    AtomicOutputFile screenshot(picture.string());
    screenshot.write(screenshotPng(picture.string()));
    report.write(json.dump(2) + "\n");
    screenshot.finish();
    report.finish();
    screenshot.commit();
    report.commit();
    return true;
  }
  catch (const std::exception& failure)
  {
    error = failure.what();
    return false;
  }
}

void InspectorWindow::askToolRadius()
{
  bool chosen = false;
  const double millimetres =
    QInputDialog::getDouble(this, tr("Tool radius"), tr("The probe's and the tool's radius (mm):"),
                            proxyRadius() * 1000.0, 0.001, 1000.0, 3, &chosen);
  if (!chosen)
  {
    return;
  }
  std::string error;
  if (!setToolRadius(millimetres / 1000.0, error))
  {
    QMessageBox::warning(this, windowTitle(), QString::fromStdString(error));
  }
}

void InspectorWindow::exportAs()
{
  const QString file = QFileDialog::getSaveFileName(
    this, tr("Export the report"), "inspection-report.json", tr("Reports (*.json)"));
  if (file.isEmpty())
  {
    return;
  }
  std::string error;
  if (!exportReport(file.toStdString(), error))
  {
    QMessageBox::warning(this, windowTitle(), QString::fromStdString(error));
  }
}

void InspectorWindow::openPart()
{
  const QString file = QFileDialog::getOpenFileName(
    this, tr("Open a part"), QString(),
    tr("Meshes (*.stl *.STL *.obj *.OBJ *.ply *.PLY *.off *.OFF *.gltf *.glb *.vtp)"));
  if (file.isEmpty())
  {
    return;
  }
  // The files carry no units: the scale turns them into metres (0.001 for millimetres).
  bool chosen = false;
  const double scale =
    QInputDialog::getDouble(this, tr("Scale"), tr("Metres per unit of the file (0.001 for mm):"),
                            m_part.scale, 1e-9, 1e9, 9, &chosen);
  if (chosen)
  {
    emit partRequested(file, scale);
  }
}

} // namespace proxima::inspector
