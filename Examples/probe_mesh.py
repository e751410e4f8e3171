#!/usr/bin/python3
"""Load a mesh, play a finger path over it in lockstep and print, per tick, the proxy and the force
a device would render: probe_mesh.cpp's program in Python, on an installed Proxima.

    PYTHONPATH=PREFIX/lib/python3/dist-packages python3 probe_mesh.py MESH SCALE RADIUS PATH.csv

Writes CSV to standard output (tick,t,proxy xyz,force xyz, every digit) and the largest force to
standard error: the same numbers as `proxima run`'s trace.
"""
import sys

import numpy

import proxima


def main(argv):
    if len(argv) != 5:
        print(f"usage: {argv[0]} MESH SCALE RADIUS PATH.csv", file=sys.stderr)
        return 2
    mesh, scale, radius, path = argv[1], float(argv[2]), float(argv[3]), argv[4]
    try:
        trace, summary = proxima.run(mesh=mesh, path=path, scale=scale, radius=radius)
    except proxima.InputError as error:
        print(error, file=sys.stderr)
        return 2
    columns = ("tick", "t", "proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z")
    print(",".join(columns))
    for row in zip(*(trace[name] for name in columns)):
        # repr gives the shortest digits that read back as the same double.
        print(",".join([str(int(row[0]))] + [repr(float(value)) for value in row[1:]]))
    force = numpy.sqrt(trace["force_x"] ** 2 + trace["force_y"] ** 2 + trace["force_z"] ** 2)
    print(f"{summary['ticks']} ticks, {summary['contact_ticks']} in contact, "
          f"largest force {force.max():.3f} N", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
