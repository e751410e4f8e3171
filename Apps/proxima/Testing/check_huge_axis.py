#!/usr/bin/env python3
"""`proxima run` on the lever scene with its hinge axis given as [1e300, 0, 0] and as
[1e300, 1e300, 0], in a scratch folder: standard output is the summary and nothing else (it
parses as JSON), standard error is empty, no MUJOCO_LOG.TXT appears in the current folder, and
the lever turns, by the same angle as with the axis [1, 0, 0].

Usage: check_huge_axis.py PROXIMA SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile


def run(proxima, scene, path, folder):
    result = subprocess.run(
        [proxima, "run", "--scene", scene, "--path", path, "--out", "trace.csv"],
        cwd=folder, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, (scene, result.returncode, result.stderr)
    assert result.stderr == "", (scene, result.stderr)
    try:
        summary = json.loads(result.stdout)
    except json.JSONDecodeError as error:
        raise AssertionError(f"{scene}: standard output is not JSON ({error}):\n"
                             f"{result.stdout[:300]}")
    left = sorted(os.listdir(folder))
    assert left == ["trace.csv"], (scene, left)
    return summary["bodies"][0]["q"]


def main():
    proxima, source = sys.argv[1:3]
    testing = os.path.join(source, "Apps", "proxima", "Testing")
    path = os.path.join(source, "Data", "Paths", "Bodies", "lever-press-hold.csv")
    angles = {}
    for name, scene in [("unit", os.path.join(source, "Data", "Scenes", "lever.json")),
                        ("huge", os.path.join(testing, "huge-axis-lever-scene.json")),
                        ("diagonal", os.path.join(testing, "diagonal-huge-axis-scene.json"))]:
        with tempfile.TemporaryDirectory() as folder:
            angles[name] = run(proxima, scene, path, folder)
    print(angles)
    # The lever before the fix stayed at exactly 0 rad.
    assert abs(angles["unit"]) > 1e-4, angles
    assert angles["huge"] == angles["unit"], angles
    assert abs(angles["diagonal"]) > 1e-6, angles


if __name__ == "__main__":
    main()
