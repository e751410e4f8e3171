#include "InspectorWindowMain.h"

#include "DisplayCheck.h"
#include "InspectorWindow.h"

#include "Geometry/TriangleMesh.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/Output/StandardOutput.h"

#include <QApplication>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>

namespace proxima::inspector
{

namespace
{
// A window on the part at `file` and `scale`; throws InputError for a part that cannot be read or
// a tool larger than it.
std::unique_ptr<InspectorWindow> openWindow(const std::string& file, double scale,
                                            const InspectorWindowOptions& options)
{
  InspectorPart part{file, scale, readMeshFile(file, scale)};
  TriangleMesh mesh = buildTriangleMesh(part.soup, file);
  if (options.toolRadius > mesh.diagonal())
  {
    throw InputError("--tool-radius", "a tool of " + std::to_string(options.toolRadius) +
                                        " m is larger than the whole part (its bounding box's "
                                        "diagonal is " +
                                        std::to_string(mesh.diagonal()) + " m)");
  }
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(std::move(mesh));
  shell::HapticWindowSettings settings;
  settings.title = "Proxima inspector: " + std::filesystem::path(file).filename().string();
  settings.scene = scene;
  settings.radius = options.toolRadius;
  settings.stiffness = options.stiffness;
  settings.servoRate = options.rate;
  settings.device = options.device;
  settings.falconFirmware = options.falconFirmware;
  settings.width = options.width;
  settings.height = options.height;
  return std::make_unique<InspectorWindow>(std::move(part), settings);
}

// The session's measurements in one line, as the trainer prints its attempt: scripts read it.
std::string closingLine(const InspectorWindow& window)
{
  const ProbeMeasurements& m = window.measurements();
  std::string line = "proxima-inspector: closed " +
                     std::filesystem::path(window.part().file).filename().string() + ": " +
                     std::to_string(m.markers.size()) + " markers";
  char text[200];
  if (!m.distances.empty())
  {
    std::snprintf(text, sizeof text, ", last two %.3f mm apart (across %.3f mm)",
                  m.distances.back().distance * 1000.0, m.distances.back().across * 1000.0);
    line += text;
  }
  if (m.narrowestGap)
  {
    std::snprintf(text, sizeof text, ", narrowest gap %.3f mm", m.narrowestGap->width * 1000.0);
    line += text;
  }
  std::snprintf(text, sizeof text,
                ", %zu stops, %zu marks missed (nothing touched), tool radius %.3f mm, %zu ticks\n",
                m.stopCount, m.marksMissed, window.proxyRadius() * 1000.0, m.ticks);
  return line + text;
}
} // namespace

int runInspectorWindow(const InspectorWindowOptions& options, int argc, char** argv)
{
  const std::string noDisplay = shell::displayProblem("proxima-inspector");
  if (!noDisplay.empty())
  {
    throw InputError("the inspector's window", noDisplay);
  }
  // Before the application: the OpenGL context VTK's widget needs (DEBIAN-NOTES.md).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  // The part named on the command line is refused with status 2 like any other input.
  std::unique_ptr<InspectorWindow> window = openWindow(options.mesh, options.scale, options);
  // File > Open a part: a window on the new part replaces this one; a part that cannot be used
  // is named in a message and the current window stays, with what it measured.
  std::function<void(InspectorWindow&)> connectOpen = [&](InspectorWindow& current) {
    QObject::connect(
      &current, &InspectorWindow::partRequested, &current, [&](const QString& file, double scale) {
        try
        {
          InspectorWindowOptions next = options;
          next.toolRadius = window->proxyRadius();
          next.device = window->deviceSpec();
          std::unique_ptr<InspectorWindow> opened = openWindow(file.toStdString(), scale, next);
          connectOpen(*opened);
          opened->show();
          window->hide();
          window->deleteLater();
          window.release();
          window = std::move(opened);
        }
        catch (const std::exception& error)
        {
          QMessageBox::warning(window.get(), QObject::tr("Proxima inspector"),
                               QString::fromStdString(error.what()));
        }
      });
  };
  connectOpen(*window);
  window->show();
  const int status = QApplication::exec();
  const std::string line = closingLine(*window);
  window.reset();
  writeStandardOutput(line);
  return status == 0 ? 0 : 1;
}

} // namespace proxima::inspector
