#!/usr/bin/env python3
"""proxima view's screenshots frame what the finger is among, read from the pictures' pixels:

- at the force clamp, the force arrow lies wholly inside the picture (it ran out of it, a thick
  red bar, when its length was thirty proxy radii at a camera forty radii away);
- on the lever, the hinge's axis is drawn (magenta) and the 0.35 N arrow shows;
- on scenes of several objects (the spheres on the table, the pushed free block, the crank), no
  surface runs over the picture's top, left or right edge (the bottom left holds the HUD).

Run under a display (Library/VTK/Testing/run-under-xvfb.sh).
Usage: check_view_framing.py PROXIMA SOURCE_DIR OUT_DIR
"""
import os
import re
import subprocess
import sys

import matplotlib.image

WIDTH, HEIGHT = 480, 360


def screenshot(proxima, out_dir, name, arguments):
    """The picture's pixels (rows of RGB in 0..1) and the force its line reports."""
    png = os.path.join(out_dir, name + ".png")
    result = subprocess.run([proxima, "view"] + arguments +
                            ["--width", str(WIDTH), "--height", str(HEIGHT), "--screenshot", png],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, (name, result.stderr)
    force = float(re.search(r"force ([0-9.]+) N", result.stdout).group(1))
    return matplotlib.image.imread(png)[:, :, :3], force


def is_red(pixel):
    r, g, b = pixel
    return r > 0.45 and g < 0.3 and b < 0.3


def is_magenta(pixel):
    r, g, b = pixel
    return r > 0.75 and b > 0.75 and g < 0.5


def is_background(pixel):
    # The gradient from (0.1, 0.12, 0.16) to (0.25, 0.28, 0.34): bluer than any surface.
    r, g, b = pixel
    return b - r > 0.03 and b < 0.45


def pixels(image, test):
    return [(y, x) for y in range(image.shape[0]) for x in range(image.shape[1])
            if test(image[y, x])]


def edge_pixels(image):
    """The top row, the right column, and the left column above the HUD."""
    height, width = image.shape[:2]
    edge = [(0, x) for x in range(width)] + [(y, width - 1) for y in range(height)]
    return edge + [(y, 0) for y in range(int(0.75 * height))]


def main():
    proxima, source, out_dir = sys.argv[1:4]
    data = os.path.join(source, "Data")
    failures = []

    image, force = screenshot(proxima, out_dir, "clamp", [
        "--mesh", os.path.join(data, "Meshes", "icosphere-4.obj"),
        "--path", os.path.join(data, "Paths", "icosphere-4-press-stroke.csv"),
        "--max-force", "2", "--at", "1.2"])
    assert abs(force - 2.0) < 1e-3, f"the clamp case is not at the clamp: {force} N"
    red = pixels(image, is_red)
    on_edge = [(y, x) for y, x in red
               if y <= 1 or x <= 1 or y >= image.shape[0] - 2 or x >= image.shape[1] - 2]
    if len(red) < 40:
        failures.append(f"clamp: the force arrow shows in {len(red)} pixels, not 40 or more")
    if on_edge:
        failures.append(f"clamp: the force arrow reaches the picture's edge at {on_edge[:3]}")

    image, force = screenshot(proxima, out_dir, "lever", [
        "--scene", os.path.join(data, "Scenes", "lever.json"),
        "--path", os.path.join(data, "Paths", "Bodies", "lever-press-hold.csv"), "--at", "1.0"])
    assert 0.2 < force < 0.5, f"the lever case's force is {force} N"
    red = len(pixels(image, is_red))
    magenta = len(pixels(image, is_magenta))
    if red < 15:
        failures.append(f"lever: the {force} N arrow shows in {red} pixels, not 15 or more")
    if magenta < 100:
        failures.append(f"lever: the hinge's axis shows in {magenta} pixels, not 100 or more")

    scenes = [
        ("spheres-on-table", "spheres-on-table.json", "spheres-on-table-press-stroke.csv", "0.9"),
        ("free-block", "free-block.json", os.path.join("Bodies", "free-block-push.csv"), "1.0"),
        ("crank", "crank.json", os.path.join("Bodies", "crank-turn.csv"), "1.0"),
    ]
    for name, scene, path, at in scenes:
        image, _ = screenshot(proxima, out_dir, name, [
            "--scene", os.path.join(data, "Scenes", scene),
            "--path", os.path.join(data, "Paths", path), "--at", at])
        cut = [(y, x) for y, x in edge_pixels(image)
               if not is_background(image[y, x]) and not is_magenta(image[y, x])]
        if cut:
            failures.append(f"{name}: a surface runs over the picture's edge, {len(cut)} edge "
                            f"pixels, the first at (row, column) {cut[0]}")

    for failure in failures:
        print(failure)
    assert not failures, f"{len(failures)} failures"
    print("the arrow, the hinge and the scenes' objects are in the picture")


if __name__ == "__main__":
    main()
