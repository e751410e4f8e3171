// proxima-inspector without --path: the inspector's window on a part (InspectorWindow.h).
#pragma once

#include <string>

namespace proxima::inspector
{

struct InspectorWindowOptions
{
  std::string mesh;
  double scale = 1.0;
  double toolRadius = 0.001;
  double stiffness = 1000.0;
  double rate = 1000.0;
  /// mouse (default), spacemouse, falcon or replay:FILE.
  std::string device = "mouse";
  std::string falconFirmware;
  int width = 1024;
  int height = 720;
};

/// Runs the window until it is closed; the exit status. Throws InputError for a part that cannot
/// be read, a tool larger than the part, or no display, before any window opens.
int runInspectorWindow(const InspectorWindowOptions& options, int argc, char** argv);

} // namespace proxima::inspector
