"""proxima.batch on a local Dask cluster of two workers: the same rows as the cases run one by
one, a bad case reported in its row, and the table written whole; a script that starts a batch
without `if __name__ == "__main__":` refused at once rather than left waiting for workers."""
import csv
import os
import subprocess
import sys
import textwrap
import time

import proxima
from proxima import batch
from conftest import SOURCE, needs_shared_data, shared_case


@needs_shared_data()
def test_batch_on_two_workers_matches_one_by_one(tmp_path):
    paths = []
    meshes = []
    for name in ("screw", "liver"):
        mesh, path, scale, radius = shared_case(name)
        short = tmp_path / f"{name}.csv"
        proxima.read_path(path)  # the path is readable
        with open(path) as source, open(short, "w") as out:
            out.writelines(source.readlines()[:801])
        meshes.append({"mesh": mesh, "scale": scale, "radius": radius})
        paths.append(str(short))
    # Each mesh with its own path, at two radii: four cases, and one that cannot run.
    cases = []
    for mesh, path in zip(meshes, paths):
        cases += batch.cases([mesh], [path], settings=[{}, {"radius": mesh["radius"] * 0.5}])
    cases.append({"name": "missing mesh", "mesh": str(tmp_path / "none.obj"), "path": paths[0]})

    done = []
    rows = batch.run_cases(cases, workers=2, progress=lambda d, t: done.append((d, t)))
    assert done[-1] == (5, 5)
    assert [row["name"] for row in rows] == [case["name"] for case in cases]
    assert "none.obj" in rows[-1]["error"]
    for case, row in zip(cases[:-1], rows[:-1]):
        alone = batch.run_case(case)
        assert row["trace_digest"] == alone["trace_digest"], case["name"]
        assert row["oracle_passed"] and alone["oracle_passed"], row.get("oracle")
        assert row["contact_ticks"] == alone["contact_ticks"] > 0
        assert row["iterations_max"] == alone["iterations_max"]

    table = tmp_path / "table.csv"
    batch.write_table(rows, str(table))
    with open(table) as written:
        records = list(csv.DictReader(written))
    assert len(records) == 5 and records[0]["oracle_passed"] == "True"
    assert list(tmp_path.glob(".proxima-batch-*")) == []


def run_script(folder, name, body):
    """Runs `body` as the script `name` in `folder` with this test's proxima, at most 120 s."""
    script = folder / name
    script.write_text(textwrap.dedent(body))
    start = time.monotonic()
    # The proxima this test imported, wherever PYTHONPATH found it.
    package = os.path.dirname(os.path.dirname(os.path.abspath(proxima.__file__)))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([package, os.environ.get("PYTHONPATH", "")]))
    result = subprocess.run([sys.executable, str(script)], cwd=folder, capture_output=True,
                            text=True, timeout=120, env=env)
    return result, time.monotonic() - start


def test_a_script_without_the_main_guard_is_refused_not_left_waiting(tmp_path):
    # Python.md's batch as it was, without the guard: each of the local cluster's workers
    # imported the script again and started a cluster of its own, and the script waited for
    # workers that never came (240 s and 720 leaked semaphores).
    mesh = os.path.join(SOURCE, "Data", "Meshes", "icosphere-4.obj")
    path = os.path.join(SOURCE, "Data", "Paths", "icosphere-4-press-stroke.csv")
    cases = f"batch.cases(meshes=[{{'mesh': {mesh!r}}}], paths=[{path!r}])"
    result, seconds = run_script(tmp_path, "unguarded.py", f"""
        from proxima import batch
        rows = batch.run_cases({cases}, workers=1, check_trace=False)
        print("rows", len(rows))
        """)
    assert result.returncode == 1, (result.stdout, result.stderr[-2000:])
    assert "rows" not in result.stdout
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith("RuntimeError: proxima.batch.run_cases was called at the top level of ")
    assert 'outside `if __name__ == "__main__":`' in last
    assert seconds < 60, seconds

    # A function the script calls at its top level is the same thing.
    result, _ = run_script(tmp_path, "unguarded_main.py", f"""
        from proxima import batch

        def main():
            return batch.run_cases({cases}, workers=1, check_trace=False)

        main()
        """)
    assert result.returncode == 1 and "at the top level of" in result.stderr

    # With the guard, as Python.md has it now, the batch runs.
    result, _ = run_script(tmp_path, "guarded.py", f"""
        from proxima import batch

        if __name__ == "__main__":
            rows = batch.run_cases({cases}, workers=1, check_trace=False)
            print("rows", len(rows), rows[0]["ticks"], rows[0].get("error", ""))
        """)
    assert result.returncode == 0, result.stderr[-2000:]
    assert result.stdout == "rows 1 2318 \n", result.stdout
