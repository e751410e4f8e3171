"""proxima.Session: stepped by hand, it gives the ticks of a whole run."""
import numpy

import proxima
from conftest import needs_shared_data, shared_case


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
