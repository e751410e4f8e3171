#!/usr/bin/env python3
"""Bodies from real runs (paper section 6): `proxima run` plays the paper's scenes in Data/Scenes
with their scripted paths in Data/Paths/Bodies and plots what the bodies did beside the closed
forms: the lever's spring moment k q against the moment of the finger's push (they meet when it
settles: k q = F L), and the pendulum's and the test mass's swings after release against the
periods 2 pi sqrt(I / m g d) and 2 pi / (sqrt(k / m) sqrt(1 - zeta^2)); and the crank (an MJCF
mechanism) turned a whole turn, the moment of the push against c q' + m g d sin q.

Usage: Tools/dynamics.py [--proxima build/bin/proxima] [--out Documentation/Figures/dynamics.png]
"""
import argparse
import csv
import math
import os
import tempfile

from proxima_runs import proxima, read_trace
import matplotlib.pyplot as plt  # noqa: E402 (proxima_runs picks the Agg backend first)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Data/Meshes/box.obj: 0.1 x 0.2 x 0.01 m; 0.2 kg at 1000 kg/m^3.
MASS = 0.2
LENGTH = 0.2
THICKNESS = 0.01


def run(binary, work, scene, path):
    trace = os.path.join(work, scene + "-trace.csv")
    bodies = os.path.join(work, scene + "-bodies.csv")
    proxima(binary, "run", "--scene", os.path.join(ROOT, "Data", "Scenes", scene + ".json"),
            "--path", os.path.join(ROOT, "Data", "Paths", "Bodies", path + ".csv"),
            "--out", trace, "--bodies-out", bodies)
    with open(bodies, newline="") as stream:
        rows = [{key: float(value) if value else 0.0 for key, value in row.items()}
                for row in csv.DictReader(stream)]
    return read_trace(trace), rows


def upward_crossings(rows, after):
    times = []
    for before, now in zip(rows, rows[1:]):
        if before["t"] > after and before["q"] < 0.0 <= now["q"]:
            times.append(before["t"] + (0.0 - before["q"]) / (now["q"] - before["q"]) *
                         (now["t"] - before["t"]))
    return times


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--out", default="Documentation/Figures/dynamics.png")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="dynamics-")
    fig, (lever_axes, swing_axes, crank_axes) = plt.subplots(3, 1, figsize=(9, 10))

    # The lever: hinge along x at y = -0.1 m, torsional spring 2 N m/rad.
    trace, bodies = run(args.proxima, work, "lever", "lever-press-hold")
    times, spring, push = [], [], []
    for row, body in zip(trace, bodies):
        force_on_body = (-row["force_y"], -row["force_z"])
        # The contact lies one proxy radius (1 mm) from the proxy, against the force.
        magnitude = math.hypot(row["force_y"], row["force_z"])
        if magnitude > 0.0:
            contact_y = row["proxy_y"] - 0.001 * row["force_y"] / magnitude
            contact_z = row["proxy_z"] - 0.001 * row["force_z"] / magnitude
        else:
            contact_y, contact_z = row["proxy_y"], row["proxy_z"]
        arm = (contact_y + 0.1, contact_z)
        times.append(row["t"])
        spring.append(-2.0 * body["q"])
        push.append(-(arm[0] * force_on_body[1] - arm[1] * force_on_body[0]))
    settled = int(1.4 * 1000)
    print("lever at 1.4 s: spring moment %.9f N m, push moment %.9f N m (%.2e relative)"
          % (spring[settled], push[settled], (spring[settled] - push[settled]) / push[settled]))
    lever_axes.plot(times, spring, lw=1.2, label="spring moment -k q")
    lever_axes.plot(times, push, lw=1.0, ls="--", label="moment of the finger's push (r x F)")
    lever_axes.set_ylabel("N m")
    lever_axes.set_title("Lever on a torsional spring, pressed and held: k q = F L once settled")
    lever_axes.legend(loc="upper right")

    # The pendulum and the test mass after release.
    d = LENGTH / 2.0
    inertia = MASS * (THICKNESS ** 2 + LENGTH ** 2) / 12.0 + MASS * d * d
    pendulum_period = 2.0 * math.pi * math.sqrt(inertia / (MASS * 9.81 * d))
    k, damping = 50.0, 2.0
    zeta = damping / (2.0 * math.sqrt(k * MASS))
    mass_period = 2.0 * math.pi * math.sqrt(MASS / k) / math.sqrt(1.0 - zeta ** 2)
    for scene, path, release, period, label in [
            ("pendulum", "pendulum-push-release", 0.4, pendulum_period, "pendulum q (rad)"),
            ("sensor-mass", "sensor-press-release", 2.25, mass_period,
             "test mass q (m) x 10")]:
        _, rows = run(args.proxima, work, scene, path)
        crossings = upward_crossings(rows, release)
        measured = [b - a for a, b in zip(crossings, crossings[1:])]
        print("%s: periods %s s, closed form %.6f s (%+.4f %%)"
              % (scene, ", ".join("%.6f" % p for p in measured), period,
                 100.0 * (measured[0] - period) / period))
        scale = 10.0 if scene == "sensor-mass" else 1.0
        swing_axes.plot([r["t"] for r in rows], [scale * r["q"] for r in rows], lw=1.0,
                        label="%s: period %.4f s, closed form %.4f s" % (label, measured[0], period))
    swing_axes.set_xlabel("time (s)")
    swing_axes.set_title("Pushed, then released: they swing at their closed-form periods")
    swing_axes.legend(loc="upper right", fontsize=8)

    # The crank (Data/Scenes/crank.xml): aluminium arm and handle hanging from a hinge about y,
    # damped 0.03 N m s/rad; the push's moment about the hinge against what turning it asks.
    aluminium = 2700.0
    arm_mass = aluminium * 0.02 * 0.008 * 0.12
    handle_mass = aluminium * 0.016 * 0.03 * 0.016
    weight_moment = 9.81 * (arm_mass * 0.05 + handle_mass * 0.1)
    crank_damping = 0.03
    trace, bodies = run(args.proxima, work, "crank", "crank-turn")
    arm = [body for body in bodies if body["object"] == 0]
    times, push, asked = [], [], []
    for k in range(1, len(trace) - 1):
        row = trace[k]
        magnitude = math.hypot(row["force_x"], row["force_z"])
        if not (0.2 <= row["t"] <= 2.45) or magnitude == 0.0:
            continue
        contact_x = row["proxy_x"] - 0.001 * row["force_x"] / magnitude
        contact_z = row["proxy_z"] - 0.001 * row["force_z"] / magnitude
        # (r x F)_y with F the force on the crank, -force.
        times.append(row["t"])
        push.append(-(contact_z * row["force_x"] - contact_x * row["force_z"]))
        rate = (arm[k + 1]["q"] - arm[k - 1]["q"]) / 0.002
        asked.append(crank_damping * rate + weight_moment * math.sin(arm[k]["q"]))
    crank_axes.plot(times, push, lw=1.2, label="moment of the finger's push (r x F)")
    crank_axes.plot(times, asked, lw=1.0, ls="--", label="c q' + m g d sin q (closed form)")
    crank_axes.set_xlabel("time (s)")
    crank_axes.set_ylabel("N m")
    crank_axes.set_title("Crank (MJCF: arm and handle) turned at pi rad/s against its weight and "
                         "damping")
    crank_axes.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
