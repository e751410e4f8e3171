#!/usr/bin/env python3
"""proxima view's lockstep screenshot of a scene with tissue draws the organ as the press has
deformed it, and plays the same steps as `proxima run`:

- the kidney held pressed (1.5 s into Data/Paths/Tissue/kidney-press.csv, the proxy 5.5 mm into
  the kidney's rest shape): the whole proxy shows in its dent. The proxy's blue pixels span as
  many rows as columns (within 15 %), as when it hovers above the kidney. Drawn at rest, as the
  picture once was, the rest surface hides the proxy's lower part: 29 rows of 40 (0.72).
- the same from a live device (a replay of the path on the real clock, `--device replay:`): the
  threaded runtime's proxy thread stepped the solid and the picture draws the surface its last
  step handed over, so the proxy shows whole in its dent there too.
- the force the picture reports is the force of `proxima run --tick-budget default` on that tick
  (the real-time default budget, which the picture's lockstep run takes), to the 4 decimals the
  line prints.

Run under a display (Library/VTK/Testing/run-under-xvfb.sh).
Usage: check_view_tissue.py PROXIMA SOURCE_DIR OUT_DIR
"""
import csv
import math
import os
import re
import subprocess
import sys

import matplotlib.image
import numpy

WIDTH, HEIGHT = 480, 360
HELD = 1.5
RUN = ["--scene", "Data/Scenes/kidney-tissue.json", "--path", "Data/Paths/Tissue/kidney-press.csv",
       "--radius", "0.004", "--stiffness", "500"]


def screenshot(proxima, source, out_dir, name, at, device=()):
    """The picture's blue proxy pixels (a boolean image) and the force its line reports."""
    png = os.path.join(out_dir, name + ".png")
    result = subprocess.run([proxima, "view"] + RUN + list(device) +
                            ["--at", str(at), "--view-distance", "0.12", "--width", str(WIDTH),
                             "--height", str(HEIGHT), "--screenshot", png],
                            capture_output=True, text=True, timeout=300, cwd=source)
    assert result.returncode == 0, (name, result.stderr)
    print(result.stdout.strip())
    force = float(re.search(r"force ([0-9.]+) N", result.stdout).group(1))
    rgb = matplotlib.image.imread(png)[:, :, :3]
    red, green, blue = rgb[:, :, 0], rgb[:, :, 1], rgb[:, :, 2]
    # The proxy's colour (0.2, 0.45, 1.0), lit: blue well above green and red. The contact disc
    # (0.3, 0.85, 0.95) and the surface are not.
    return (blue > 0.5) & (blue - green > 0.25) & (blue - red > 0.35), force


def run(proxima, source, extra):
    """`proxima run` of the kidney press with `extra` arguments; fails the check if it fails."""
    result = subprocess.run([proxima, "run"] + RUN + extra, capture_output=True, text=True,
                            timeout=300, cwd=source)
    assert result.returncode == 0, result.stderr


def rows_per_column(mask):
    rows = numpy.where(mask.any(axis=1))[0]
    columns = numpy.where(mask.any(axis=0))[0]
    assert rows.size > 0, "no proxy in the picture"
    return (rows.max() - rows.min() + 1) / (columns.max() - columns.min() + 1)


def main():
    proxima, source, out_dir = sys.argv[1:4]
    failures = []
    hovering, _ = screenshot(proxima, source, out_dir, "kidney-hover", 0.3)
    held, force = screenshot(proxima, source, out_dir, "kidney-held", HELD)
    hover_shape = rows_per_column(hovering)
    held_shape = rows_per_column(held)
    print(f"proxy's rows per column: hovering {hover_shape:.3f}, held in the dent {held_shape:.3f}")
    if held_shape < 0.85 * hover_shape:
        failures.append(f"the held proxy is hidden below the surface drawn ({held_shape:.3f} rows "
                        f"per column against {hover_shape:.3f} hovering): the kidney is drawn at "
                        "rest, not deformed")

    # The path as a device recording (what a replay plays), from a lockstep run of it.
    recording = os.path.join(out_dir, "kidney-device.csv")
    run(proxima, source, ["--out", os.path.join(out_dir, "kidney-recorded.csv"),
                          "--record-device", recording])
    live, _ = screenshot(proxima, source, out_dir, "kidney-held-live", HELD,
                         ["--device", "replay:" + recording])
    live_shape = rows_per_column(live)
    print(f"proxy's rows per column held in the dent, live: {live_shape:.3f}")
    if live_shape < 0.85 * hover_shape:
        failures.append(f"live, the held proxy is hidden below the surface drawn ({live_shape:.3f} "
                        f"rows per column against {hover_shape:.3f} hovering): the surface the "
                        "threaded runtime's steps handed over was not drawn")

    trace = os.path.join(out_dir, "kidney-run.csv")
    run(proxima, source, ["--tick-budget", "default", "--out", trace])
    with open(trace, newline="") as rows:
        for row in csv.DictReader(rows):
            if abs(float(row["t"]) - HELD) < 1e-9:
                ran = math.sqrt(sum(float(row[k]) ** 2 for k in ("force_x", "force_y", "force_z")))
                break
        else:
            raise AssertionError(f"no tick at {HELD} s in the run's trace")
    print(f"force at {HELD} s: picture {force:.4f} N, proxima run {ran:.4f} N")
    if f"{ran:.4f}" != f"{force:.4f}":
        failures.append(f"the picture's force {force:.4f} N is not the run's {ran:.4f} N")

    for failure in failures:
        print("check_view_tissue: " + failure, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
