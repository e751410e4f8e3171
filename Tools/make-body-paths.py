#!/usr/bin/env python3
"""Writes the scripted finger paths of the body scenes (Data/Paths/Bodies, for Data/Scenes/*.json
with bodies; Documentation/Dynamics.md). Most are a few corners, played by linear interpolation;
the windmill's and the crank's follow their rotors around a circle and are sampled at 1 kHz.

Usage (from the repository's root): /usr/bin/python3 Tools/make-body-paths.py [--out Data/Paths/Bodies]
"""
import argparse
import math
import os

# Corners (t, x, y, z) in seconds and metres.
CORNERS = {
    # The lever (hinged at y = -0.1 m, top face at z = 0.005 m): press 3 cm from its free end,
    # hold, let go.
    "lever-press-hold": [(0, 0, 0.08, 0.03), (0.2, 0, 0.08, 0), (1.5, 0, 0.08, 0),
                         (1.7, 0, 0.08, 0.03)],
    # The pendulum (hung from z = 0.1 m, its face at y = -0.005 m): push near the bottom for
    # 0.3 s, then leave it to swing.
    "pendulum-push-release": [(0, 0, -0.03, -0.08), (0.1, 0, -0.006, -0.08),
                              (0.3, 0, 0.004, -0.08), (0.32, 0, -0.05, -0.08),
                              (3.5, 0, -0.05, -0.08)],
    # The test mass (top face at z = 0.005 m): press 9 mm, hold 2 s, let go.
    "sensor-press-release": [(0, 0, 0, 0.03), (0.2, 0, 0, -0.004), (2.2, 0, 0, -0.004),
                             (2.21, 0, 0, 0.05), (4, 0, 0, 0.05)],
    # The free block (its side at x = -0.05 m, centre height 0.006 m): push along x for 0.2 s.
    # The ball pendulum (box.obj upright, hung by a ball at z = 0.1 m, its side at x = 0.05 m):
    # push the side near the bottom along -x for 0.3 s, then step aside (-y) and let it swing in
    # its own plane.
    "ball-pendulum-push-release": [(0, 0.08, 0, -0.08), (0.1, 0.052, 0, -0.08),
                                   (0.3, 0.04, 0, -0.08), (0.32, 0.06, -0.05, -0.08),
                                   (3.5, 0.06, -0.05, -0.08)],
    # The carousel (box.obj flat, on a hinge about z through its centre): flick its long side
    # (x = 0.05 m) along -x, 8 cm from the axis, then lift off above it and let it coast.
    "carousel-flick": [(0, 0.08, 0.08, 0), (0.1, 0.047, 0.08, 0), (0.15, 0.04, 0.08, 0),
                       (0.17, 0.04, 0.08, 0.03), (3, 0.04, 0.08, 0.03)],
    "free-block-push": [(0, -0.08, 0, 0.006), (0.1, -0.052, 0, 0.006), (0.3, -0.03, 0, 0.006),
                        (0.31, -0.09, 0, 0.006), (2, -0.09, 0, 0.006)],
}

# The windmill: its rotor (the plate on edge, face at y = -0.005 m, turning about z through the
# origin) is pushed 4 cm from the axis by a finger that comes in, then goes round the axis at
# WINDMILL_SPEED for WINDMILL_TURN_SECONDS, pressed 2 mm behind the face, then backs off.
WINDMILL_RADIUS = 0.04
WINDMILL_SPEED = 2.0
WINDMILL_TURN_SECONDS = 1.5
WINDMILL_PRESSED_Y = -0.004
RATE = 1000.0

# The crank (Data/Scenes/crank.xml: hanging from a hinge about y through the origin, its handle's
# pushed face at x = 0.008 m, 10 cm below the axis, centred at y = -0.019 m): a finger comes in
# against the face, 1 mm deep for the 1 mm proxy, goes round the axis at CRANK_SPEED for
# CRANK_TURN_SECONDS (a turn and an eighth), slides off the handle along -y and leaves it to
# settle.
CRANK_SPEED = math.pi
CRANK_TURN_SECONDS = 2.25
CRANK_FACE = (0.008, -0.019, -0.1)


def windmill():
    rows = []
    approach = 0.1
    for k in range(int(approach * RATE) + 1):
        t = k / RATE
        y = -0.03 + (WINDMILL_PRESSED_Y + 0.03) * t / approach
        rows.append((t, WINDMILL_RADIUS, y, 0.0))
    for k in range(1, int(WINDMILL_TURN_SECONDS * RATE) + 1):
        t = approach + k / RATE
        angle = WINDMILL_SPEED * k / RATE
        c, s = math.cos(angle), math.sin(angle)
        rows.append((t, c * WINDMILL_RADIUS - s * WINDMILL_PRESSED_Y,
                     s * WINDMILL_RADIUS + c * WINDMILL_PRESSED_Y, 0.0))
    # Back off along the face's normal, away from the rotor, and stay there.
    end, x, y, z = rows[-1]
    angle = WINDMILL_SPEED * WINDMILL_TURN_SECONDS
    away = (math.sin(angle), -math.cos(angle))
    rows.append((end + 0.02, x + 0.03 * away[0], y + 0.03 * away[1], z))
    rows.append((end + 0.5, x + 0.03 * away[0], y + 0.03 * away[1], z))
    return rows


def crank():
    rows = []
    approach = 0.2
    x0, y0, z0 = CRANK_FACE
    for k in range(int(approach * RATE) + 1):
        t = k / RATE
        rows.append((t, 0.03 + (x0 - 0.03) * t / approach, y0, z0))
    for k in range(1, int(CRANK_TURN_SECONDS * RATE) + 1):
        t = approach + k / RATE
        angle = CRANK_SPEED * k / RATE
        c, s = math.cos(angle), math.sin(angle)
        # A turn by `angle` about +y: x' = x cos + z sin, z' = -x sin + z cos.
        rows.append((t, x0 * c + z0 * s, y0, -x0 * s + z0 * c))
    end, x, y, z = rows[-1]
    rows.append((end + 0.1, x, -0.06, z))
    rows.append((end + 3.0, x, -0.06, z))
    return rows


def write(path, rows):
    with open(path, "w") as stream:
        stream.write("t,x,y,z\n")
        for row in rows:
            stream.write(",".join(repr(float(v)) if isinstance(v, float) else str(v)
                                  for v in row) + "\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default="Data/Paths/Bodies")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, corners in CORNERS.items():
        write(os.path.join(args.out, name + ".csv"), corners)
    write(os.path.join(args.out, "windmill-turn.csv"), windmill())
    write(os.path.join(args.out, "crank-turn.csv"), crank())
    print("wrote %d paths to %s" % (len(CORNERS) + 2, args.out))


if __name__ == "__main__":
    main()
