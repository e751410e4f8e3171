"""proxima.haptic_client against `proxima serve --device sim`: the Python client of the live
server, the C++ client bound, uploads a sphere under a scripted finger that
presses 5 mm into it, and follows the proxy: never inside the sphere (its distance from the
centre against the polyhedron's inscribed radius), the held force within kp times the spring's
stretch, a touch event for the shape; a malformed model is refused in the server's words. A
server killed and started again: the observer follows on, the owner is told it no longer owns the
model and claims it again; one that does not come back is a ConnectionError naming it."""
import os
import signal
import subprocess

import numpy
import pytest

from conftest import BUILD, SOURCE, read_obj

grpc = pytest.importorskip("grpc")
from proxima import TICK_CONDITIONS  # noqa: E402
from proxima.haptic_client import HapticClient, OwnershipEnded  # noqa: E402 (after the skip)

KP, RADIUS, HELD_Z = 1000.0, 0.001, 0.045


def test_the_python_client_uploads_and_follows(live_server):
    server = live_server
    points, triangles = read_obj(os.path.join(SOURCE, "Data", "Meshes", "icosphere-4.obj"))
    a, b, c = (points[triangles[:, i]] for i in range(3))
    normals = numpy.cross(b - a, c - a)
    inscribed = numpy.min(numpy.abs(numpy.sum(normals * a, axis=1)) /
                          numpy.linalg.norm(normals, axis=1))
    client = HapticClient(server)
    client.push_matrix()
    client.rotate(90.0, (0, 0, 1))  # a sphere about its centre: the same sphere, turned
    client.shape(points, triangles, name="sphere")
    client.pop_matrix()
    receipt = client.commit()
    assert receipt["version"] == 2 and receipt["triangles"] == 5120 and receipt["live_ms"] >= 0
    held, events, live = [], [], None
    for sample in client.stream(200.0):
        events += sample["events"]
        assert sample["latency_ms"] < 1000.0
        if sample["model_version"] == receipt["version"]:
            live = sample["t"] if live is None else live
            distance = numpy.linalg.norm(sample["proxy"])
            assert distance >= inscribed + RADIUS - 1e-9
            # Held: the finger at rest, past the servo's 0.1 s ramp after the model's swap.
            # Not fading: the runtime fades the force while its proxy loop is starved.
            fading = sample["flags"] & TICK_CONDITIONS["force_fading"]
            if sample["t"] > max(1.05, live + 0.2) and not fading:
                held.append(sample)
        if len(held) >= 50:
            break
    assert (0, True) in events
    for sample in held:
        assert sample["contacts"] >= 1 and sample["shape"] == 0
        assert KP * (inscribed + RADIUS - HELD_Z) - 1e-6 <= sample["force"][2]
        assert sample["force"][2] <= KP * (0.05 + RADIUS - HELD_Z) + 1e-6
    # A triangle beyond its points: refused by name, the sphere stays.
    client.shape([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 7]], name="broken")
    with pytest.raises(ValueError, match=r"shape 0 \('broken'\)"):
        client.commit()
    sample = next(client.stream(10.0))
    assert sample["model_version"] == receipt["version"]
    client.close()


def test_no_server_is_a_connection_error():
    with pytest.raises(ConnectionError, match="no Proxima server answers"):
        HapticClient("127.0.0.1:1", timeout=2.0)


def _serve(press, listen="127.0.0.1:0"):
    """`proxima serve --device sim` on LISTEN; (process, "HOST:PORT") once it listens."""
    process = subprocess.Popen([os.path.join(BUILD, "bin", "proxima"), "serve", "--listen", listen,
                                "--device", "sim", "--path", str(press)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    assert "listening on" in line, process.stderr.read()
    return process, line.strip().rsplit(" ", 1)[1]


def _stop(process):
    if process.poll() is None:
        process.send_signal(signal.SIGINT)
        assert process.wait(timeout=30) == 0


def test_a_restarted_server_is_followed_on_and_its_owner_told(tmp_path):
    """`proxima serve` killed (SIGKILL) and started again on its address: the observer's stream
    goes on from the new server; the owner's commit raises OwnershipEnded, as the C++ client's,
    until it claims the model again; each step waits for its event (a line, a sample)."""
    press = tmp_path / "press.csv"
    press.write_text("t,x,y,z\n0,0,0,0.08\n0.5,0,0,0.08\n1.0,0,0,0.045\n600,0,0,0.045\n")
    points, triangles = read_obj(os.path.join(SOURCE, "Data", "Meshes", "icosphere-4.obj"))
    server, address = _serve(press)
    try:
        owner = HapticClient(address)
        owner.shape(points, triangles, name="sphere")
        first = owner.commit()["version"]
        observer = HapticClient(address, role="observer")
        samples = observer.stream(100.0)
        assert next(samples)["reconnections"] == 0
        server.kill()
        server.wait(timeout=30)
        server, restarted = _serve(press, listen=address)
        assert restarted == address
        owner.shape(points, triangles, name="sphere")
        with pytest.raises(OwnershipEnded, match="no longer owns the model"):
            owner.commit()
        assert not owner.owns_model and owner.ownership_end
        assert owner.pending_shapes() == 1
        after = next(sample for sample in samples if sample["reconnections"] == 1)
        assert after["model_version"] < first  # the new server starts without the model
        owner.claim_ownership()
        assert owner.owns_model and owner.ownership_end == ""
        version = owner.commit()["version"]
        for count, sample in enumerate(samples):
            assert count < 6000, "the observer never saw the model committed again"
            if sample["model_version"] == version:
                break
        samples.close()
        owner.close()
        observer.close()
    finally:
        _stop(server)


def test_a_server_that_does_not_come_back_is_a_connection_error(tmp_path):
    press = tmp_path / "press.csv"
    press.write_text("t,x,y,z\n0,0,0,0.08\n600,0,0,0.08\n")
    server, address = _serve(press)
    try:
        observer = HapticClient(address, role="observer", reconnect=0.5)
        samples = observer.stream(100.0)
        next(samples)
        server.kill()
        server.wait(timeout=30)
        with pytest.raises(ConnectionError,
                           match=f"the server at {address} went away and did not come back "
                                 r"within 0.5 s"):
            for _ in samples:
                pass
        observer.close()
    finally:
        _stop(server)
