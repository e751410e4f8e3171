#!/usr/bin/python3
"""Makes the surgical trainer's shipped exercises and their scripted paths.

Reads the shipped liver (Data/Meshes/VH_M_Liver.glb at scale 0.5, 10 cm across) with VTK, picks
spots on its upper surface (the side a default camera looks at, +z) and writes:

  Data/Scenes/liver-nodule.json.in         the liver, soft, with a hard nodule 6 mm under one spot
  Data/Exercises/liver-palpation.json.in   find the nodule and mark it
  Data/Scenes/liver-soft-nodule.json.in    the liver as soft tissue, the nodule a stiff inclusion
  Data/Exercises/liver-soft-palpation.json.in  find that nodule (the palpation's paths)
  Data/Exercises/kidney-press.json.in      press the soft kidney's poles gently, in turn
  Data/Exercises/liver-targets.json.in     touch three spots in order with 0.5-2 N
  Data/Exercises/liver-trace.json.in       follow a 4 cm line on the surface within 3 mm

and on the shared cranium (../shared/data/meshes/cranium_bone_iso075mm.ply, millimetres, 1.5M
triangles; it may not ship), where --shared has it (else the cranium's files are left as they
are):

  Data/Scenes/cranium.json.in              the skull, bone as hard as the scene's spring
  Data/Exercises/cranium-trace.json.in     trace a 4.5 cm craniotomy line on the vertex within
                                           2 mm, never pressing the bone with more than 6 N
  Data/Paths/Trainer/*.csv                 for each exercise a path that passes and one that
                                           fails (and the palpation's mark times)

The .json.in files name the liver as @PROXIMA_DATA_DIR@/Meshes/VH_M_Liver.glb and the cranium as
@PROXIMA_SHARED_DATA@/meshes/...; the build turns the liver's into build/Data/{Scenes,Exercises}/
always, and the cranium's when the shared cranium is present. Deterministic: run it again and
nothing changes. Never edit its outputs by hand.

Usage: /usr/bin/python3 Tools/make-trainer-exercises.py [--shared ../shared/data]
"""

import argparse
import json
import math
import os

import numpy as np
from vtkmodules.vtkCommonCore import reference
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkFiltersGeometry import vtkCompositeDataGeometryFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkCommonDataModel import vtkCellLocator
from vtkmodules.vtkIOGeometry import vtkGLTFReader
import vtkmodules.vtkIOImage  # noqa: F401  (the glTF reader's images)

SCALE = 0.5
RADIUS = 0.002
STIFFNESS = 500.0
TISSUE_STIFFNESS = 0.6  # the liver's factor on kp: 300 N/m
RATE = 1000.0
NODULE_DEPTH = 0.006
NODULE_RADIUS = 0.012
NODULE_SCALE = 4.0
FORCE_LIMIT = 5.0
KIDNEY_FORCE_LIMIT = 0.4  # N
KIDNEY_FORCE_BAND = [0.05, 0.25]  # N
KIDNEY_DEPTH = 0.006  # m: the finger behind the proxy's first touch in the passing presses
KIDNEY_DEEP = 0.03  # m: the failing path's second press
SOFT_YOUNGS_MODULUS = 3000.0  # Pa: soft liver
SOFT_NODULE_FACTOR = 10.0
SOFT_DAMPING = 20.0  # 1/s
SOFT_TET_SIZE = 0.006  # m: about 6,000 tetrahedra, the nodule a few dozen
SOFT_HELD_FRACTION = 0.65  # the lower part of the liver's height held: it rests on what is behind
TOLERANCE = 0.003


def read_mesh(path, scale):
    """The mesh at `path` (glTF or PLY) scaled to metres."""
    if path.endswith(".glb"):
        reader = vtkGLTFReader()
        reader.SetFileName(path)
        flatten = vtkCompositeDataGeometryFilter()
        flatten.SetInputConnection(reader.GetOutputPort())
        source = flatten
    else:
        source = vtkPLYReader()
        source.SetFileName(path)
    transform = vtkTransform()
    transform.Scale(scale, scale, scale)
    scaled = vtkTransformPolyDataFilter()
    scaled.SetTransform(transform)
    scaled.SetInputConnection(source.GetOutputPort())
    scaled.Update()
    return scaled.GetOutput()


