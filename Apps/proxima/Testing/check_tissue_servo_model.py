#!/usr/bin/env python3
"""Checks the servo's local model of a contact on tissue (Documentation/Tissue.md) on a lockstep
trace of a press that ends where it began, against the spring the trace itself gives,
kp (proxy - finger), which is what the servo rendered without the model (the proxy and the solid
do not depend on it):
- the 200 Hz sawtooth is gone: on ticks in contact whose force was not clamped, faded or
  rate-limited, the mean size of the force's second difference (tick to tick) is at most
  `max_ripple` times the spring's;
- the force never pulls the finger into the tissue (never against the spring's direction) and
  is zero out of contact;
- over the whole path, a closed cycle, the force did no positive work on the finger: the servo
  gave the hand no energy.

Usage: check_tissue_servo_model.py TRACE.csv KP MAX_RIPPLE
"""
import csv
import sys

# The trace's flags of a force that is not the servo's own law: clamped, fading, rate-limited.
FORCE_SHAPED = (1 << 2) | (1 << 3) | (1 << 9)


def vector(row, name):
    return [float(row[name + "_" + axis]) for axis in "xyz"]


def norm(v):
    return sum(c * c for c in v) ** 0.5


def main():
    trace_file, kp, max_ripple = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    with open(trace_file, newline="") as stream:
        rows = list(csv.DictReader(stream))
    failures = []
    rendered, spring, touching = [], [], []
    for row in rows:
        force = vector(row, "force")
        stretch = [p - f for p, f in zip(vector(row, "proxy"), vector(row, "finger"))]
        rendered.append(force)
        spring.append([kp * s for s in stretch])
        touching.append(int(row["contacts"]) > 0 and not int(row["flags"]) & FORCE_SHAPED)
        if int(row["contacts"]) == 0 and norm(force) != 0.0 and not int(row["flags"]) & FORCE_SHAPED:
            failures.append(f"tick {row['tick']}: a force of {norm(force):.4g} N out of contact")
        if sum(a * b for a, b in zip(force, spring[-1])) < 0.0:
            failures.append(f"tick {row['tick']}: the force pulls the finger into the tissue")

    def ripple(forces):
        sizes = [norm(f) for f in forces]
        bends = [abs(sizes[k + 1] - 2.0 * sizes[k] + sizes[k - 1]) for k in range(1, len(rows) - 1)
                 if touching[k - 1] and touching[k] and touching[k + 1]]
        return sum(bends) / len(bends), len(bends)

    (model_ripple, counted), (spring_ripple, _) = ripple(rendered), ripple(spring)
    print(f"mean |second difference| of the force over {counted} ticks in contact: "
          f"{model_ripple:.3g} N with the local model, {spring_ripple:.3g} N with the spring alone "
          f"({model_ripple / spring_ripple:.3f} of it)")
    if not model_ripple <= max_ripple * spring_ripple:
        failures.append(f"the force's ripple is {model_ripple / spring_ripple:.3f} of the spring's, "
                        f"above {max_ripple}")
    if vector(rows[0], "finger") != vector(rows[-1], "finger"):
        failures.append("the path does not end where it began: not a closed cycle")
    work = sum(sum(f * (b - a) for f, a, b in zip(rendered[k], vector(rows[k], "finger"),
                                                  vector(rows[k + 1], "finger")))
               for k in range(len(rows) - 1))
    spring_work = sum(sum(f * (b - a) for f, a, b in zip(spring[k], vector(rows[k], "finger"),
                                                         vector(rows[k + 1], "finger")))
                      for k in range(len(rows) - 1))
    print(f"work on the finger over the cycle: {work:.4g} J with the local model, "
          f"{spring_work:.4g} J with the spring alone")
    if work > 0.0:
        failures.append(f"the servo gave the hand {work:.3g} J over a closed cycle")
    for failure in failures[:20]:
        print("check_tissue_servo_model: " + failure, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
