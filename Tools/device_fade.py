#!/usr/bin/env python3
"""A device lost mid-stroke, from real runs: `proxima run` records the device of the bundled
press-and-stroke run (--record-device), the recording is cut at 0.9 s, in contact, and replayed
(--device replay:FILE): past its end the replay device reports itself disconnected, as an
unplugged SpaceMouse or Falcon does, and the servo fades the force to zero over its fade time.
Plots the force magnitude on the finger of both runs against time.

Usage: Tools/device_fade.py [--proxima build/bin/proxima] [--out Documentation/Figures/device-fade.png]
"""
import argparse
import math
import os
import tempfile

from proxima_runs import proxima, read_trace
import matplotlib.pyplot as plt  # noqa: E402 (proxima_runs picks the Agg backend first)

CUT_AT = 0.9


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--out", default="Documentation/Figures/device-fade.png")
    args = parser.parse_args()
    mesh = "Data/Meshes/icosphere-4.obj"
    path = "Data/Paths/icosphere-4-press-stroke.csv"
    with tempfile.TemporaryDirectory() as folder:
        recording = os.path.join(folder, "recording.csv")
        cut = os.path.join(folder, "cut.csv")
        full_trace = os.path.join(folder, "full.csv")
        lost_trace = os.path.join(folder, "lost.csv")
        proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", full_trace,
                "--record-device", recording)
        with open(recording) as source, open(cut, "w") as target:
            for number, line in enumerate(source):
                if number == 0 or float(line.split(",")[0]) <= CUT_AT:
                    target.write(line)
        proxima(args.proxima, "run", "--mesh", mesh, "--path", path, "--out", lost_trace,
                "--device", "replay:" + cut)
        full = read_trace(full_trace)
        lost = read_trace(lost_trace)

    def magnitude(row):
        return math.sqrt(row["force_x"] ** 2 + row["force_y"] ** 2 + row["force_z"] ** 2)

    figure, axes = plt.subplots(figsize=(8, 3.6))
    axes.plot([r["t"] for r in full], [magnitude(r) for r in full], color="0.6",
              label="device connected throughout")
    axes.plot([r["t"] for r in lost], [magnitude(r) for r in lost], color="tab:red",
              label="device lost at %.1f s (replay of a cut recording)" % CUT_AT)
    axes.axvline(CUT_AT, color="tab:red", linestyle=":", linewidth=1)
    axes.set_xlim(CUT_AT - 0.3, CUT_AT + 0.3)
    axes.set_xlabel("time (s)")
    axes.set_ylabel("|force on the finger| (N)")
    axes.set_title("A lost device: the servo fades the force out over 50 ms")
    axes.legend(loc="lower left")
    figure.tight_layout()
    figure.savefig(args.out, dpi=110)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
