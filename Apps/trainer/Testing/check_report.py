#!/usr/bin/python3
"""Runs proxima-trainer on one exercise and path and checks its report (a ctest entry).

Usage: check_report.py TRAINER EXERCISE PATH REPORT [--needs FILE] [--marks M]
                       [--screenshot S --at T] CHECK...
With --needs, a FILE that is absent (a shared mesh, which may not ship) skips the check: status
77, which ctest takes for a skip, with a line saying why. A CHECK is KEY=VALUE or KEY<VALUE or KEY>VALUE, KEY a dotted path into the report
(tasks.0.passed, damage_events.#, peak_force_n); `#` is a list's length; VALUE is JSON
(true, 3, "liver", null). With --screenshot, the file must be a PNG of 800 x 600 pixels. Fails
with every failed check listed.
"""

import json
import os
import re
import struct
import subprocess
import sys


def png_size(path):
    """(width, height) from a PNG's IHDR chunk, or None when the file is not a PNG."""
    with open(path, "rb") as stream:
        head = stream.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def lookup(report, key):
    value = report
    for part in key.split("."):
        if part == "#":
            value = len(value)
        elif isinstance(value, list):
            value = value[int(part)]
        else:
            value = value[part]
    return value


def main():
    trainer, exercise, path, report_path, *rest = sys.argv[1:]
    command = [trainer, "--exercise", exercise, "--path", path, "--report", report_path]
    screenshot = None
    while rest[:1] and rest[0] in ("--needs", "--marks", "--screenshot", "--at"):
        if rest[0] == "--needs":
            if not os.path.exists(rest[1]):
                print(f"check_report: {rest[1]} is absent (PROXIMA_SHARED_DATA): skipped")
                sys.exit(77)
            rest = rest[2:]
            continue
        command += rest[:2]
        if rest[0] == "--screenshot":
            screenshot = rest[1]
        rest = rest[2:]
    for output in (report_path, screenshot):
        if output and os.path.exists(output):
            os.remove(output)
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"proxima-trainer exited {run.returncode}: {run.stderr.strip()}")
    print(run.stdout.strip())
    with open(report_path) as stream:
        report = json.load(stream)
    failures = []
    for check in rest:
        key, operator, expected = re.match(r"([^=<>]+)([=<>])(.*)", check).groups()
        actual = lookup(report, key)
        wanted = json.loads(expected)
        ok = {"=": actual == wanted,
              "<": actual is not None and actual < wanted,
              ">": actual is not None and actual > wanted}[operator]
        print(f"{'ok  ' if ok else 'FAIL'} {key} {operator} {expected}: {json.dumps(actual)}")
        if not ok:
            failures.append(check)
    if screenshot:
        size = png_size(screenshot) if os.path.exists(screenshot) else None
        print(f"{'ok  ' if size == (800, 600) else 'FAIL'} {screenshot}: {size}")
        if size != (800, 600):
            failures.append("screenshot of 800 x 600")
    if failures:
        sys.exit("failed: " + ", ".join(failures))


if __name__ == "__main__":
    main()
