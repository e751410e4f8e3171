"""Shared by the figure scripts in Tools/: run the proxima command line, write finger paths and
read trace files (DESIGN.md section 3)."""
import csv
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")  # no display on CI machines


def proxima(binary, *arguments):
    """Runs `proxima ARGUMENTS...`, failing loudly; its JSON report is not needed here."""
    subprocess.run([binary] + [str(a) for a in arguments], check=True, stdout=subprocess.DEVNULL)


def write_path(path, points, rate=1000.0):
    """Writes a finger path file: one row per servo tick, `points` in metres."""
    with open(path, "w") as f:
        f.write("t,x,y,z\n")
        for k, (x, y, z) in enumerate(points):
            f.write("%.17g,%.17g,%.17g,%.17g\n" % (k / rate, x, y, z))


def read_trace(path):
    """The rows of a trace file, with numbers as floats and ints."""
    rows = []
    with open(path) as f:
        for row in csv.DictReader(f):
            rows.append({key: (int(value) if key in ("tick", "contacts", "iterations", "solve_ns",
                                                        "object", "flags")
                               else float(value)) for key, value in row.items()})
    return rows


def write_atomically(path, text=None, figure=None):
    """Writes a file through a temporary one beside it, so that a failed write leaves nothing."""
    folder = os.path.dirname(path)
    handle, temporary = tempfile.mkstemp(dir=folder, suffix=os.path.splitext(path)[1])
    try:
        with os.fdopen(handle, "w") as f:
            if text is not None:
                f.write(text)
        if figure is not None:
            figure.savefig(temporary, dpi=110)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
