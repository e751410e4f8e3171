#!/usr/bin/env python3
"""Checks the trace and summary of `proxima run` on a path that starts at the centre of the
bundled 5 cm sphere and leaves it (issue 13): the proxy starts outside and is never inside, the
first tick and only it carries flag 1024, the force stays under the clamp and ramps in at the
servo's rate limit, the proxy is at the finger once the finger is out, and the summary says where
the proxy started.

usage: check_start_inside_trace.py TRACE.csv SUMMARY.json
"""
import csv
import json
import math
import sys

SPHERE_RADIUS = 0.05
PROXY_RADIUS = 0.001  # proxima run's default --radius
FACET_SAG = 1e-4  # icosphere-4's faces lie this close inside the round sphere
MAX_FORCE = 10.0  # --max-force default
RATE_LIMIT = 200.0  # N/s after a start outside, for the scene-change window
WINDOW = 0.1
STARTED_OUTSIDE = 1024


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def main(trace_path, summary_path):
    failures = []
    with open(trace_path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        return ["empty trace"]
    previous_force = (0.0, 0.0, 0.0)
    previous_t = None
    free_rows = 0
    for row in rows:
        tick = int(row["tick"])
        t = float(row["t"])
        finger = tuple(float(row["finger_" + a]) for a in "xyz")
        proxy = tuple(float(row["proxy_" + a]) for a in "xyz")
        force = tuple(float(row["force_" + a]) for a in "xyz")
        flagged = int(row["flags"]) & STARTED_OUTSIDE != 0
        if flagged != (tick == 0):
            failures.append(f"tick {tick}: flag 1024 is {flagged}")
        if norm(proxy) < SPHERE_RADIUS + PROXY_RADIUS - FACET_SAG:
            failures.append(f"tick {tick}: the proxy is inside, {norm(proxy)} m from the centre")
        if norm(force) > MAX_FORCE * (1 + 1e-12):
            failures.append(f"tick {tick}: force {norm(force)} N above the clamp")
        if tick == 0 and norm(force) != 0.0:
            failures.append(f"tick 0: force {norm(force)} N, expected the ramp to start at 0")
        if previous_t is not None and t < WINDOW:
            step = norm(tuple(a - b for a, b in zip(force, previous_force)))
            if step > RATE_LIMIT * (t - previous_t) * (1 + 1e-9) + 1e-12:
                failures.append(f"tick {tick}: the force jumped {step} N in one tick")
        if norm(finger) > SPHERE_RADIUS + 2 * PROXY_RADIUS and finger[2] > 0:
            free_rows += 1
            gap = norm(tuple(a - b for a, b in zip(proxy, finger)))
            if gap > 1e-9:
                failures.append(f"tick {tick}: the finger is out but the proxy is {gap} m from it")
        previous_force = force
        previous_t = t
    if free_rows < 400:
        failures.append(f"only {free_rows} ticks with the finger out of the sphere")
    with open(summary_path) as handle:
        summary = json.load(handle)
    started = summary.get("started_inside")
    if not isinstance(started, dict):
        failures.append(f"summary: started_inside is {started!r}")
    else:
        if started.get("object") != 0 or started.get("ticks") != 1:
            failures.append(f"summary: started_inside is {started!r}")
        if not abs(started.get("winding_number", 0) - 1.0) < 1e-9:
            failures.append(f"summary: winding number {started.get('winding_number')}")
        moved = started.get("moved_m", 0)
        if not SPHERE_RADIUS - FACET_SAG < moved < SPHERE_RADIUS + 2 * PROXY_RADIUS:
            failures.append(f"summary: moved {moved} m")
    return failures


if __name__ == "__main__":
    problems = main(sys.argv[1], sys.argv[2])
    for problem in problems[:20]:
        print(problem)
    if problems:
        print(f"{len(problems)} problems")
        sys.exit(1)
    print("ok")
