#!/usr/bin/env python3
"""Checks a `proxima run --realtime` of a scene with one tissue against the lockstep run of the
same path (its summary): the threaded runtime steps the solid on the servo's clock, on a thread
of its own, so the tissue must do what it did in lockstep, up to the
finger samples the real-time loop skipped and the steps that outlasted a tick
(Documentation/Tissue.md, "On the real clock").
- lockstep launched no step late and no update met a step-old surface (late_steps and
  stale_updates are 0: the solid steps inline there);
- both summaries are of the same scene and tissue (tetrahedra, vertices, ticks per step);
- the real-time run stepped the solid at least `min_share` as often as lockstep did: a skipped
  sample only loses a step when it held every tick of one, but a slow machine skips many (600 of
  600 steps here in Release, 299-446 under AddressSanitizer, whose step outlasts several); the
  schedule itself is checked bit for bit by ThreadedTissueTests;
- the deepest indentation is within `tolerance` (relative) of lockstep's, and above 1 mm;
- the tissue is back near rest at the end (displacement under a tenth of the deepest).

Usage: check_tissue_realtime.py REALTIME.json LOCKSTEP.json MIN_SHARE TOLERANCE
"""
import json
import sys


def main():
    realtime_file, lockstep_file = sys.argv[1:3]
    min_share, tolerance = float(sys.argv[3]), float(sys.argv[4])
    with open(realtime_file) as stream:
        realtime = json.load(stream)
    with open(lockstep_file) as stream:
        lockstep = json.load(stream)
    assert realtime["mode"] == "realtime" and lockstep["mode"] == "lockstep", (
        realtime["mode"], lockstep["mode"])
    live, reference = realtime["tissue"][0], lockstep["tissue"][0]
    for key in ("object", "tetrahedra", "vertices", "fixed_vertices", "ticks_per_step"):
        assert live[key] == reference[key], (key, live[key], reference[key])
    assert reference["late_steps"] == 0 and reference["stale_updates"] == 0, reference
    assert live["steps"] >= min_share * reference["steps"], (live["steps"], reference["steps"])
    deepest, expected = live["deepest_indentation_m"], reference["deepest_indentation_m"]
    assert deepest > 0.001, deepest
    assert abs(deepest - expected) <= tolerance * expected, (deepest, expected)
    assert live["max_displacement_at_end_m"] < 0.1 * deepest, live["max_displacement_at_end_m"]
    assert realtime["contact_ticks"] > 0
    print(f"real-time: {live['steps']} solid steps (lockstep {reference['steps']}), deepest "
          f"indentation {deepest * 1e3:.4f} mm (lockstep {expected * 1e3:.4f} mm), dynamics "
          f"p99.9 {realtime['dynamics_ns']['p99.9'] / 1e3:.0f} us, servo missed deadlines "
          f"{realtime['realtime']['servo']['missed_deadlines']}; {live['late_steps']} steps "
          f"launched late, {live['stale_updates']} updates met a step-old surface")


if __name__ == "__main__":
    main()
