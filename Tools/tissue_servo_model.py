#!/usr/bin/env python3
"""The servo's local model on the soft kidney: the force the servo renders against the spring
alone, kp (proxy - finger), on Data/Paths/Tissue/kidney-press.csv in lockstep at 1 kHz and 4 kHz
(the solid at 200 Hz). Writes Documentation/Figures/tissue_servo_model.png and prints the
figures Documentation/Tissue.md quotes. The proxy and the solid do not depend on the model, so
one trace gives both forces.

Usage: /usr/bin/python3 Tools/tissue_servo_model.py [--build BUILD]
"""
import argparse
import os
import platform
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "Tools"))
import proxima_runs  # noqa: E402  (sets the Agg backend)
import matplotlib.pyplot as plt  # noqa: E402

KP = 500.0
RUN = ["run", "--scene", os.path.join(ROOT, "Data", "Scenes", "kidney-tissue.json"),
       "--path", os.path.join(ROOT, "Data", "Paths", "Tissue", "kidney-press.csv"),
       "--radius", "0.004", "--stiffness", str(KP)]
# The press's first 0.2 s in contact, where the finger pushes on at a steady speed.
WINDOW = (0.36, 0.56)


def magnitude(row, name):
    return sum(row[name + "_" + axis] ** 2 for axis in "xyz") ** 0.5


def forces(rows):
    """The rendered force and the spring's, tick by tick (N)."""
    rendered = [magnitude(row, "force") for row in rows]
    spring = [KP * sum((row["proxy_" + a] - row["finger_" + a]) ** 2 for a in "xyz") ** 0.5
              for row in rows]
    return rendered, spring


def ripple(values, rows):
    """The mean size of the second difference over ticks in contact (N)."""
    bends = [abs(values[k + 1] - 2 * values[k] + values[k - 1]) for k in range(1, len(rows) - 1)
             if all(rows[j]["contacts"] > 0 for j in (k - 1, k, k + 1))]
    return sum(bends) / len(bends)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    arguments = parser.parse_args()
    binary = os.path.join(arguments.build, "bin", "proxima")
    figure, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)
    with tempfile.TemporaryDirectory() as work:
        for axis, rate in zip(axes, (1000, 4000)):
            trace = os.path.join(work, "kidney-%d.csv" % rate)
            proxima_runs.proxima(binary, *RUN, "--rate", rate, "--out", trace)
            rows = proxima_runs.read_trace(trace)
            rendered, spring = forces(rows)
            print("%d Hz: ripple %.3g N with the model, %.3g N with the spring alone (%.3f); "
                  "largest force while pressing %.3f N against %.3f N" % (
                      rate, ripple(rendered, rows), ripple(spring, rows),
                      ripple(rendered, rows) / ripple(spring, rows),
                      max(rendered[:len(rows) // 4]), max(spring[:len(rows) // 4])))
            times = [row["t"] for row in rows]
            shown = [k for k, t in enumerate(times) if WINDOW[0] <= t <= WINDOW[1]]
            axis.plot([times[k] for k in shown], [spring[k] for k in shown], color="#c0504d",
                      linewidth=0.9, label="spring alone, kp (proxy - finger)")
            axis.plot([times[k] for k in shown], [rendered[k] for k in shown], color="#1f5fa8",
                      linewidth=1.4, label="rendered: the servo's local model")
            axis.set_title("servo at %d Hz, solid at 200 Hz" % rate)
            axis.set_xlabel("time (s)")
    axes[0].set_ylabel("force on the finger (N)")
    axes[0].legend(fontsize=8, loc="upper left")
    where = "%s, %s" % (platform.node() or "machine", platform.processor() or platform.machine())
    figure.suptitle("The soft kidney pressed at 32 mm/s (kidney-press.csv), lockstep")
    figure.text(0.01, 0.01, where + "  |  /usr/bin/python3 Tools/tissue_servo_model.py",
                fontsize=7, color="grey")
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    proxima_runs.write_atomically(
        os.path.join(ROOT, "Documentation", "Figures", "tissue_servo_model.png"), figure=figure)


if __name__ == "__main__":
    main()
