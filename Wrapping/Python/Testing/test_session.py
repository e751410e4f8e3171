"""proxima.Session: stepped by hand, it gives the ticks of a whole run."""
import os

import numpy

import proxima
from conftest import SOURCE, needs_shared_data, proxima_cli, read_cli_trace, shared_case


def test_tick_conditions_name_the_flags_bits():
    bits = proxima.TICK_CONDITIONS
    assert len(bits) == 13
    assert sorted(bits.values()) == [1 << i for i in range(13)]
    assert bits["force_fading"] == 8 and bits["started_outside"] == 1024
    assert bits["surface_lagging"] == 4096


@needs_shared_data()
def test_stepping_by_hand_gives_the_runs_ticks():
    mesh, path, scale, radius = shared_case("liver")
    rows = proxima.read_path(path)[:1500]
    trace, _ = proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)
    session = proxima.Session(mesh=mesh, scale=scale, radius=radius)
    stepped = [session.step(row[1:]) for row in rows]
    proxies = numpy.array([tick["proxy"] for tick in stepped])
    forces = numpy.array([tick["force"] for tick in stepped])
    assert numpy.array_equal(proxies[:, 0], trace["proxy_x"])
    assert numpy.array_equal(proxies[:, 2], trace["proxy_z"])
    assert numpy.array_equal(forces[:, 1], trace["force_y"])
    assert [tick["contacts"] for tick in stepped] == list(trace["contacts"])
    assert trace["contacts"].max() > 0
    assert numpy.array_equal(session.proxy, proxies[-1])


@needs_shared_data()
def test_session_run_and_force_clamp():
    mesh, path, scale, radius = shared_case("bunny")
    rows = proxima.read_path(path)[:3000]
    session = proxima.Session(mesh=mesh, scale=scale, radius=radius, max_force=0.5)
    trace = session.run(rows)
    reference, summary = proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius,
                                     max_force=0.5)
    assert numpy.array_equal(trace["proxy_y"], reference["proxy_y"])
    force = numpy.sqrt(trace["force_x"] ** 2 + trace["force_y"] ** 2 + trace["force_z"] ** 2)
    assert force.max() <= 0.5 * (1 + 1e-12)
    assert summary["clamped_force_ticks"] > 0  # the clamp was reached, not only respected


def test_a_session_moves_the_scenes_bodies_as_the_command_line_does(tmp_path):
    """The crank (an MJCF mechanism of two bodies): a session's run gives `proxima run`'s trace,
    stepping by hand gives the same ticks, and the bodies end where the command line's
    --bodies-out leaves them."""
    scene = os.path.join(SOURCE, "Data", "Scenes", "crank.json")
    path = os.path.join(SOURCE, "Data", "Paths", "Bodies", "crank-turn.csv")
    trace_file = str(tmp_path / "trace.csv")
    poses_file = str(tmp_path / "poses.csv")
    proxima_cli("run", "--scene", scene, "--path", path, "--out", trace_file,
                "--bodies-out", poses_file)
    reference = read_cli_trace(trace_file)
    session = proxima.Session(scene=scene)
    assert len(session.bodies) == 2
    assert numpy.array_equal(session.bodies[0]["rotation"], numpy.eye(3))
    trace = session.run(path)
    for column in ("proxy_x", "proxy_z", "force_x", "force_z", "contacts", "flags"):
        assert numpy.array_equal(trace[column], reference[column]), column
    assert reference["contacts"].max() > 0
    # The handle went round about y: its last pose is the one the command line wrote.
    last = numpy.genfromtxt(poses_file, delimiter=",", names=True)[-2:]
    for body, row in zip(session.bodies, last):
        assert body["object"] == int(row["object"])
        assert numpy.array_equal(body["translation"], [row["x"], row["y"], row["z"]])
        w, x, y, z = row["qw"], row["qx"], row["qy"], row["qz"]
        rotation = numpy.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                                [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                                [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
        assert numpy.allclose(body["rotation"], rotation, atol=1e-12)
    # By hand, on a fresh session, at the fingers the run's device gave: the same ticks.
    fingers = numpy.column_stack([reference["finger_x"], reference["finger_y"],
                                  reference["finger_z"]])[:1500]
    by_hand = proxima.Session(scene=scene)
    stepped = [by_hand.step(finger) for finger in fingers]
    assert numpy.array_equal([tick["proxy"][0] for tick in stepped], trace["proxy_x"][:1500])
    assert numpy.array_equal([tick["force"][2] for tick in stepped], trace["force_z"][:1500])


def test_a_session_deforms_the_scenes_tissue_as_the_command_line_does(tmp_path):
    """The kidney as soft tissue (Data/Scenes/kidney-tissue.json) pressed and released: a
    session's run gives `proxima run`'s trace bit for bit, the solid stepping every 5 ticks as
    there, and stepping by hand on a fresh session gives the same ticks."""
    scene = os.path.join(SOURCE, "Data", "Scenes", "kidney-tissue.json")
    path = os.path.join(SOURCE, "Data", "Paths", "Tissue", "kidney-press.csv")
    trace_file = str(tmp_path / "trace.csv")
    tissue_file = str(tmp_path / "tissue.csv")
    proxima_cli("run", "--scene", scene, "--path", path, "--radius", "0.004", "--stiffness",
                "500", "--out", trace_file, "--tissue-out", tissue_file)
    reference = read_cli_trace(trace_file)
    # The press dents the kidney by millimetres: a trace that depends on the solid's steps.
    indentation = numpy.genfromtxt(tissue_file, delimiter=",", names=True)["indentation"]
    assert indentation.max() > 0.004
    session = proxima.Session(scene=scene, radius=0.004, stiffness=500)
    trace = session.run(path)
    for column in ("proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z", "contacts",
                   "flags"):
        assert numpy.array_equal(trace[column], reference[column]), column
    assert reference["contacts"].max() > 0
    fingers = numpy.column_stack([reference["finger_x"], reference["finger_y"],
                                  reference["finger_z"]])[:2000]
    by_hand = proxima.Session(scene=scene, radius=0.004, stiffness=500)
    stepped = [by_hand.step(finger) for finger in fingers]
    assert numpy.array_equal([tick["proxy"][2] for tick in stepped], trace["proxy_z"][:2000])
    assert numpy.array_equal([tick["force"][2] for tick in stepped], trace["force_z"][:2000])
