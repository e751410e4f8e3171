#!/usr/bin/env python3
"""Checks `proxima run --bodies-out` on the lever scene (Data/Scenes/lever.json, a hinge about x
through (0, -0.1, 0)) against the run's trace and summary: the header of DESIGN.md section 3, one
row per tick, unit quaternions, the last row's q as the summary gives it, and each row's pose
the rotation by q about the hinge, i.e. the pose and q written apart agree.

Usage: check_bodies_out.py BODIES.csv TRACE.csv SUMMARY.json
"""
import csv
import json
import math
import sys

HEADER = ["tick", "t", "object", "x", "y", "z", "qw", "qx", "qy", "qz", "q"]
ANCHOR = (0.0, -0.1, 0.0)


def main():
    bodies_file, trace_file, summary_file = sys.argv[1:4]
    with open(bodies_file, newline="") as stream:
        reader = csv.reader(stream)
        header = next(reader)
        rows = list(reader)
    assert header == HEADER, header
    with open(trace_file, newline="") as stream:
        ticks = sum(1 for _ in csv.DictReader(stream))
    with open(summary_file) as stream:
        summary = json.load(stream)
    assert len(rows) == ticks == summary["ticks"], (len(rows), ticks, summary["ticks"])
    worst = 0.0
    for index, row in enumerate(rows):
        tick, t, obj = int(row[0]), float(row[1]), int(row[2])
        x, y, z, qw, qx, qy, qz, q = (float(v) for v in row[3:])
        assert tick == index and obj == 0, row
        assert abs(qw * qw + qx * qx + qy * qy + qz * qz - 1.0) < 1e-12, row
        # The rotation by q about x, through the anchor: quaternion (cos q/2, sin q/2, 0, 0) and
        # the translation that keeps the anchor in place, anchor - R anchor.
        expected_w, expected_x = math.cos(q / 2.0), math.sin(q / 2.0)
        ay, az = ANCHOR[1], ANCHOR[2]
        rotated_y = math.cos(q) * ay - math.sin(q) * az
        rotated_z = math.sin(q) * ay + math.cos(q) * az
        error = max(abs(qw - expected_w), abs(qx - expected_x), abs(qy), abs(qz), abs(x),
                    abs(y - (ay - rotated_y)), abs(z - (az - rotated_z)))
        worst = max(worst, error)
    assert worst < 1e-12, worst
    last_q = float(rows[-1][10])
    assert last_q == summary["bodies"][0]["q"], (last_q, summary["bodies"][0]["q"])
    deepest = min(float(row[10]) for row in rows)
    assert deepest < -0.01, deepest  # the lever was pressed down by a visible angle
    print("%d rows; pose and q agree to %.3g; deepest q %.6f rad" % (len(rows), worst, deepest))


if __name__ == "__main__":
    main()
