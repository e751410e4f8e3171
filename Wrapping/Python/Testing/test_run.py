"""proxima.run against `proxima run`: the same trace, bit for bit (but solve_ns), and the same
summary (but the clock's figures), on shared meshes read by each of the readers involved."""
import json
import os
import re

import numpy
import pytest

import proxima
from conftest import (needs_shared_data, proxima_cli, read_cli_trace, shared_case,
                      without_timing)


@needs_shared_data()
@pytest.mark.parametrize("name", ["bunny", "liver", "screw"])
def test_run_gives_the_command_lines_trace(name, tmp_path):
    mesh, path, scale, radius = shared_case(name)
    out = tmp_path / "trace.csv"
    cli_summary = json.loads(proxima_cli("run", "--mesh", mesh, "--scale", str(scale),
                                         "--radius", str(radius), "--path", path,
                                         "--out", str(out)))
    trace, summary = proxima.run(mesh=mesh, path=path, scale=scale, radius=radius)
    cli_trace = read_cli_trace(out)
    assert list(trace) == list(proxima.TRACE_COLUMNS)
    for column in proxima.TRACE_COLUMNS:
        if column == "solve_ns":
            continue
        assert numpy.array_equal(trace[column].astype(numpy.float64), cli_trace[column]), column
    assert trace["proxy_x"].dtype == numpy.float64
    assert len(trace["tick"]) == cli_summary["ticks"] > 7000
    assert summary["contact_ticks"] > 1000  # the path touches: the comparison is not of free air
    cli_summary["trace"] = None  # the library run keeps its ticks in memory
    assert without_timing(summary) == without_timing(cli_summary)
    assert summary["budget"]["limited_ticks"] == 0


@needs_shared_data()
def test_a_path_array_runs_as_its_file(tmp_path):
    mesh, path, scale, radius = shared_case("screw")
    rows = proxima.read_path(path)
    assert rows.shape[1] == 4 and rows.dtype == numpy.float64
    from_file, _ = proxima.run(mesh=mesh, path=path, scale=scale, radius=radius)
    from_array, summary = proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)
    assert summary["path"] == "path array"
    for column in ("proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z", "flags"):
        assert numpy.array_equal(from_file[column], from_array[column]), column


@needs_shared_data()
def test_tick_budget_and_friction_keywords_reach_the_run(tmp_path):
    mesh, path, scale, radius = shared_case("bunny")
    short = proxima.read_path(path)[:2000]
    _, budgeted = proxima.run(mesh=mesh, path=short, scale=scale, radius=radius,
                              tick_budget="2it")
    assert budgeted["budget"]["tick_budget"] == "2it"
    assert budgeted["budget"]["limited_ticks"] > 0
    _, sticky = proxima.run(mesh=mesh, path=short, scale=scale, radius=radius,
                            static_friction=0.6, dynamic_friction=0.4)
    assert sticky["static_friction"] == 0.6
    assert sticky["stuck_ticks"] > 0


def test_a_scene_file_runs_as_on_the_command_line(tmp_path):
    source = os.environ.get("PROXIMA_SOURCE_DIR", "")
    scene = os.path.join(source, "Data", "Scenes", "spheres-on-table.json")
    path = os.path.join(source, "Data", "Paths", "spheres-on-table-press-stroke.csv")
    out = tmp_path / "trace.csv"
    cli_summary = json.loads(proxima_cli("run", "--scene", scene, "--path", path,
                                         "--radius", "0.002", "--out", str(out)))
    trace, summary = proxima.run(scene=scene, path=path, radius=0.002)
    cli_trace = read_cli_trace(out)
    for column in proxima.TRACE_COLUMNS:
        if column != "solve_ns":
            assert numpy.array_equal(trace[column].astype(numpy.float64), cli_trace[column]), column
    assert len(summary["objects"]) == 3
    assert set(trace["object"]) >= {0, 1}  # two of the three objects touched, at least
    cli_summary["trace"] = None
    assert without_timing(summary) == without_timing(cli_summary)


def test_run_settings_are_the_command_lines_options():
    """RUN_SETTINGS, from the settings table, names exactly the knobs `proxima run --help` lists
    (but the inputs and outputs), each with the default the help gives where it gives one, and
    run() refuses a bad value of each in the command line's words, naming its option."""
    shown = proxima_cli("run", "--help")
    listed = set()
    for line in shown.splitlines():
        column = line.strip().split(" ")[0]
        if column.startswith("--"):
            listed.add(column.split(",")[0])
    # What is not a knob: the run's inputs and outputs, its mode, and the device's options.
    not_knobs = {"--help", "--mesh", "--scene", "--path", "--out", "--summary", "--max-ticks",
                 "--realtime", "--no-floor", "--bodies-out", "--tissue-out",
                 "--falcon-firmware"}
    not_knobs |= {o for o in listed if o.startswith("--device") or "record" in o}
    knobs = {option for option, _, _ in proxima.RUN_SETTINGS.values()}
    assert knobs == listed - not_knobs, shown
    for keyword, (option, default, help_text) in proxima.RUN_SETTINGS.items():
        assert option == "--" + keyword.replace("_", "-")
        assert help_text in " ".join(shown.split()), option
        # Where the help names a plain default, it is the one the table gives the member.
        said = re.search(r"\(default ([^):]+)", help_text)
        if said:
            assert said.group(1) == default, (option, help_text, default)
    mesh = os.path.join(os.environ.get("PROXIMA_SOURCE_DIR", ""), "Data", "Meshes",
                        "icosphere-4.obj")
    path = numpy.array([[0.0, 0.0, 0.0, 1.0], [0.01, 0.0, 0.0, 1.0]])
    for keyword, bad in (("radius", -1.0), ("max_force", 1e9), ("max_iterations", 0),
                         ("shading", "sometimes"), ("tick_budget", "fast")):
        with pytest.raises(proxima.InputError, match="--" + keyword.replace("_", "-")):
            proxima.run(mesh=mesh, path=path, **{keyword: bad})
