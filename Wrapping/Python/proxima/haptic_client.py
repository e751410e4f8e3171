"""The live haptic server's Python client (Documentation/Server.md): the C++ HapticClient
(Library/Net/HapticClient.h) itself, bound by the compiled module, for a Python application
beside a `proxima serve --device` elsewhere. Connecting, bundling a scene file with its files,
splitting large shapes, ownership, the token, TLS and reconnecting are the C++ client's; this
module gives them Python's names, numpy arrays and exceptions.

    from proxima.haptic_client import HapticClient
    client = HapticClient("haptics-pc:50051")
    client.translate(0.0, 0.0, -0.05)
    client.shape(points, triangles, name="floor")        # (N, 3) and (M, 3) arrays
    receipt = client.commit()                            # live there when it returns
    for sample in client.stream(100.0):                  # dicts, 100 per second
        draw(sample["proxy"], sample["force"])

Shapes are given as arrays (the C++ client's vertex-by-vertex calls would be slow from Python),
under a stack of rigid transforms and a material, as in the C++ client; or a whole scene file
with its meshes, textures and bodies (`scene`). One client at a time owns the model (the
default role); `role="observer"` follows the state of a model another client owns.

A server that goes away and comes back on its address (a restart) is waited for, as by the C++
client: gRPC reconnects 50 ms after the failure and then at intervals growing by 1.6 to 2 s, a
call is made again once the channel is ready, and after `reconnect` seconds (10 by default, 0 for
never) it is a ConnectionError naming the address. The stream goes on from the new server (its
samples count `reconnections`). An owner's ownership ends with the connection it was granted on:
commit() then raises OwnershipEnded (a PermissionError) until claim_ownership() claims the model
again; the client never claims it again by itself, since a restarted server starts without the
model.
"""

import time

import numpy

from proxima import _proxima

#: An owner's ownership of the model ended without its asking: its connection dropped (the server
#: went away or restarted; a restarted server starts without the model). A PermissionError.
OwnershipEnded = _proxima.OwnershipEnded


class HapticClient:
    def __init__(self, server, token=None, timeout=10.0, role="owner", tls_ca=None,
                 reconnect=10.0):
        """Connects to `server` (HOST:PORT) as the model's "owner" or as an "observer", over TLS
        when `tls_ca` names the PEM file that signs the server's certificate. ConnectionError
        when nothing answers there within `timeout` seconds, PermissionError when another client
        owns the model. `reconnect`: seconds to wait for a server that went away to answer
        again (0: never)."""
        if role not in ("owner", "observer"):
            raise ValueError(f"role: 'owner' or 'observer', not {role!r}")
        self.server = server
        self.role = role
        self.reconnect = float(reconnect)
        self._client = _proxima.HapticClient(server, token or "", role == "owner", tls_ca or "",
                                             self.reconnect, float(timeout))

    @property
    def owns_model(self):
        """True while this owner's ownership holds (false for an observer, and once the
        connection it was granted on has dropped)."""
        return self._client.owns_model()

    @property
    def ownership_end(self):
        """Why an owner's ownership ended without its asking; "" while it holds."""
        return self._client.ownership_end()

    def claim_ownership(self):
        """Claims the model again for an owner whose ownership ended, waiting for a server that
        went away to answer; nothing while it still owns. PermissionError when another client
        owns the model now (or this client observes), ConnectionError when the server does not
        come back. A restarted server's model is empty: commit the model again."""
        if self.role != "owner":
            raise PermissionError("claim_ownership: this client observes")
        self._client.claim_ownership()

    # The transform stack: rigid motions applied to the shapes given after them.
    def load_identity(self):
        self._client.load_identity()

    def push_matrix(self):
        self._client.push_matrix()

    def pop_matrix(self):
        """IndexError on more pops than pushes."""
        self._client.pop_matrix()

    def mult_matrix(self, matrix):
        """A 4x4 rigid motion (ValueError for one that scales or shears)."""
        self._client.mult_matrix(numpy.asarray(matrix, dtype=float).reshape(4, 4))

    def translate(self, x, y, z):
        self._client.translate(float(x), float(y), float(z))

    def rotate(self, degrees, axis):
        """Right-handed about `axis` (any length but zero: ValueError)."""
        x, y, z = (float(v) for v in axis)
        self._client.rotate(float(degrees), x, y, z)

    def material(self, stiffness=1.0, static_friction=0.0, dynamic_friction=0.0, viscosity=0.0):
        """The material of the shapes given after (the factor on kp, friction, N s/m)."""
        self._client.material(stiffness, static_friction, dynamic_friction, viscosity)

    def shape(self, points, triangles, normals=None, texture_coordinates=None, name=""):
        """A shape: (N, 3) points, (M, 3) triangles by point index, optional (N, 3) normals and
        (N, 2) texture coordinates; transformed by the current matrix."""
        self._client.shape(numpy.asarray(points, dtype=float).reshape(-1, 3),
                           numpy.asarray(triangles, dtype=numpy.int64).reshape(-1, 3),
                           None if normals is None else numpy.asarray(normals, dtype=float),
                           None if texture_coordinates is None
                           else numpy.asarray(texture_coordinates, dtype=float),
                           name)

    def scene(self, file):
        """A scene file (Documentation/SceneFiles.md) as the whole model: checked here as
        `proxima run --scene` checks it (proxima.InputError, a ValueError, naming the file and
        its defect), then sent with every file it names (meshes, texture images, an MJCF file);
        its bodies move there. RuntimeError while shapes are pending."""
        self._client.scene(str(file))

    def pending_shapes(self):
        return self._client.pending_shapes()

    def commit(self):
        """Sends the shapes given since the last commit as the server's new model; returns the
        receipt (version, shapes, triangles, build_ms, live_ms) once it is live there. A server
        that goes away meanwhile is waited for. ValueError with the server's words for a model it
        refuses (the old model stays); OwnershipEnded (a PermissionError) once this owner's
        ownership has ended (the shapes stay pending); PermissionError for an observer."""
        if self.role != "owner":
            raise PermissionError("commit: this client observes; only the owner changes the model")
        return self._client.commit()

    def stream(self, rate_hz, seconds=None):
        """The server's state, `rate_hz` samples per second (1 to 1000), as dicts (tick, t,
        finger, proxy, force, contacts, shape, flags, model_version, events, dropped_samples,
        bodies as (shape, 4x4 pose) pairs, latency_ms, reconnections), for `seconds` or until
        the caller stops iterating. A server that goes away is waited for, and the stream goes on
        from it (`reconnections` counts); ConnectionError when it does not come back."""
        end = None if seconds is None else time.monotonic() + seconds
        self._client.start_stream(float(rate_hz))
        try:
            while end is None or time.monotonic() < end:
                # Short waits, so that the generator notices its end and its deadline.
                sample = self._client.next_sample(0.1)
                if sample is not None:
                    yield sample
                    continue
                why = self._client.stream_end()
                if why:
                    raise ConnectionError(why)
        finally:
            self._client.stop_stream()

    def close(self):
        """Ends the stream, the ownership (another client may own the model then) and the
        connection."""
        self._client.close()