def read_liver(root):
    return read_mesh(os.path.join(root, "Data", "Meshes", "VH_M_Liver.glb"), SCALE)


class Surface:
    """The liver's upper surface, found by rays cast down from above it."""

    def __init__(self, polydata):
        self.polydata = polydata
        self.locator = vtkCellLocator()
        self.locator.SetDataSet(polydata)
        self.locator.BuildLocator()
        bounds = polydata.GetBounds()
        self.bounds = bounds
        self.top = bounds[5]

    def spot(self, x, y):
        """The topmost surface point above (x, y), and the surface's outward normal there."""
        start = [x, y, self.top + 0.05]
        end = [x, y, self.bounds[4] - 0.05]
        t = reference(0.0)
        point = [0.0, 0.0, 0.0]
        pcoords = [0.0, 0.0, 0.0]
        sub = reference(0)
        cell_id = reference(0)
        hit = self.locator.IntersectWithLine(start, end, 1e-9, t, point, pcoords, sub, cell_id)
        if not hit:
            raise SystemExit(f"no surface under ({x}, {y})")
        cell = self.polydata.GetCell(int(cell_id))
        ids = cell.GetPointIds()
        a, b, c = (np.array(self.polydata.GetPoint(ids.GetId(k))) for k in range(3))
        normal = np.cross(b - a, c - a)
        normal /= np.linalg.norm(normal)
        if normal[2] < 0:  # the side rays from above meet faces up
            normal = -normal
        return np.array(point), normal


class PathWriter:
    """A finger path of straight moves at given speeds and holds. Only the corners are written:
    the path file's rows are interpolated linearly (Runtime/FingerPath.h), tick by tick."""

    def __init__(self, start):
        self.t = 0.0
        self.rows = [(0.0, np.array(start, dtype=float))]

    @property
    def position(self):
        return self.rows[-1][1]

    def move(self, to, speed):
        to = np.array(to, dtype=float)
        # Whole milliseconds, so that the corners fall on the 1 kHz ticks.
        seconds = max(math.ceil(np.linalg.norm(to - self.position) / speed * RATE), 1) / RATE
        self.t += seconds
        self.rows.append((self.t, to))

    def hold(self, seconds):
        self.t += round(seconds * RATE) / RATE
        self.rows.append((self.t, self.position))

    def write(self, path):
        with open(path, "w") as out:
            out.write("t,x,y,z\n")
            for t, p in self.rows:
                out.write(f"{t:.3f},{p[0]:.9f},{p[1]:.9f},{p[2]:.9f}\n")


def pressed(spot, depth, radius=RADIUS):
    """The finger `depth` behind the proxy resting on the surface at `spot`: force kp * depth."""
    point, normal = spot
    return point + normal * (radius - depth)


def above(spot, height, radius=RADIUS):
    point, normal = spot
    return point + normal * (radius + height)


def press_at(writer, surface, spot, depth, hold, travel_height):
    """Travels high above the surface, comes down along the normal, presses and lifts."""
    writer.move([*above(spot, 0.015)[:2], travel_height], 0.1)
    writer.move(above(spot, 0.015), 0.05)
    writer.move(above(spot, 0.001), 0.03)
    writer.move(pressed(spot, depth), 0.01)
    press_time = writer.t
    writer.hold(hold)
    writer.move(above(spot, 0.015), 0.03)
    return press_time + hold / 2


def surface_line(surface, uv_start, uv_end, offset=(0.0, 0.0), spacing=0.002):
    """Surface spots every `spacing` along the line between fractions `uv_start` and `uv_end` of
    the surface's x and y extent, shifted by `offset` metres in x and y."""
    x0, x1, y0, y1, _, _ = surface.bounds
    extent = np.array([x1 - x0, y1 - y0])
    origin = np.array([x0, y0])
    uv_start, uv_end = np.array(uv_start), np.array(uv_end)
    count = int(np.linalg.norm((uv_end - uv_start) * extent) / spacing) + 1
    return [surface.spot(*(origin + (uv_start + (uv_end - uv_start) * k / (count - 1)) * extent +
                           np.array(offset))) for k in range(count)]


