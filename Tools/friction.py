#!/usr/bin/env python3
"""Friction from real runs (paper 4.1, 4.2): `proxima run` strokes a finger 2 mm into a flat grid
at 5 cm/s under three materials and plots the force ratio |f_t| / |f_n| on the finger, and the
proxy's lag behind it, against time: dynamic friction alone (the ratio settles at mu_d), static
above dynamic (stick-slip: the ratio climbs to mu_s, then snaps back to mu_d), and dynamic with
viscosity (the ratio settles above mu_d by b v / (kp depth)).

Usage: Tools/friction.py [--proxima build/bin/proxima] [--out Documentation/Figures/friction.png]
"""
import argparse
import math
import os
import tempfile

from proxima_runs import proxima, read_trace, write_path
import matplotlib.pyplot as plt  # noqa: E402 (proxima_runs picks the Agg backend first)

DEPTH_BELOW_SURFACE = 0.002
SPEED = 0.05
PRESS_TICKS = 100
STROKE_TICKS = 1000
MATERIALS = [
    ("dynamic mu_d = 0.3", ["--dynamic-friction", 0.3]),
    ("static mu_s = 0.5, dynamic mu_d = 0.3", ["--static-friction", 0.5, "--dynamic-friction", 0.3]),
    ("mu_d = 0.3, viscosity b = 2 N s/m", ["--dynamic-friction", 0.3, "--viscosity", 2]),
]


def stroke_path(path):
    points = [(0.0, 0.0, 0.005 + (-DEPTH_BELOW_SURFACE - 0.005) * i / PRESS_TICKS)
              for i in range(PRESS_TICKS + 1)]
    points += [(SPEED * 0.001 * i, 0.0, -DEPTH_BELOW_SURFACE) for i in range(1, STROKE_TICKS + 1)]
    write_path(path, points)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--out", default="Documentation/Figures/friction.png")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="friction-")
    mesh = os.path.join(work, "grid.obj")
    path = os.path.join(work, "stroke.csv")
    proxima(args.proxima, "generate", "grid", "--size", 0.2, "--cells", 16, "--out", mesh)
    stroke_path(path)
    fig, (ratio_axes, lag_axes) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for label, flags in MATERIALS:
        trace = os.path.join(work, "trace.csv")
        proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", trace, *flags)
        times, ratios, lags = [], [], []
        for row in read_trace(trace)[PRESS_TICKS + 1:]:
            normal = row["force_z"]
            tangential = math.hypot(row["force_x"], row["force_y"])
            times.append(row["t"])
            ratios.append(tangential / normal)
            lags.append(1000.0 * (row["finger_x"] - row["proxy_x"]))
        sliding = ratios[len(ratios) // 2:]
        print("%s: ratio over the second half of the stroke: min %.4f, mean %.4f, max %.4f"
              % (label, min(sliding), sum(sliding) / len(sliding), max(sliding)))
        ratio_axes.plot(times, ratios, lw=1.0, label=label)
        lag_axes.plot(times, lags, lw=1.0, label=label)
    ratio_axes.set_ylabel("|f_t| / |f_n| on the finger")
    ratio_axes.grid(True, lw=0.3)
    ratio_axes.legend(fontsize=8, loc="lower right")
    ratio_axes.set_title("Friction: finger 2 mm into a plane, stroking at 5 cm/s, kp = 1000 N/m, "
                         "1 kHz (proxima run)", fontsize=9)
    lag_axes.set_ylabel("proxy lag behind the finger [mm]")
    lag_axes.set_xlabel("time [s]")
    lag_axes.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    main()
