// Whether an application has an X display to draw on. Debian's VTK 9.1 renders, even offscreen,
// through an X OpenGL window; without a display its window segfaulted or aborted, after the
// screenshot's file was already opened. Asked first, the answer is one line and status 2.
#pragma once

#include <string>

namespace proxima::shell
{

/// Empty when an X display can be opened; otherwise one line that says why not and how to get
/// one: `xvfb-run -a COMMAND ...`, with `command` as the user typed it ("proxima view").
std::string displayProblem(const std::string& command);

} // namespace proxima::shell