def stroke_path(start, travel, stroke, depth, radius):
    """Down onto the first spot, pressed `depth` along every spot of `stroke`, up and back."""
    writer = PathWriter(start)
    writer.move([*above(stroke[0], 0.015, radius)[:2], travel], 0.1)
    writer.move(above(stroke[0], 0.015, radius), 0.05)
    writer.move(above(stroke[0], 0.001, radius), 0.03)
    writer.move(pressed(stroke[0], depth, radius), 0.01)
    for spot in stroke[1:]:
        writer.move(pressed(spot, depth, radius), 0.02)
    writer.move(above(stroke[-1], 0.015, radius), 0.03)
    writer.move(start, 0.1)
    return writer


def line_points(line, every=5):
    """Every `every`-th point of a surface line and its last, for the exercise file."""
    points = [rounded(p) for p, _ in line[::every]]
    if (len(line) - 1) % every:
        points.append(rounded(line[-1][0]))
    return points


def write_json(path, document):
    with open(path, "w") as out:
        out.write(json.dumps(document, indent=2) + "\n")


def rounded(v):
    return [round(float(c), 6) for c in v]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shared", default=os.path.join(root, "..", "shared", "data"))
    args = parser.parse_args()

    surface = Surface(read_liver(root))
    x0, x1, y0, y1, _, top = surface.bounds
    travel = top + 0.02
    start = [(x0 + x1) / 2, (y0 + y1) / 2, travel]

    def at(u, v):
        """A spot at fractions (u, v) of the liver's x and y extent."""
        return surface.spot(x0 + (x1 - x0) * u, y0 + (y1 - y0) * v)

    scenes = os.path.join(root, "Data", "Scenes")
    exercises = os.path.join(root, "Data", "Exercises")
    paths = os.path.join(root, "Data", "Paths", "Trainer")
    os.makedirs(exercises, exist_ok=True)
    os.makedirs(paths, exist_ok=True)

    # The nodule: 6 mm under a spot on the right lobe's upper surface.
    nodule_spot = at(0.6, 0.55)
    nodule_center = nodule_spot[0] - nodule_spot[1] * NODULE_DEPTH
    write_json(os.path.join(scenes, "liver-nodule.json.in"), {
        "version": 1,
        "objects": [{
            "mesh": "@PROXIMA_DATA_DIR@/Meshes/VH_M_Liver.glb",
            "scale": SCALE,
            "material": {
                "stiffness": TISSUE_STIFFNESS,
                "stiffness_regions": [{"center": rounded(nodule_center),
                                       "radius": NODULE_RADIUS, "scale": NODULE_SCALE}],
            },
        }],
    })
    common = {
        "format": "proxima-exercise",
        "version": 1,
        "scene": "../Scenes/liver-nodule.json",
        "proxy": {"radius": RADIUS, "stiffness": STIFFNESS, "rate": RATE, "max_force": 10},
        "tissues": [{"object": 0, "name": "liver", "force_limit": FORCE_LIMIT}],
    }

    # Palpation: press at three spots; the passing path marks the one over the nodule, the failing
    # one marks a spot 3 cm away.
    write_json(os.path.join(exercises, "liver-palpation.json.in"), {
        **common,
        "name": "Liver palpation: find the hidden nodule",
        "instructions": "Somewhere under the liver's upper surface is a hard nodule. Press gently "
                        "over the surface until you feel it push back harder, then mark the spot "
                        "(the M key).",
        "tasks": [{"type": "palpation", "object": 0, "region": 0, "pass_distance": 0.01}],
    })
    decoys = [at(0.3, 0.55), at(0.45, 0.7)]
    for name, marked in (("pass", nodule_spot), ("fail", decoys[0])):
        writer = PathWriter(start)
        marks = []
        for spot in (decoys[0], nodule_spot, decoys[1]):
            middle = press_at(writer, surface, spot, 0.004, 1.0, travel)
            if spot is marked:
                marks.append(middle)
        writer.move(start, 0.1)
        writer.write(os.path.join(paths, f"liver-palpation-{name}.csv"))
        with open(os.path.join(paths, f"liver-palpation-{name}-marks.csv"), "w") as out:
            out.write("t\n" + "".join(f"{t:.3f}\n" for t in marks))

    # The soft liver (issue 35): the same liver as an elastic solid (3 kPa, Documentation/Tissue.md)
    # held along the lower 65 % of its height (held along its lower third, the lobe bent under the
    # finger and the nodule sank with it: 0.09 N over it against 0.08 N beside it), with the nodule
    # an inclusion ten times stiffer at the same place.
    # Palpated by the same paths: what the trainee feels over the nodule is the solid pushing back.
    _, _, _, _, bottom, top = surface.bounds
    held = bottom + (top - bottom) * SOFT_HELD_FRACTION
    write_json(os.path.join(scenes, "liver-soft-nodule.json.in"), {
        "version": 3,
        "objects": [{
            "mesh": "@PROXIMA_DATA_DIR@/Meshes/VH_M_Liver.glb",
            "scale": SCALE,
            "tissue": {
                "youngs_modulus": SOFT_YOUNGS_MODULUS,
                "poisson_ratio": 0.45,
                "damping": SOFT_DAMPING,
                "tet_size": SOFT_TET_SIZE,
                "fixed": {"box": [rounded([x0 - 0.01, y0 - 0.01, bottom - 0.01]),
                                  rounded([x1 + 0.01, y1 + 0.01, held])]},
                "inclusions": [{"center": rounded(nodule_center), "radius": NODULE_RADIUS,
                                "youngs_modulus": SOFT_YOUNGS_MODULUS * SOFT_NODULE_FACTOR}],
            },
        }],
    })
    write_json(os.path.join(exercises, "liver-soft-palpation.json.in"), {
        **common,
        "scene": "../Scenes/liver-soft-nodule.json",
        "name": "Soft liver palpation: find the hidden nodule",
        "instructions": "The liver gives way under your finger. Somewhere under its upper surface "
                        "is a hard nodule. Press gently over the surface until you feel it push "
                        "back harder, then mark the spot (the M key).",
        "tasks": [{"type": "palpation", "object": 0, "inclusion": 0, "pass_distance": 0.01}],
    })

    # Targets: three spots in order, each held for 0.3 s with 0.5-2 N (a 4 mm press on the
    # liver's 300 N/m is 1.2 N). The failing path skips the second and presses the third at 20 mm
    # (6 N: above the band, and damage).
    targets = [("A", at(0.25, 0.5)), ("B", at(0.45, 0.6)), ("C", at(0.75, 0.6))]
    write_json(os.path.join(exercises, "liver-targets.json.in"), {
        **common,
        "name": "Liver targets: touch A, B and C in order",
        "instructions": "Touch the three marked spots in order, A, B then C, pressing with between "
                        "0.5 and 2 N for a third of a second on each. Do not press harder than 5 N.",
        "tasks": [{
            "type": "targets",
            "targets": [{"name": n, "center": rounded(s[0]), "radius": 0.005} for n, s in targets],
            "force": [0.5, 2.0],
            "hold": 0.3,
        }],
    })
    for name, visits in (("pass", [(0, 0.004), (1, 0.004), (2, 0.004)]),
                         ("fail", [(0, 0.004), (2, 0.020)])):
        writer = PathWriter(start)
        for index, depth in visits:
            press_at(writer, surface, targets[index][1], depth, 0.6, travel)
        writer.move(start, 0.1)
        writer.write(os.path.join(paths, f"liver-targets-{name}.csv"))

    # Trace: a 4 cm line across the upper surface, drawn through surface points 2 mm apart. The
    # passing path strokes along it pressed 3 mm; the failing one strokes a line 8 mm beside it.
    line = surface_line(surface, (0.3, 0.55), (0.7, 0.55))
    write_json(os.path.join(exercises, "liver-trace.json.in"), {
        **common,
        "name": "Liver trace: follow the line",
        "instructions": "Follow the drawn line from its left end to its right end, pressing "
                        "lightly, within 3 mm of it.",
        "tasks": [{"type": "trace", "line": line_points(line),
                   "tolerance": TOLERANCE, "min_coverage": 0.9, "max_off_line": 0.1}],
    })
    for name, offset in (("pass", 0.0), ("fail", 0.008)):
        stroke = surface_line(surface, (0.3, 0.55), (0.7, 0.55), (0.0, offset))
        stroke_path(start, travel, stroke, 0.003, RADIUS).write(
            os.path.join(paths, f"liver-trace-{name}.csv"))

    # The kidney as soft tissue (Data/Scenes/kidney-tissue.json, 6 kPa, held along its back): press
    # its upper and lower pole in turn, each gently, for a third of a second; it is damaged above
    # KIDNEY_FORCE_LIMIT. The failing path presses the lower pole KIDNEY_DEEP deep.
    kidney = Surface(read_mesh(os.path.join(root, "Data", "Meshes", "VH_M_Kidney_L.glb"), 1.0))
    kx0, kx1, ky0, ky1, _, ktop = kidney.bounds
    kidney_travel = ktop + 0.02
    kidney_start = [(kx0 + kx1) / 2, (ky0 + ky1) / 2, kidney_travel]
    poles = [("upper", kidney.spot(kx0 + (kx1 - kx0) * 0.5, ky0 + (ky1 - ky0) * 0.7)),
             ("lower", kidney.spot(kx0 + (kx1 - kx0) * 0.5, ky0 + (ky1 - ky0) * 0.3))]
    write_json(os.path.join(exercises, "kidney-press.json.in"), {
        "format": "proxima-exercise",
        "version": 1,
        "scene": "@PROXIMA_DATA_DIR@/Scenes/kidney-tissue.json",
        "proxy": {"radius": RADIUS, "stiffness": STIFFNESS, "rate": RATE, "max_force": 10},
        "tissues": [{"object": 0, "name": "kidney", "force_limit": KIDNEY_FORCE_LIMIT}],
        "name": "Soft kidney: press the upper pole, then the lower",
        "instructions": "The kidney gives way under your finger. Press its upper pole, then its "
                        "lower pole, each with between 0.05 and 0.25 N for a third of a second. "
                        "Do not press harder than 0.4 N.",
        "tasks": [{
            "type": "targets",
            "targets": [{"name": n, "center": rounded(s[0]), "radius": 0.006} for n, s in poles],
            "force": KIDNEY_FORCE_BAND,
            "hold": 0.3,
        }],
    })
    for name, depths in (("pass", (KIDNEY_DEPTH, KIDNEY_DEPTH)), ("fail", (KIDNEY_DEPTH, KIDNEY_DEEP))):
        writer = PathWriter(kidney_start)
        for (_, spot), depth in zip(poles, depths):
            press_at(writer, kidney, spot, depth, 0.8, kidney_travel)
        writer.move(kidney_start, 0.1)
        writer.write(os.path.join(paths, f"kidney-press-{name}.csv"))

    # The cranium: a craniotomy line across the vertex, 1 mm proxy on bone at 1000 N/m. The
    # passing path strokes it pressed 2 mm (2 N); the failing one presses 8 mm (8 N, over the
    # bone's 6 N limit) along the same line: covered, but damaged.
    cranium = os.path.join(args.shared, "meshes", "cranium_bone_iso075mm.ply")
    if not os.path.isfile(cranium):
        print(f"make-trainer-exercises: {cranium} is absent (--shared): the cranium's exercise "
              "and paths are left as they are")
        return
    skull = Surface(read_mesh(cranium, 0.001))
    write_json(os.path.join(scenes, "cranium.json.in"), {
        "version": 1,
        "objects": [{"mesh": "@PROXIMA_SHARED_DATA@/meshes/cranium_bone_iso075mm.ply",
                     "scale": 0.001}],
    })
    craniotomy = surface_line(skull, (0.4, 0.5), (0.6, 0.5))
    write_json(os.path.join(exercises, "cranium-trace.json.in"), {
        "format": "proxima-exercise",
        "version": 1,
        "name": "Cranium: trace the craniotomy line",
        "instructions": "Trace the planned craniotomy line across the top of the skull from end "
                        "to end, within 2 mm of it, without pressing the bone harder than 6 N.",
        "scene": "../Scenes/cranium.json",
        "proxy": {"radius": 0.001, "stiffness": 1000, "rate": RATE, "max_force": 10},
        "tissues": [{"object": 0, "name": "bone", "force_limit": 6}],
        "tasks": [{"type": "trace", "line": line_points(craniotomy), "tolerance": 0.002,
                   "min_coverage": 0.9, "max_off_line": 0.1}],
    })
    _, _, _, _, _, skull_top = skull.bounds
    skull_start = [*craniotomy[0][0][:2], skull_top + 0.02]
    for name, depth in (("pass", 0.002), ("fail", 0.008)):
        stroke_path(skull_start, skull_top + 0.02, craniotomy, depth, 0.001).write(
            os.path.join(paths, f"cranium-trace-{name}.csv"))

if __name__ == "__main__":
    main()
