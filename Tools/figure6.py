#!/usr/bin/env python3
"""Reproduces the paper's Figure 6 with `proxima run`: a ten-sided prism with radial point
normals, a finger circling 2 mm inside the facets, faceted (--shading off) against shaded
(--shading on). Plots the force direction's error against the round cylinder's normal (radial at
the finger's angle) along the turn, and prints the mean and max error and the largest change of
force direction between ticks.

Usage: Tools/figure6.py [--proxima build/bin/proxima] [--out Documentation/Figures/figure6.png]
"""
import argparse
import math
import os
import tempfile

from proxima_runs import proxima, read_trace, write_path
import matplotlib.pyplot as plt  # noqa: E402 (proxima_runs picks the Agg backend first)

SIDES = 10
PRISM_RADIUS = 0.05
DEPTH = 0.002
TICKS_PER_TURN = 3600
RATE = 1000.0


def circle_path(path):
    """Press in from 5 mm outside along x, settle a quarter turn, then one measured turn."""
    finger_radius = PRISM_RADIUS * math.cos(math.pi / SIDES) - DEPTH
    points = []
    start = PRISM_RADIUS + 0.005
    press = 100
    for i in range(press + 1):
        points.append((start + (finger_radius - start) * i / press, 0.0, 0.0))
    for i in range(1, TICKS_PER_TURN + TICKS_PER_TURN // 4 + 1):
        angle = 2.0 * math.pi * i / TICKS_PER_TURN
        points.append((finger_radius * math.cos(angle), finger_radius * math.sin(angle), 0.0))
    write_path(path, points, RATE)
    return press + 1 + TICKS_PER_TURN // 4  # first measured row


def errors(trace, first):
    angles, errs, jumps = [], [], []
    previous = None
    for row in read_trace(trace):
        if row["tick"] < first:
            continue
        fx, fy = row["force_x"], row["force_y"]
        norm = math.hypot(fx, fy)
        if norm == 0.0:
            continue
        finger_angle = math.atan2(row["finger_y"], row["finger_x"])
        direction = (fx / norm, fy / norm)
        # The force on the finger points out of the cylinder: radial at the finger's angle.
        cosine = direction[0] * math.cos(finger_angle) + direction[1] * math.sin(finger_angle)
        errs.append(math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))
        angles.append(math.degrees(finger_angle) % 360.0)
        if previous is not None:
            c = direction[0] * previous[0] + direction[1] * previous[1]
            jumps.append(math.degrees(math.acos(max(-1.0, min(1.0, c)))))
        previous = direction
    return angles, errs, jumps


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--out", default="Documentation/Figures/figure6.png")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="figure6-")
    mesh = os.path.join(work, "prism.obj")
    path = os.path.join(work, "circle.csv")
    proxima(args.proxima, "generate", "prism", "--sides", SIDES, "--radius", PRISM_RADIUS,
            "--height", 0.1, "--out", mesh)
    first = circle_path(path)
    results = {}
    for shading in ["off", "on"]:
        trace = os.path.join(work, "trace-%s.csv" % shading)
        proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", trace,
                "--shading", shading, "--max-force", 100)
        results[shading] = errors(trace, first)
    fig, ax = plt.subplots(figsize=(9, 4.2))
    for shading, label, style in [("off", "faceted (--shading off)", "-"),
                                  ("on", "shaded (--shading on)", "-")]:
        angles, errs, jumps = results[shading]
        order = sorted(range(len(angles)), key=lambda k: angles[k])
        ax.plot([angles[k] for k in order], [errs[k] for k in order], style, lw=1.0,
                label="%s: mean %.2f, max %.2f deg, largest jump %.2f deg"
                % (label, sum(errs) / len(errs), max(errs), max(jumps)))
        print("%s: mean error %.3f deg, max %.3f deg, largest jump between ticks %.3f deg, "
              "%d ticks" % (label, sum(errs) / len(errs), max(errs), max(jumps), len(errs)))
    ax.set_xlabel("finger angle around the axis [deg]")
    ax.set_ylabel("force direction error [deg]")
    ax.set_yscale("symlog", linthresh=0.5)
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 36))
    ax.grid(True, lw=0.3)
    ax.set_title("Figure 6: ten-sided prism, radial normals, finger 2 mm inside, "
                 "3600 ticks a turn (proxima run)", fontsize=9)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    main()
