"""proxima.check: the oracle's verdict passes a real run and catches a trace that is wrong."""
import numpy

import proxima
from conftest import needs_shared_data, shared_case


@needs_shared_data()
def test_the_oracle_passes_a_run_and_fails_a_tampered_trace():
    mesh, path, scale, radius = shared_case("screw")
    rows = proxima.read_path(path)[:1200]
    result = proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)
    verdict = proxima.check(result, rows, mesh=mesh, scale=scale, radius=radius)
    assert verdict["passed"], verdict["messages"]
    assert verdict["ticks"] == len(rows) and verdict["contact_ticks"] > 100
    assert verdict["min_clearance_m"] > -1e-9

    # Push the proxy of one contact tick half a radius toward its finger, into the screw.
    tampered = {name: column.copy() for name, column in result.trace.items()}
    tick = int(numpy.flatnonzero(tampered["contacts"] > 0)[50])
    proxy = numpy.array([tampered[f"proxy_{axis}"][tick] for axis in "xyz"])
    finger = numpy.array([tampered[f"finger_{axis}"][tick] for axis in "xyz"])
    pushed = proxy + 0.5 * radius * (finger - proxy) / numpy.linalg.norm(finger - proxy)
    for i, axis in enumerate("xyz"):
        tampered[f"proxy_{axis}"][tick] = pushed[i]
    bad = proxima.check(tampered, rows, mesh=mesh, scale=scale, radius=radius)
    assert not bad["passed"]
    assert bad["penetrations"] >= 1
    assert bad["min_clearance_m"] < -0.25 * radius


@needs_shared_data()
def test_the_oracle_fails_a_trace_that_is_cut_or_whose_force_is_not_the_servos():
    mesh, path, scale, radius = shared_case("screw")
    rows = proxima.read_path(path)[:1200]
    result = proxima.run(mesh=mesh, path=rows, scale=scale, radius=radius)

    # The first 10 ticks alone are not the path's 1,200.
    cut = {name: column[:10].copy() for name, column in result.trace.items()}
    verdict = proxima.check(cut, rows, mesh=mesh, scale=scale, radius=radius)
    assert not verdict["passed"]
    assert verdict["coverage_failures"] == 1
    assert "10 ticks" in verdict["messages"][0] and "1200" in verdict["messages"][0]

    # Every other tick left out: as many rows would not do either.
    thinned = {name: column[::2].copy() for name, column in result.trace.items()}
    assert proxima.check(thinned, rows, mesh=mesh, scale=scale, radius=radius)[
        "coverage_failures"] == 1

    # A force of zero along z where the spring pulls is not the servo's.
    zeroed = {name: column.copy() for name, column in result.trace.items()}
    zeroed["force_z"][:] = 0.0
    verdict = proxima.check(zeroed, rows, mesh=mesh, scale=scale, radius=radius)
    assert not verdict["passed"]
    assert verdict["force_failures"] > 100
    assert verdict["coverage_failures"] == 0
    assert "kp (proxy - finger)" in verdict["messages"][0]

    # The clamp: a force under the limit flagged clamped is not the servo's either.
    flagged = {name: column.copy() for name, column in result.trace.items()}
    flagged["flags"] = flagged["flags"] | 4  # force clamped
    assert proxima.check(flagged, rows, mesh=mesh, scale=scale, radius=radius)["force_failures"] > 0
