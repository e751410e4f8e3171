"""Proxima from Python: scripted haptic runs, sessions stepped by hand, finger paths, the oracle.

    import proxima
    trace, summary = proxima.run(mesh="bunny.obj", path="probe.csv", scale=0.4, radius=0.002)
    trace["proxy_x"]       # numpy column, the same values as `proxima run`'s trace CSV
    summary["solve_ns"]    # the summary `proxima run` prints, as a dict

The keywords are `proxima run`'s options with _ for - (Documentation/Python.md). Errors in
settings, files or paths raise proxima.InputError (a ValueError) naming the option or file.
"""
import json as _json
import os as _os
from typing import NamedTuple as _NamedTuple

# Installed, the load-on-use modules of the mesh readers live in <prefix>/lib/proxima, three
# folders up from <prefix>/lib/python3/dist-packages/proxima; from the build tree the library
# finds them by itself.
_installed_modules = _os.path.normpath(
    _os.path.join(_os.path.dirname(__file__), "..", "..", "..", "proxima"))
if _os.path.isdir(_installed_modules):
    _os.environ.setdefault("PROXIMA_MODULE_DIR", _installed_modules)

from . import _proxima  # noqa: E402
from ._proxima import InputError, OutputError, Session, make_path, path_kinds, read_path  # noqa: E402,F401

#: The bit of each tick condition in a trace's `flags` column and a live sample's `flags`, by name
#: (Documentation/CommandLine.md): "force_fading" is 8, for one.
TICK_CONDITIONS = dict(_proxima.tick_conditions)

#: The keywords run, check and Session take besides mesh and scene, from the settings table
#: (Library/IO/ScriptedRun/RunSettingList.h): keyword -> (the command line's option, its default
#: as the command line spells it, its help). RUN_SETTINGS["max_force"][0] is "--max-force".
RUN_SETTINGS = dict(_proxima.run_settings)

#: The columns of a trace, in the order of trace v2's CSV header.
TRACE_COLUMNS = ("tick", "t", "finger_x", "finger_y", "finger_z", "proxy_x", "proxy_y", "proxy_z",
                 "force_x", "force_y", "force_z", "contacts", "iterations", "solve_ns", "object",
                 "flags")


class RunResult(_NamedTuple):
    """What run returns: the trace as named numpy columns, and the summary as a dict."""
    trace: dict
    summary: dict


def run(mesh=None, path=None, *, scene=None, max_ticks=1e7, **options):
    """Plays a finger path through a mesh (or a scene file) in lockstep, as `proxima run` does.

    path: a CSV file name (t,x,y,z) or an (N, 4) array of rows t, x, y, z.
    options: `proxima run`'s options with _ for -, the keys of RUN_SETTINGS (radius, max_force,
    tick_budget, ...).
    Returns RunResult(trace, summary); the trace's values are those of the CLI's CSV, bit for bit
    (but solve_ns, the one measured column).
    """
    if path is None:
        raise TypeError("run() needs a path: a CSV file name or an (N, 4) array t, x, y, z")
    columns, summary = _proxima.run(path, max_ticks, mesh=mesh, scene=scene, **options)
    return RunResult(columns, _json.loads(summary))


def check(trace, path, *, mesh=None, scene=None, **options):
    """The oracle's verdict on a trace of `path` through the mesh or scene (the settings of the
    run that made it): a dict with 'passed', the failure counts and the worst margins.

    The oracle (CGAL's AABB tree, exact predicates, an exact QP) is written apart from the solver:
    a trace is never checked against the code that made it."""
    if not hasattr(_proxima, "check_trace"):
        raise RuntimeError("this proxima was built without its tests, and so without the oracle")
    if isinstance(trace, RunResult):
        trace = trace.trace
    return _proxima.check_trace(trace, path, mesh=mesh, scene=scene, **options)
