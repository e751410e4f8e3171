#include "DisplayCheck.h"

#include <X11/Xlib.h>

#include <cstdlib>

namespace proxima::shell
{

std::string displayProblem(const std::string& command)
{
  const std::string howToGetOne =
    ": run it under a virtual one, as in xvfb-run -a " + command + " ... (package xvfb)";
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0')
  {
    return "DISPLAY is not set, so there is no display to draw on" + howToGetOne;
  }
  // Opening the display is what VTK's window does first; here a failure is an answer, not a
  // crash.
  Display* display = XOpenDisplay(nullptr);
  if (display == nullptr)
  {
    return std::string("cannot open the display DISPLAY=") + name + howToGetOne;
  }
  XCloseDisplay(display);
  return {};
}

} // namespace proxima::shell
