"""The vtkHaptic* classes in VTK's Python, wrapped by VTK's own wrapping (Wrapping/VTKPython).

    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from proxima.vtk import vtkHapticScene, vtkHapticRenderer
    scene = vtkHapticScene()
    scene.AddObject(sphere.GetOutput())      # a vtkPolyData made in VTK's Python
"""
# VTK's own modules first: the wrapped classes derive from theirs.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingCore  # noqa: F401

from .vtkProximaHaptic import (vtkHapticRenderer, vtkHapticScene,  # noqa: F401
                               vtkHapticSphereTreeFilter, vtkHapticStateRepresentation)
