"""proxima.batch on a local Dask cluster of two workers: the same rows as the cases run one by
one, a bad case reported in its row, and the table written whole."""
import csv

import proxima
from proxima import batch
from conftest import needs_shared_data, shared_case


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
