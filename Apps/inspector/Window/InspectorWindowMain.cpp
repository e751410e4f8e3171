#include "InspectorWindowMain.h"

#include "DisplayCheck.h"
#include "InspectorWindow.h"

#include "Geometry/TriangleMesh.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <filesystem>
#include <memory>

namespace proxima::inspector
{

int runInspectorWindow(const InspectorWindowOptions& options, int argc, char** argv)
{
  const std::string noDisplay = shell::displayProblem("proxima-inspector");
  if (!noDisplay.empty())
  {
    throw InputError("the inspector's window", noDisplay);
  }
  InspectorPart part{options.mesh, options.scale, readMeshFile(options.mesh, options.scale)};
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(part.soup, error))
  {
    throw InputError(options.mesh, error.message);
  }
  if (options.toolRadius > mesh.diagonal())
  {
    throw InputError("--tool-radius", "a tool of " + std::to_string(options.toolRadius) +
                                        " m is larger than the whole part (its bounding box's "
                                        "diagonal is " +
                                        std::to_string(mesh.diagonal()) + " m)");
  }
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(std::move(mesh));

  // Before the application: the OpenGL context VTK's widget needs (DEBIAN-NOTES.md).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  shell::HapticWindowSettings settings;
  settings.title = "Proxima inspector: " + std::filesystem::path(options.mesh).filename().string();
  settings.scene = scene;
  settings.radius = options.toolRadius;
  settings.stiffness = options.stiffness;
  settings.servoRate = options.rate;
  settings.device = options.device;
  settings.falconFirmware = options.falconFirmware;
  settings.width = options.width;
  settings.height = options.height;
  InspectorWindow window(std::move(part), settings);
  window.show();
  return QApplication::exec();
}

} // namespace proxima::inspector
