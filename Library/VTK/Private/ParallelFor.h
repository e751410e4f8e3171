// vtkSMPTools::For behind a plain function, for files that cannot include vtkSMPTools.h (VTK
// 9.1's header does not compile as C++20; this one file is compiled as C++17).
#pragma once

#include <functional>

namespace proxima::vtk::detail
{

/// Calls `body(i)` for every i in [0, count), in parallel on VTK's SMP backend, one index per
/// task (for a few large items, such as the trees of a scene's objects). `body` must not throw.
void parallelForEach(long count, const std::function<void(long)>& body);

} // namespace proxima::vtk::detail
