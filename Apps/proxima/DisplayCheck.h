// Whether the viewer has an X display to draw on. Debian's VTK 9.1 renders, even offscreen,
// through an X OpenGL window; without a display its window segfaulted or aborted, after the
// screenshot's file was already opened. Asked first, the answer is one line and status 2.
#pragma once

#include <string>

namespace proxima::cli
{

/// Empty when an X display can be opened; otherwise one line that says why not and how to get
/// one (xvfb-run).
std::string displayProblem();

} // namespace proxima::cli
