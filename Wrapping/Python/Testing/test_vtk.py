"""The vtkHaptic* classes in VTK's Python (VTK's own wrapping): a vtkPolyData made in Python
becomes a haptic scene, and the haptic threads press a scripted finger into it. The oracle is
the sphere's geometry: the proxy rests on its surface, the force is the spring's."""
import math
import time

import pytest

vtk_sources = pytest.importorskip("vtkmodules.vtkFiltersSources")
from proxima.vtk import vtkHapticRenderer, vtkHapticScene, vtkHapticSphereTreeFilter  # noqa: E402

RADIUS = 0.05  # the sphere's, metres


def sphere_polydata():
    source = vtk_sources.vtkSphereSource()
    source.SetRadius(RADIUS)
    source.SetThetaResolution(64)
    source.SetPhiResolution(64)
    source.Update()
    return source.GetOutput()


def test_a_python_polydata_becomes_a_scene_object():
    scene = vtkHapticScene()
    polydata = sphere_polydata()
    assert scene.AddObject(polydata) == 0
    scene.Update()
    assert scene.GetNumberOfObjects() == 1
    assert scene.GetSceneVersion() == 1
    # Its output draws the objects it holds: the sphere's own bounds, in metres.
    assert scene.GetOutput().GetBounds() == pytest.approx(polydata.GetBounds(), abs=1e-12)


def test_the_sphere_tree_filter_covers_the_surface():
    tree = vtkHapticSphereTreeFilter()
    tree.SetInputData(sphere_polydata())
    tree.SetLevel(0)  # the root sphere: it must hold the whole mesh
    tree.Update()
    bounds = tree.GetOutput().GetBounds()
    assert tree.GetOutput().GetNumberOfPoints() > 0
    assert bounds[1] >= RADIUS * (1 - 1e-9) and bounds[0] <= -RADIUS * (1 - 1e-9)


def test_the_haptic_threads_press_a_python_finger_into_the_sphere():
    scene = vtkHapticScene()
    scene.AddObject(sphere_polydata())
    scene.Update()
    haptics = vtkHapticRenderer()
    haptics.SetScene(scene)
    # Down onto the top of the sphere, 4 mm into it, in 0.2 s, then held.
    haptics.AddFingerSample(0.0, 0.0, 0.0, 0.06)
    haptics.AddFingerSample(0.2, 0.0, 0.0, RADIUS - 0.003)
    haptics.AddFingerSample(10.0, 0.0, 0.0, RADIUS - 0.003)
    haptics.SetProxyRadius(0.001)
    haptics.SetStiffness(1000.0)
    assert haptics.Start(), haptics.GetStartMessage()
    try:
        # 0.4 s of servo ticks: the finger has been held for 0.2 s.
        ticks = 0.4 * haptics.GetServoRate()
        deadline = time.monotonic() + 5.0
        while haptics.GetStateTick() < ticks and time.monotonic() < deadline:
            time.sleep(0.05)
        # A state whose force is the spring's: the runtime fades the force while its proxy loop
        # is starved (a loaded two-core machine), and such states come and go.
        proxy = [0.0, 0.0, 0.0]
        force = [0.0, 0.0, 0.0]
        finger = [0.0, 0.0, 0.0]
        settled = time.monotonic() + 5.0
        while True:
            haptics.GetProxyPosition(proxy)
            haptics.GetForce(force)
            haptics.GetFingerPosition(finger)
            spring = 1000.0 * (proxy[2] - finger[2])
            if abs(force[2] - spring) <= 1e-6 * abs(spring) or time.monotonic() > settled:
                break
            time.sleep(0.01)
        contacts = haptics.GetNumberOfContacts()
    finally:
        haptics.Stop()
    assert haptics.GetStateTick() >= ticks
    # On the sphere: its centre a proxy radius outside the 64 x 64 facets (which lie at most
    # R (1 - cos(pi / 64)) = 0.06 mm inside the true sphere).
    assert math.dist(proxy, (0, 0, 0)) == pytest.approx(RADIUS + 0.001, abs=1e-4)
    assert contacts >= 1
    # The spring's force, pushing the finger back up by about kp x 4 mm.
    assert force[2] == pytest.approx(1000.0 * (proxy[2] - finger[2]), rel=1e-6)
    assert 3.5 < force[2] < 4.5
