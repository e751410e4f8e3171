// The VTK module Proxima::vtkHaptic holds no code of its own: its headers are Library/VTK's
// vtkHaptic* classes, which VTK's Python wrapping reads, and its library links Proxima::VTK,
// where they are compiled. VTK's module system wants at least one source in a module library.
#include "vtkProximaHapticModule.h"

namespace proxima::vtk
{
/// Gives the module's library a symbol of its own.
VTKPROXIMAHAPTIC_EXPORT int wrappingModuleVersion()
{
  return 1;
}
} // namespace proxima::vtk
