"""proxima.make_path gives `proxima path`'s rows, bit for bit."""
import os

import numpy
import pytest

import proxima
from conftest import MESHES, proxima_cli


@pytest.mark.parametrize("kind,seed", [("probe", 3), ("press-stroke", 2), ("jab", 5)])
def test_make_path_gives_the_command_lines_rows(kind, seed, tmp_path):
    mesh = os.path.join(MESHES, "teapot.obj")
    out = tmp_path / "path.csv"
    proxima_cli("path", kind, "--mesh", mesh, "--scale", "0.01", "--radius", "0.001",
                "--seed", str(seed), "--duration", "2", "--out", str(out))
    made = proxima.make_path(kind, mesh=mesh, scale=0.01, radius=0.001, seed=seed, duration=2)
    assert made.shape[1] == 4 and len(made) > 100
    assert numpy.array_equal(made, proxima.read_path(str(out)))
    assert kind in proxima.path_kinds()


def test_unknown_kind_is_refused():
    with pytest.raises(proxima.InputError, match="'zigzag' is not a path kind"):
        proxima.make_path("zigzag", mesh="m.obj")
