"""Many scripted cases (meshes x paths x settings) on a Dask cluster, gathered into one table.

    from proxima import batch

    if __name__ == "__main__":  # a local cluster's workers import the script again
        cases = batch.cases(meshes=[{"mesh": "bunny.obj", "scale": 0.4}],
                            paths=["bunny-probe.csv"], settings=[{"radius": 0.002}])
        table = batch.run_cases(cases)           # a local cluster of two worker processes
        table = batch.run_cases(cases, scheduler="tcp://farm:8786")   # many machines
        batch.write_table(table, "results.csv")

Each case runs proxima.run and, with check=True, the oracle on its trace (proxima.check). A row
holds the case, the run's figures, the oracle's verdict and a digest of the trace's deterministic
columns (all but solve_ns), so that a farm's results can be compared with a run one by one.
From a shell: python3 -m proxima.batch CASES.json [--scheduler ADDRESS] [--out TABLE.csv].
"""
import argparse
import ast
import csv
import hashlib
import io
import itertools
import json
import os
import sys
import tempfile

import numpy

from . import check, run, TRACE_COLUMNS

#: The columns of a row after the case's own keys.
RESULT_COLUMNS = ("ticks", "contact_ticks", "iterations_max", "solve_median_us", "solve_p99_us",
                  "solve_p999_us", "solve_max_us", "max_force_N", "budget_limited_ticks",
                  "oracle_passed", "oracle_failures", "penetrations", "tunnels",
                  "local_minimum_failures", "min_clearance_m", "trace_digest", "error")


def cases(meshes, paths, settings=({},)):
    """Every combination of a mesh (a dict with "mesh" or "scene" and its own keys, e.g. scale),
    a path (a file name, or a dict {"path": ..., "name": ...}) and settings (dicts of run keywords).
    Each case is a dict of run keywords with "name" and "path"."""
    made = []
    for mesh, path, setting in itertools.product(meshes, paths, settings):
        case = dict(mesh)
        case.update(path if isinstance(path, dict) else {"path": path})
        case.update(setting)
        if "name" not in case:
            surface = case.get("mesh") or case.get("scene")
            keys = ",".join(f"{k}={v}" for k, v in sorted(setting.items()))
            case["name"] = f"{os.path.basename(str(surface))}|{os.path.basename(str(case['path']))}|{keys}"
        made.append(case)
    return made


def trace_digest(trace):
    """SHA-256 of the trace's deterministic columns (every column but solve_ns), as stored."""
    digest = hashlib.sha256()
    for name in TRACE_COLUMNS:
        if name != "solve_ns":
            digest.update(numpy.ascontiguousarray(trace[name]).tobytes())
    return digest.hexdigest()


def run_case(case, check_trace=True):
    """One case: its run, its figures and, with check_trace, the oracle's verdict. A case that
    cannot run (a bad file, a bad setting) gives a row with its error, not an exception, so that
    one bad case does not lose the others."""
    options = {k: v for k, v in case.items() if k not in ("name", "path")}
    row = {"name": case.get("name", ""), "case": case}
    try:
        trace, summary = run(path=case["path"], **options)
        solve = summary["solve_ns"]
        row.update({
            "ticks": summary["ticks"],
            "contact_ticks": summary["contact_ticks"],
            "iterations_max": summary["iterations"]["max"],
            "solve_median_us": solve["median"] / 1e3,
            "solve_p99_us": solve["p99"] / 1e3,
            "solve_p999_us": solve["p99.9"] / 1e3,
            "solve_max_us": solve["max"] / 1e3,
            "max_force_N": summary["max_force_N"],
            "budget_limited_ticks": summary["budget"]["limited_ticks"],
            "trace_digest": trace_digest(trace),
            "summary": summary,
        })
        if check_trace:
            verdict = check(trace, case["path"], **options)
            row.update({
                "oracle_passed": verdict["passed"],
                "oracle_failures": verdict["failures"],
                "penetrations": verdict["penetrations"],
                "tunnels": verdict["tunnels"],
                "local_minimum_failures": verdict["local_minimum_failures"],
                "min_clearance_m": verdict["min_clearance_m"],
                "oracle": verdict,
            })
    except (ValueError, OSError) as error:
        row["error"] = str(error)
    return row


_UNGUARDED = ("proxima.batch.run_cases {where}: a local cluster's workers import the script that "
              "started them, so each would start a cluster of its own and the script would wait "
              "for workers that never come; start the batch under "
              "`if __name__ == \"__main__\":` (Documentation/Python.md)")


def _is_main_guard(node):
    """True for `if __name__ == "__main__":` (either way round)."""
    if not isinstance(node, ast.If) or not isinstance(node.test, ast.Compare):
        return False
    test = node.test
    if len(test.ops) != 1 or not isinstance(test.ops[0], ast.Eq):
        return False
    sides = [test.left, test.comparators[0]]
    names = [s for s in sides if isinstance(s, ast.Name) and s.id == "__name__"]
    texts = [s for s in sides if isinstance(s, ast.Constant) and s.value == "__main__"]
    return len(names) == 1 and len(texts) == 1


def _guarded(tree, line):
    """True when `line` of the module `tree` is in the body of an `if __name__ == "__main__":`."""
    for node in ast.walk(tree):
        if _is_main_guard(node) and node.body and \
                node.body[0].lineno <= line <= node.body[-1].end_lineno:
            return True
    return False


