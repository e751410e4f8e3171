#!/usr/bin/env python3
"""Checks what `proxima run` reports for bodies with no single joint coordinate, on the ball
pendulum (Data/Scenes/ball-pendulum.json) and the free block (free-block.json): every row of
--bodies-out has q, the angle of the body's turn from the start (2 atan2(|(qx, qy, qz)|, |qw|)
of the row's own quaternion), the last row's q is the summary's, and the summary's q_rate is an
angular speed (never negative; the ball pendulum still swinging, the gliding block not turning).

Usage: check_turn_bodies_out.py PROXIMA SOURCE_DIR
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def check(proxima, source, scene, path, turns):
    with tempfile.TemporaryDirectory(prefix="proxima-turn-") as work:
        poses, trace = os.path.join(work, "poses.csv"), os.path.join(work, "trace.csv")
        done = subprocess.run(
            [proxima, "run", "--scene", os.path.join(source, "Data", "Scenes", scene), "--path",
             os.path.join(source, "Data", "Paths", "Bodies", path), "--out", trace,
             "--bodies-out", poses], capture_output=True, text=True, check=True)
        summary = json.loads(done.stdout)["bodies"][0]
        with open(poses, newline="") as stream:
            rows = list(csv.reader(stream))[1:]
    largest = 0.0
    for row in rows:
        assert row[10] != "", row
        qw, qx, qy, qz, q = (float(v) for v in row[6:11])
        angle = 2.0 * math.atan2(math.sqrt(qx * qx + qy * qy + qz * qz), abs(qw))
        assert abs(q - angle) < 1e-12, (row, angle)
        largest = max(largest, q)
    assert float(rows[-1][10]) == summary["q"], (rows[-1], summary)
    assert summary["q_rate"] >= 0.0, summary
    if turns:
        assert largest > 0.05 and summary["q"] > 0.0 and summary["q_rate"] > 0.01, summary
    else:
        assert largest < 1e-6 and summary["q_rate"] < 1e-6, (largest, summary)
    print("%s: %d rows, turned up to %.6f rad; summary q %.6g rad, q_rate %.6g rad/s"
          % (scene, len(rows), largest, summary["q"], summary["q_rate"]))


def main():
    proxima, source = sys.argv[1:3]
    check(proxima, source, "ball-pendulum.json", "ball-pendulum-push-release.csv", True)
    check(proxima, source, "free-block.json", "free-block-push.csv", False)


if __name__ == "__main__":
    main()
