"""Bad input from Python: a clear error naming the option or file, as on the command line."""
import numpy
import pytest

import proxima
from conftest import needs_shared_data, shared_case


@needs_shared_data()
def test_out_of_range_settings_name_the_option():
    mesh, path, scale, _ = shared_case("screw")
    with pytest.raises(proxima.InputError, match=r"^--radius: must be above 0 and at most 1 m"):
        proxima.run(mesh=mesh, path=path, scale=scale, radius=5.0)
    with pytest.raises(proxima.InputError, match=r"^--dynamic-friction: mu_d 0.9 is above"):
        proxima.run(mesh=mesh, path=path, scale=scale, static_friction=0.5, dynamic_friction=0.9)
    with pytest.raises(proxima.InputError, match=r"^--tick-budget: 'fast'"):
        proxima.run(mesh=mesh, path=path, scale=scale, tick_budget="fast")
    with pytest.raises(ValueError):  # InputError is a ValueError
        proxima.run(mesh=mesh, path=path, scale=-1.0)


@pytest.mark.parametrize("keyword, value, takes", [
    ("radius", "a", r"a number \(an int or a float\), not str \('a'\)"),
    ("radius", "0.002", r"a number \(an int or a float\), not str \('0.002'\)"),
    ("radius", True, r"a number \(an int or a float\), not bool \(True\)"),
    ("stiffness", numpy.bool_(True), r"a number \(an int or a float\), not numpy.bool_"),
    ("scale", [1.0], r"a number \(an int or a float\), not list"),
    ("max_iterations", 1.5, r"a whole number \(an int\), not float \(1.5\)"),
    ("max_iterations", "8", r"a whole number \(an int\), not str \('8'\)"),
    ("max_iterations", False, r"a whole number \(an int\), not bool \(False\)"),
])
def test_a_keyword_of_the_wrong_type_is_a_type_error_naming_it(keyword, value, takes):
    # Not pybind11's "RuntimeError: Unable to cast Python instance", and True is not 1 m.
    with pytest.raises(TypeError, match=rf"^keyword '{keyword}' takes {takes}"):
        proxima.run(mesh="m.obj", path=numpy.zeros((2, 4)), **{keyword: value})


def test_numbers_out_of_range_name_the_option():
    path = numpy.zeros((2, 4))
    with pytest.raises(proxima.InputError,
                       match=r"^--max-iterations: must be a whole number from 1 to 1000, "
                             r"not 1180591620717411303424$"):
        proxima.run(mesh="m.obj", path=path, max_iterations=2**70)
    with pytest.raises(proxima.InputError, match=r"^--max-iterations: .*, not 0$"):
        proxima.run(mesh="m.obj", path=path, max_iterations=0)
    with pytest.raises(proxima.InputError, match=r"^--radius: must be above 0 and at most 1 m"):
        proxima.run(mesh="m.obj", path=path, radius=2**70)
    with pytest.raises(proxima.InputError, match=r"^--radius: must be above 0 and at most 1 m"):
        proxima.run(mesh="m.obj", path=path, radius=10**400)
    with pytest.raises(proxima.InputError, match=r"^--scale: must be above 0"):
        proxima.run(mesh="m.obj", path=path, scale=numpy.float32(-1.0))


def test_numbers_of_every_numeric_type_are_taken():
    # An int, numpy's scalars: the keyword's value, and only then the mesh is looked for.
    for keywords in ({"radius": 1}, {"radius": numpy.float32(0.002)},
                     {"max_iterations": numpy.int64(8)}, {"stiffness": numpy.int32(500)}):
        with pytest.raises(proxima.InputError, match="no-such-mesh.obj"):
            proxima.run(mesh="no-such-mesh.obj", path=numpy.zeros((2, 4)), **keywords)


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword 'radious'"):
        proxima.run(mesh="m.obj", path=numpy.zeros((2, 4)), radious=0.001)


@needs_shared_data()
def test_missing_files_are_named(tmp_path):
    mesh, path, scale, radius = shared_case("screw")
    missing = str(tmp_path / "no-such-mesh.obj")
    with pytest.raises(proxima.InputError, match="no-such-mesh.obj"):
        proxima.run(mesh=missing, path=path, scale=scale, radius=radius)
    with pytest.raises(proxima.InputError, match="no-such-path.csv"):
        proxima.run(mesh=mesh, path=str(tmp_path / "no-such-path.csv"), scale=scale,
                    radius=radius)


@needs_shared_data()
def test_bad_path_arrays_are_refused():
    mesh, path, scale, radius = shared_case("screw")
    rows = proxima.read_path(path)[:100].copy()
    rows[50, 2] = numpy.nan
    with pytest.raises(proxima.InputError, match=r"^path array: row 50: y is not finite"):
        proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)
    rows = proxima.read_path(path)[:100].copy()
    rows[60, 0] = 0.0
    with pytest.raises(proxima.InputError, match=r"^path array: row 60: time goes backwards"):
        proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)
    with pytest.raises(proxima.InputError, match=r"\(N, 4\) array"):
        proxima.run(mesh=mesh, path=numpy.zeros((10, 3)), scale=scale, radius=radius)
    with pytest.raises(proxima.InputError, match="closer than the proxy radius"):
        # A path that starts on the surface leaves the proxy no free side.
        trace, _ = proxima.run(mesh=mesh, path=path, scale=scale, radius=radius)
        touching = numpy.column_stack([trace["t"], trace["proxy_x"], trace["proxy_y"],
                                       trace["proxy_z"]])
        start = int(numpy.argmax(trace["contacts"] > 0))
        proxima.run(mesh=mesh, path=touching[start:] - [0, 0, 0, 0], scale=scale,
                    radius=radius * 1.5)
