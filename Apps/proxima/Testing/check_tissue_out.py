#!/usr/bin/env python3
"""Checks `proxima run --tissue-out` on a scene with one tissue against the run's trace and
summary, which are computed apart from it:
- the header of Documentation/Tissue.md, one row per tick, in order, for object 0;
- a row is `touched` exactly when the trace's tick touches object 0;
- on a tick with one contact plane whose force was not clamped, the spring's press on the tissue
  (from the contact's depth, kp mu) has the magnitude of the spring's force from the trace's
  proxy and finger, kp |proxy - finger| (what the servo renders at the solid's steps; between
  them it renders its local model, check_tissue_servo_model.py);
- the tissue gave way while pressed (indentation and displacement above `min_depth`), and is
  back near rest at the end (displacement under a tenth of the deepest);
- the summary's deepest indentation is the column's largest, and its displacement at the end
  the last row's.

Usage: check_tissue_out.py TISSUE.csv TRACE.csv SUMMARY.json MIN_DEPTH
"""
import csv
import json
import math
import sys

# The trace's flags of a force that is not kp |proxy - finger|: clamped, fading, rate-limited.
FORCE_SHAPED = (1 << 2) | (1 << 3) | (1 << 9)
HEADER = ["tick", "t", "object", "max_displacement", "indentation", "force", "touched"]


def main():
    tissue_file, trace_file, summary_file = sys.argv[1:4]
    min_depth = float(sys.argv[4])
    with open(tissue_file, newline="") as stream:
        reader = csv.reader(stream)
        header = next(reader)
        rows = list(reader)
    assert header == HEADER, header
    with open(trace_file, newline="") as stream:
        ticks = list(csv.DictReader(stream))
    with open(summary_file) as stream:
        summary = json.load(stream)
    assert len(rows) == len(ticks) == summary["ticks"], (len(rows), len(ticks), summary["ticks"])
    tissue = summary["tissue"][0]
    compared = 0
    worst = 0.0
    deepest = 0.0
    for index, (row, tick) in enumerate(zip(rows, ticks)):
        number, obj = int(row[0]), int(row[2])
        displacement, indentation, force = (float(v) for v in row[3:6])
        touched = row[6] == "1"
        assert number == index == int(tick["tick"]) and obj == 0, row
        assert float(row[1]) == float(tick["t"]), (row, tick["t"])
        on_tissue = int(tick["contacts"]) > 0 and int(tick["object"]) == 0
        assert touched == on_tissue, (row, tick)
        deepest = max(deepest, indentation)
        if int(tick["contacts"]) == 1 and on_tissue:
            rendered = summary["stiffness_N_per_m"] * math.sqrt(sum(
                (float(tick["proxy_" + a]) - float(tick["finger_" + a])) ** 2 for a in "xyz"))
            if rendered > 1e-3 and int(tick["flags"]) & FORCE_SHAPED == 0:
                worst = max(worst, abs(force - rendered) / rendered)
                compared += 1
    assert compared > 100, compared
    assert worst < 1e-6, worst
    assert deepest > min_depth, deepest
    assert max(float(row[3]) for row in rows) > min_depth
    assert tissue["deepest_indentation_m"] == deepest, (tissue, deepest)
    assert tissue["max_displacement_at_end_m"] == float(rows[-1][3]), tissue
    assert float(rows[-1][3]) < 0.1 * deepest, (rows[-1], deepest)
    print(f"{len(rows)} rows; press against rendered force on {compared} ticks within {worst:.2g}; "
          f"deepest indentation {deepest:.4g} m; displacement at the end {float(rows[-1][3]):.3g} m")


if __name__ == "__main__":
    main()
