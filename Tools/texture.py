#!/usr/bin/env python3
"""Texture from real runs (paper 4.3): `proxima run --texture` strokes a finger 2 mm into a flat,
textured 20 cm square whose height map is 0.6 mm * (1/2 + 1/2 sin(2 pi 10 u)) and plots the tilt
of the force on the finger from the plane's normal against the tilt of the bumpy surface it
stands for, atan(-dh/dx); and, with the same image as a friction map on mu_d = 0.4, the sliding
ratio |f_t| / |f_n| against 0.4 * image.

Usage: Tools/texture.py [--proxima build/bin/proxima] [--out Documentation/Figures/texture.png]
"""
import argparse
import math
import os
import tempfile

import numpy
from proxima_runs import proxima, read_trace, write_path
import matplotlib.pyplot as plt  # noqa: E402 (proxima_runs picks the Agg backend first)

SIZE = 0.2
PERIODS = 10
AMPLITUDE = 6e-4
TEXELS = 1024
DEPTH = 0.002


def write_textured_square(path, cells=64):
    """A square z = 0 of side SIZE with texture coordinates u = x / SIZE + 1/2, v likewise."""
    with open(path, "w") as f:
        for j in range(cells + 1):
            for i in range(cells + 1):
                x, y = -SIZE / 2 + SIZE * i / cells, -SIZE / 2 + SIZE * j / cells
                f.write("v %.17g %.17g 0\n" % (x, y))
                f.write("vt %.17g %.17g\n" % (x / SIZE + 0.5, y / SIZE + 0.5))
        row = cells + 1
        for j in range(cells):
            for i in range(cells):
                a = j * row + i + 1
                f.write("f %d/%d %d/%d %d/%d\n" % (a, a, a + 1, a + 1, a + row + 1, a + row + 1))
                f.write("f %d/%d %d/%d %d/%d\n" % (a, a, a + row + 1, a + row + 1, a + row, a + row))


def write_sine_image(path):
    u = (numpy.arange(TEXELS) + 0.5) / TEXELS
    row = 0.5 + 0.5 * numpy.sin(2.0 * math.pi * PERIODS * u)
    plt.imsave(path, numpy.tile(row, (8, 1)), cmap="gray", vmin=0.0, vmax=1.0)


def stroke(path):
    start = -0.03
    points = [(start, 0.0, 0.005 + (-DEPTH - 0.005) * i / 70) for i in range(71)]
    points += [(start + 0.00002 * i, 0.0, -DEPTH) for i in range(1, 3001)]
    write_path(path, points)
    return 71


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--out", default="Documentation/Figures/texture.png")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="texture-")
    mesh, image, path = (os.path.join(work, n) for n in ("square.obj", "sine.png", "stroke.csv"))
    write_textured_square(mesh)
    write_sine_image(image)
    first = stroke(path)
    fig, (bump_axes, friction_axes) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)

    trace = os.path.join(work, "bump.csv")
    proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", trace, "--texture",
            image, "--texture-role", "bump", "--texture-amplitude", AMPLITUDE)
    rows = read_trace(trace)[first:]
    x = [1000.0 * r["proxy_x"] for r in rows]
    tilt = [math.degrees(math.atan2(r["force_x"], r["force_z"])) for r in rows]
    slope = [AMPLITUDE * math.pi * PERIODS / SIZE
             * math.cos(2.0 * math.pi * PERIODS * (r["proxy_x"] / SIZE + 0.5)) for r in rows]
    surface = [math.degrees(math.atan(-s)) for s in slope]
    errors = [abs(a - b) for a, b in zip(tilt, surface)]
    print("bump: force tilt against the bumpy surface's: mean error %.3f deg, max %.3f deg, "
          "mean |tilt| %.2f deg" % (sum(errors) / len(errors), max(errors),
                                    sum(abs(t) for t in tilt) / len(tilt)))
    bump_axes.plot(x, surface, lw=2.5, alpha=0.4, label="bumpy surface: atan(-dh/dx)")
    bump_axes.plot(x, tilt, lw=1.0, label="force on the finger (proxima run --texture ... bump)")
    bump_axes.set_ylabel("tilt from the plane's normal [deg]")
    bump_axes.legend(fontsize=8, loc="upper right")
    bump_axes.grid(True, lw=0.3)
    bump_axes.set_title("Texture: finger 2 mm into a textured plane, stroking at 2 cm/s "
                        "(proxima run)", fontsize=9)

    trace = os.path.join(work, "friction.csv")
    proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", trace,
            "--dynamic-friction", 0.4, "--texture", image, "--texture-role", "friction")
    rows = read_trace(trace)[first:]
    x, ratio, expected = [], [], []
    for previous, r in zip(rows, rows[1:]):
        if r["proxy_x"] == previous["proxy_x"]:
            continue  # held: the finger is inside the cone, the ratio is below mu
        x.append(1000.0 * r["proxy_x"])
        ratio.append(math.hypot(r["force_x"], r["force_y"]) / r["force_z"])
        u = r["proxy_x"] / SIZE + 0.5
        expected.append(0.4 * (0.5 + 0.5 * math.sin(2.0 * math.pi * PERIODS * u)))
    friction_axes.plot(x, expected, lw=2.5, alpha=0.4, label="0.4 * map at the proxy")
    friction_axes.plot(x, ratio, ".", ms=2, label="|f_t| / |f_n| on sliding ticks")
    friction_axes.set_ylabel("sliding ratio")
    friction_axes.set_xlabel("proxy x [mm]")
    friction_axes.legend(fontsize=8, loc="upper right")
    friction_axes.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    main()
