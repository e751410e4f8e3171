// A render window's picture as PNG bytes, rendered offscreen: what the applications' screenshots
// write through AtomicOutputFile (VTK's image writers do not report a full disk, so the bytes go
// to the file through Proxima's own writer).
#pragma once

#include <string>

class vtkRenderWindow;

namespace proxima::shell
{

/// Renders `window` and returns its PNG; throws OutputError naming `path` when VTK's writer gives
/// nothing.
std::string windowPng(vtkRenderWindow* window, const std::string& path);

} // namespace proxima::shell
