// The CAD inspector's window (Documentation/CadInspector.md): the applications' Qt shell
// (HapticWindow) with a part in it, probed by the proxy at the tool's radius. On opening, the
// part's defects and the tool's reach are found off the window's thread (progress in the status
// bar) and drawn on it (Overlay/DefectOverlay). Every servo tick the runtime streams goes through
// the same ProbeMeter as the headless sessions: markers dropped where the proxy touches (M), the
// distances between them, the narrowest gap passed through and where the probe stopped are drawn
// and written in the HUD. The Inspect menu sets the tool's radius (the proxy's too, and the reach
// found again), shows or hides the defects and the reach, and shows the sphere tree at a level;
// File > Export writes the report (JSON) with a screenshot beside it; File > Open a part asks for
// another part and its scale.
#pragma once

#include "HapticWindow.h"
#include "IO/MeshInspection/MeshInspection.h"
#include "IO/MeshInspection/ToolReach.h"
#include "Overlay/DefectOverlay.h"
#include "Probing/ProbeMeter.h"

#include <QTimer>

#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <string>

class vtkActor;

namespace proxima::inspector
{

class ProbeOverlay;

/// The part the window opens: read from `file` at `scale`.
struct InspectorPart
{
  std::string file;
  double scale = 1.0;
  TriangleSoup soup;
};

class InspectorWindow : public shell::HapticWindow
{
  Q_OBJECT

public:
  /// `settings.scene` is the part's (one object, built from `part.soup`); `settings.radius` the
  /// tool's.
  InspectorWindow(InspectorPart part, const shell::HapticWindowSettings& settings,
                  QWidget* parent = nullptr);
  ~InspectorWindow() override;

  /// Drops a marker where the proxy touches now; false when it touches nothing.
  bool dropMarker();
  /// Forgets the markers, the gap and the stops: a new probing session.
  void clearProbe();
  /// The tool's (and the proxy's) new radius: the loops restart, the reach is found again.
  bool setToolRadius(double radius, std::string& error);
  /// The sphere tree's spheres at `level` over the part, or none for a negative level; how many.
  std::size_t showSphereTreeLevel(int level);

  /// Whether the defects and the reach of the current radius are found (and drawn).
  bool analysisReady() const { return m_inspection.has_value() && m_reach.has_value(); }
  const std::optional<MeshInspection>& inspection() const { return m_inspection; }
  const std::optional<ToolReach>& reach() const { return m_reach; }
  const ProbeMeasurements& measurements() const { return m_meter->measurements(); }
  const InspectorPart& part() const { return m_part; }
  DefectOverlay::Drawn drawnDefects() const { return m_defects.drawn(); }

  /// Writes the report (defects, reach, probe; Documentation/CadInspector.md) to `path` and the
  /// window's picture beside it (the same name, .png); neither when either fails. False with
  /// `error`; also when the analysis is not finished yet.
  bool exportReport(const std::string& path, std::string& error);

signals:
  /// File > Open a part: the program replaces this window with one on `path` at `scale`.
  void partRequested(const QString& path, double scale);

protected:
  void ticksArrived(const std::vector<HapticState>& ticks) override;
  std::string hudLines(const HapticState& state) const override;
  void sessionRestarted() override;

private:
  struct Analysis
  {
    std::optional<MeshInspection> inspection;
    ToolReach reach;
  };
  void startAnalysis();
  void pollAnalysis();
  void buildInspectMenu();
  void askToolRadius();
  void exportAs();
  void openPart();

  InspectorPart m_part;
  DefectOverlay m_defects;
  std::unique_ptr<ProbeOverlay> m_probeOverlay;
  std::unique_ptr<ProbeMeter> m_meter;
  std::optional<MeshInspection> m_inspection;
  std::optional<ToolReach> m_reach;
  std::future<Analysis> m_analysis;
  std::atomic<double> m_analysisDone{0.0};
  QTimer m_analysisTimer;
  vtkSmartPointer<vtkActor> m_treeLevel;
  bool m_ticked = false;
};

} // namespace proxima::inspector
