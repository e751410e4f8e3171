"""What the Python tests share: where the build, the sources and the test meshes and paths are
(ctest sets PROXIMA_BUILD_DIR, PROXIMA_SOURCE_DIR and PROXIMA_TEST_DATA, the build's test-data
folder: the shipped meshes, and the shared ones where PROXIMA_SHARED_DATA is present), and the
cases they run."""
import os
import signal
import subprocess

import numpy
import pytest

BUILD = os.environ.get("PROXIMA_BUILD_DIR", "")
SOURCE = os.environ.get("PROXIMA_SOURCE_DIR", "")
TEST_DATA = os.environ.get("PROXIMA_TEST_DATA", "")
MESHES = os.path.join(TEST_DATA, "meshes")
PATHS = os.path.join(TEST_DATA, "paths")

#: The shared probe paths with the settings their README gives: mesh, scale, radius.
SHARED_CASES = {
    "bunny": ("stanford-bunny.obj", 0.4, 0.002),
    "liver": ("VH_M_Liver.glb", 0.5, 0.002),
    "screw": ("M3x10_screw.stl", 0.005, 0.0005),
}

#: Summary keys measured on the clock: the rest must be equal between two runs of a case.
TIMED_KEYS = ("solve_ns", "read_ms", "tree_build_ms", "run_ms")


def shared_files():
    """The files of SHARED_CASES: meshes that may not ship and the probe paths, both only in
    PROXIMA_SHARED_DATA."""
    for name, (mesh, _, _) in SHARED_CASES.items():
        yield os.path.join(MESHES, mesh)
        yield os.path.join(PATHS, f"{name}-probe.csv")


def needs_shared_data():
    """Marks a test `shared_data` (ctest runs those as Python.SharedData, label shared-data) and
    skips it, naming what is missing, where the shared files are absent."""
    missing = [f for f in shared_files() if not os.path.isfile(f)]
    skip = pytest.mark.skipif(bool(missing), reason=f"shared data not found: {', '.join(missing)}"
                              " (PROXIMA_SHARED_DATA)")

    def mark(test):
        return pytest.mark.shared_data(skip(test))
    return mark


def pytest_configure(config):
    config.addinivalue_line("markers", "shared_data: needs files only PROXIMA_SHARED_DATA has")


def pytest_sessionfinish(session, exitstatus):
    """A run in which a case was skipped and none failed ends with status 77, which ctest reports
    as a skip (SKIP_RETURN_CODE), so that a skipped case never passes unseen."""
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if exitstatus == 0 and reporter is not None and reporter.stats.get("skipped"):
        session.exitstatus = 77


def shared_case(name):
    mesh, scale, radius = SHARED_CASES[name]
    return os.path.join(MESHES, mesh), os.path.join(PATHS, f"{name}-probe.csv"), scale, radius


def first_rows(path_file, rows, folder):
    """The first `rows` samples of a path file, as a file of their own in `folder`."""
    with open(path_file) as source:
        lines = source.readlines()[: rows + 1]
    short = os.path.join(folder, f"first-{rows}-{os.path.basename(path_file)}")
    with open(short, "w") as out:
        out.writelines(lines)
    return short


def proxima_cli(*arguments):
    """Runs build/bin/proxima; returns its standard output, failing the test on an error."""
    done = subprocess.run([os.path.join(BUILD, "bin", "proxima"), *arguments],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def read_cli_trace(file):
    """A trace CSV as named float64 columns: %.17g values parse back to the same doubles."""
    table = numpy.genfromtxt(file, delimiter=",", names=True, dtype=numpy.float64)
    return {name: table[name] for name in table.dtype.names}


def without_timing(summary):
    return {k: v for k, v in summary.items() if k not in TIMED_KEYS + ("budget",)}


def read_obj(file):
    """An OBJ file's points and triangles (the first three corners of each face) as arrays."""
    points, triangles = [], []
    with open(file) as stream:
        for line in stream:
            fields = line.split()
            if fields and fields[0] == "v":
                points.append([float(v) for v in fields[1:4]])
            elif fields and fields[0] == "f":
                triangles.append([int(f.split("/")[0]) - 1 for f in fields[1:4]])
    return numpy.array(points), numpy.array(triangles)


@pytest.fixture
def live_server(tmp_path):
    """`proxima serve --device sim` on a free loopback port, its finger above the origin for
    0.5 s, then pressing down to z = 4.5 cm by 1 s and held there: "HOST:PORT"."""
    path = tmp_path / "press.csv"
    path.write_text("t,x,y,z\n0,0,0,0.08\n0.5,0,0,0.08\n1.0,0,0,0.045\n600,0,0,0.045\n")
    process = subprocess.Popen([os.path.join(BUILD, "bin", "proxima"), "serve", "--listen",
                                "127.0.0.1:0", "--device", "sim", "--path", str(path)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    assert "listening on" in line, process.stderr.read()
    yield line.strip().rsplit(" ", 1)[1]
    process.send_signal(signal.SIGINT)
    assert process.wait(timeout=30) == 0