def _refuse_an_unguarded_script():
    """Raises RuntimeError when run_cases is about to start a local cluster from a script's top
    level outside `if __name__ == "__main__":`, and when it is called while a process started by
    spawn (as Dask starts a local cluster's workers) imports its parent's __main__: the workers of
    such a script would run its batch again. Scripts read from stdin, `-c` and interactive
    sessions have no file for the workers to import, and pass."""
    import multiprocessing

    # multiprocessing's own flag for "bootstrapping": set while spawn's child imports __main__.
    if getattr(multiprocessing.current_process(), "_inheriting", False):
        raise RuntimeError(_UNGUARDED.format(
            where="was called while a worker process imported the script that started it"))
    main = sys.modules.get("__main__")
    script = getattr(main, "__file__", None)
    if main is None or not script:
        return
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_code.co_name == "<module>"
                                     and frame.f_globals is vars(main)):
        frame = frame.f_back
    if frame is None:
        return
    try:
        with open(script, encoding="utf-8") as source:
            tree = ast.parse(source.read(), script)
    except (OSError, SyntaxError, ValueError, UnicodeDecodeError):
        return
    if not _guarded(tree, frame.f_lineno):
        raise RuntimeError(_UNGUARDED.format(
            where=f"was called at the top level of {script} (line {frame.f_lineno}), outside "
                  f"`if __name__ == \"__main__\":`"))


def run_cases(case_list, scheduler=None, workers=2, check_trace=True, progress=None):
    """Runs every case on a Dask cluster and returns their rows in the order of `case_list`.

    scheduler: None for a local cluster of `workers` processes (one thread each: a case is
    single-threaded and the timings stay honest), or the address of a running scheduler
    ("tcp://host:8786") whose workers have proxima installed and see the case files at the same
    paths. progress: called with (done, total) as cases finish."""
    from distributed import Client, LocalCluster, as_completed

    cluster = None
    if scheduler is None:
        _refuse_an_unguarded_script()
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    try:
        # pure=False: a case run twice is run twice (its timings differ), never served from cache.
        futures = [client.submit(run_case, case, check_trace, pure=False, key=f"proxima-case-{i}")
                   for i, case in enumerate(case_list)]
        index = {future.key: i for i, future in enumerate(futures)}
        rows = [None] * len(futures)
        for done, future in enumerate(as_completed(futures), start=1):
            rows[index[future.key]] = future.result()
            if progress is not None:
                progress(done, len(futures))
        return rows
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def table_rows(rows):
    """The rows as flat records: name, then RESULT_COLUMNS (empty where a row has none)."""
    return [[row.get("name", "")] + [row.get(column, "") for column in RESULT_COLUMNS]
            for row in rows]


def write_table(rows, file):
    """Writes the rows as CSV, all of it or nothing: a temporary beside `file`, renamed into place
    when complete. An error leaves nothing behind and is raised (OSError)."""
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow(("name",) + RESULT_COLUMNS)
    writer.writerows(table_rows(rows))
    folder = os.path.dirname(os.path.abspath(file))
    handle, temporary = tempfile.mkstemp(prefix=".proxima-batch-", dir=folder)
    try:
        with os.fdopen(handle, "w") as out:
            out.write(text.getvalue())
            out.flush()
            os.fsync(out.fileno())
        os.replace(temporary, file)
    except BaseException:
        os.unlink(temporary)
        raise


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m proxima.batch",
        description="Runs scripted cases on a Dask cluster and writes their table.")
    parser.add_argument("cases", help="JSON file: a list of cases (dicts of proxima.run keywords "
                                      "with 'path' and an optional 'name')")
    parser.add_argument("--scheduler", help="Address of a Dask scheduler (default: a local "
                                            "cluster)")
    parser.add_argument("--workers", type=int, default=2,
                        help="Worker processes of the local cluster (default 2)")
    parser.add_argument("--no-check", action="store_true", help="Skip the oracle's verdicts")
    parser.add_argument("--out", help="Table CSV to write (default: standard output)")
    arguments = parser.parse_args(argv)
    try:
        with open(arguments.cases) as source:
            case_list = json.load(source)
    except (OSError, ValueError) as error:
        print(f"proxima.batch: {arguments.cases}: {error}", file=sys.stderr)
        return 2
    if not isinstance(case_list, list) or not all(isinstance(c, dict) and "path" in c
                                                  for c in case_list):
        print(f"proxima.batch: {arguments.cases}: expected a list of cases, each a dict with "
              "'path'", file=sys.stderr)
        return 2
    interactive = sys.stderr.isatty()

    def progress(done, total):
        if interactive:
            print(f"\rproxima.batch: {done} of {total} cases", end="", file=sys.stderr)

    rows = run_cases(case_list, scheduler=arguments.scheduler, workers=arguments.workers,
                     check_trace=not arguments.no_check, progress=progress)
    if interactive:
        print(file=sys.stderr)
    if arguments.out:
        write_table(rows, arguments.out)
    else:
        writer = csv.writer(sys.stdout, lineterminator="\n")
        writer.writerow(("name",) + RESULT_COLUMNS)
        writer.writerows(table_rows(rows))
    failed = [row for row in rows if row.get("error") or row.get("oracle_passed") is False]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
