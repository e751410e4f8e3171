#include "VTK/Private/ParallelFor.h"

#include <vtkSMPTools.h>

namespace proxima::vtk::detail
{

void parallelForEach(long count, const std::function<void(long)>& body)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      body(static_cast<long>(i));
    }
  });
}

} // namespace proxima::vtk::detail
