// The module proxima-vtk-mesh-readers: VtkReaders.cpp's readers in the table of
// VtkReadersModule.h. Exceptions (InputError) pass through to the caller as they are.
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtkReadersModule.h"

extern "C" const proxima::detail::VtkMeshReaders* proximaVtkMeshReaders()
{
  static const proxima::detail::VtkMeshReaders readers{&proxima::detail::readWithVtk,
                                                       &proxima::detail::readGltfWithVtk};
  return &readers;
}
