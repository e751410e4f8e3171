#!/usr/bin/python3
"""Runs proxima-trainer on one exercise and path and checks its report (a ctest entry).

Usage: check_report.py TRAINER EXERCISE PATH REPORT [--marks M] CHECK...
A CHECK is KEY=VALUE or KEY<VALUE or KEY>VALUE, KEY a dotted path into the report
(tasks.0.passed, damage_events.#, peak_force_n); `#` is a list's length; VALUE is JSON
(true, 3, "liver", null). Fails with every failed check listed.
"""

import json
import os
import re
import subprocess
import sys


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
    if rest[:1] == ["--marks"]:
        command += ["--marks", rest[1]]
        rest = rest[2:]
    if os.path.exists(report_path):
        os.remove(report_path)
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
    if failures:
        sys.exit("failed: " + ", ".join(failures))


if __name__ == "__main__":
    main()
