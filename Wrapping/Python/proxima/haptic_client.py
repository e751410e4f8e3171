"""The live haptic server's Python client (Documentation/Server.md): the C++ HapticClient's
protocol (Library/Net/proxima_haptic.proto, generated here as proxima.net), for a Python
application beside a `proxima serve --device` elsewhere.

    from proxima.haptic_client import HapticClient
    client = HapticClient("haptics-pc:50051")
    client.translate(0.0, 0.0, -0.05)
    client.shape(points, triangles, name="floor")        # (N, 3) and (M, 3) arrays
    receipt = client.commit()                            # live there when it returns
    for sample in client.stream(100.0):                  # dicts, 100 per second
        draw(sample["proxy"], sample["force"])

Shapes are given as arrays (the C++ client's vertex-by-vertex calls would be slow in Python),
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
import json
import math
import os
import threading
import time

import grpc
import numpy

from proxima.net import proxima_haptic_pb2 as _messages
from proxima.net import proxima_haptic_pb2_grpc as _service

#: At most this many points or triangles in one message, as the C++ client.
PART_ITEMS = 65536

#: gRPC's reconnection after a connection drops (ms): its defaults start at 1 s and reach 120 s.
FIRST_BACKOFF_MS, MAX_BACKOFF_MS = 50, 2000


class OwnershipEnded(PermissionError):
    """An owner's ownership of the model ended without its asking: its connection dropped (the
    server went away or restarted; a restarted server starts without the model)."""


class HapticClient:
    def __init__(self, server, token=None, timeout=10.0, role="owner", tls_ca=None,
                 reconnect=10.0):
        """Connects to `server` (HOST:PORT) as the model's "owner" or as an "observer", over TLS
        when `tls_ca` names the PEM file that signs the server's certificate. ConnectionError
        when nothing answers there, PermissionError when another client owns the model.
        `reconnect`: seconds to wait for a server that went away to answer again."""
        if role not in ("owner", "observer"):
            raise ValueError(f"role: 'owner' or 'observer', not {role!r}")
        self.server = server
        self.role = role
        self.reconnect = float(reconnect)
        options = [("grpc.max_send_message_length", -1), ("grpc.max_receive_message_length", -1),
                   ("grpc.initial_reconnect_backoff_ms", FIRST_BACKOFF_MS),
                   ("grpc.max_reconnect_backoff_ms", MAX_BACKOFF_MS)]
        if tls_ca is None:
            self._channel = grpc.insecure_channel(server, options=options)
        else:
            with open(tls_ca, "rb") as stream:
                roots = stream.read()
            self._channel = grpc.secure_channel(
                server, grpc.ssl_channel_credentials(root_certificates=roots), options=options)
        try:
            grpc.channel_ready_future(self._channel).result(timeout=timeout)
        except grpc.FutureTimeoutError:
            raise ConnectionError(f"no Proxima server answers at {server} "
                                  "(is `proxima serve` running there?)") from None
        self._stub = _service.HapticServerStub(self._channel)
        self._metadata = (("proxima-token", token),) if token else ()
        self._stack = [numpy.eye(4)]
        self._material = _messages.ShapeMaterial(stiffness=1.0)
        self._shapes = []
        self._scene = None
        self._ownership = None
        self._owner_metadata = ()
        self._owns = False
        self._ownership_end = ""
        self._closing = False
        if role == "owner":
            self._hold_ownership(retry=False)

    def _hold_ownership(self, retry):
        """Claims the model: held open for the ownership's life, which ends when the call does
        (close(), or the process or its connection goes), seen by the call's done callback."""
        waiting = _Wait(self)
        while True:
            letting_go = threading.Event()
            call = self._stub.HoldOwnership(_holding(letting_go), metadata=self._metadata)
            try:
                grant = next(call)
            except grpc.RpcError as error:
                letting_go.set()
                if error.code() == grpc.StatusCode.FAILED_PRECONDITION:
                    raise PermissionError(error.details()) from None
                if retry and error.code() == grpc.StatusCode.UNAVAILABLE:
                    waiting.until_ready(error)
                    continue
                raise _error(error, self.server) from None
            self._letting_go, self._ownership = letting_go, call
            self._owner_metadata = (("proxima-owner", grant.key),)
            self._owns, self._ownership_end = True, ""
            call.add_done_callback(lambda ended, letting_go=letting_go:
                                   self._ownership_ended(ended, letting_go))
            return

    def _ownership_ended(self, call, letting_go):
        letting_go.set()  # the request generator's thread may go
        if call is not self._ownership:
            return
        self._owns = False
        if not self._closing and not self._ownership_end:
            code = call.code()
            self._ownership_end = (
                "its ownership ended when its connection to the server dropped "
                f"({call.details() if code != grpc.StatusCode.OK else 'the server stopped'}): the "
                "server went away or restarted, and a restarted proxima serve starts without the "
                "model")

    @property
    def owns_model(self):
        """True while this owner's ownership holds (false for an observer, and once the
        connection it was granted on has dropped)."""
        return self._owns

    @property
    def ownership_end(self):
        """Why an owner's ownership ended without its asking; "" while it holds."""
        return self._ownership_end

    def claim_ownership(self):
        """Claims the model again for an owner whose ownership ended, waiting for a server that
        went away to answer; nothing while it still owns. PermissionError when another client
        owns the model now, ConnectionError when the server does not come back. A restarted
        server's model is empty: commit the model again."""
        if self.role != "owner":
            raise PermissionError("claim_ownership: this client observes")
        if self._owns:
            return
        self._hold_ownership(retry=True)

    def _ownership_lost(self, why):
        self._owns = False
        self._ownership_end = self._ownership_end or why
        return OwnershipEnded(f"the server at {self.server}: this client no longer owns the "
                              f"model: {why} (claim_ownership() claims it again, if no other "
                              "client has; then commit the model again)")

    # The transform stack: rigid motions applied to the shapes given after them.
    def load_identity(self):
        self._stack[-1] = numpy.eye(4)

    def push_matrix(self):
        self._stack.append(self._stack[-1].copy())

    def pop_matrix(self):
        if len(self._stack) == 1:
            raise IndexError("pop_matrix: more pops than pushes")
        self._stack.pop()

    def mult_matrix(self, matrix):
        self._stack[-1] = self._stack[-1] @ numpy.asarray(matrix, dtype=float).reshape(4, 4)

    def translate(self, x, y, z):
        move = numpy.eye(4)
        move[:3, 3] = (x, y, z)
        self.mult_matrix(move)

    def rotate(self, degrees, axis):
        axis = numpy.asarray(axis, dtype=float)
        length = numpy.linalg.norm(axis)
        if length == 0:
            raise ValueError("rotate: the axis is zero")
        x, y, z = axis / length
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        turn = numpy.eye(4)
        turn[:3, :3] = [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                        [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                        [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]
        self.mult_matrix(turn)

    def material(self, stiffness=1.0, static_friction=0.0, dynamic_friction=0.0, viscosity=0.0):
        """The material of the shapes given after (the factor on kp, friction, N s/m)."""
        self._material = _messages.ShapeMaterial(
            stiffness=stiffness, static_friction=static_friction,
            dynamic_friction=dynamic_friction, viscosity=viscosity)

    def shape(self, points, triangles, normals=None, texture_coordinates=None, name=""):
        """A shape: (N, 3) points, (M, 3) triangles by point index, optional (N, 3) normals and
        (N, 2) texture coordinates; transformed by the current matrix."""
        matrix = self._stack[-1]
        points = numpy.asarray(points, dtype=float).reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
        if normals is not None:
            normals = numpy.asarray(normals, dtype=float).reshape(-1, 3) @ matrix[:3, :3].T
        self._shapes.append((name, self._material, points,
                             numpy.asarray(triangles, dtype=numpy.uint32).reshape(-1, 3),
                             normals, texture_coordinates))

    def scene(self, file):
        """A scene file (Documentation/SceneFiles.md) as the whole model: it is sent with every
        file it names (meshes, texture images, an MJCF file), and the server reads it as
        `proxima run --scene` does; its bodies move there. Errors come back from commit()."""
        if self._shapes:
            raise RuntimeError("scene: a scene file is the whole model, and shapes are pending")
        with open(file, "rb") as stream:
            document = json.loads(stream.read())
        folder = os.path.dirname(file)
        bundle = _messages.SceneBundle(scene_name=file)
        names = {}

        def bundled(path):
            resolved = path if os.path.isabs(path) else os.path.join(folder, path)
            if resolved not in names:
                extension = os.path.splitext(resolved)[1]
                if not extension[1:].isalnum():
                    extension = ""
                names[resolved] = f"file{len(names)}{extension}"
                with open(resolved, "rb") as data:
                    bundle.files.add(local_name=names[resolved], client_name=resolved,
                                     data=data.read())
            return names[resolved]

        if isinstance(document, dict):
            if isinstance(document.get("mjcf"), str):
                document["mjcf"] = bundled(document["mjcf"])
            for entry in document.get("objects", []) if isinstance(document.get("objects"), list) else []:
                if isinstance(entry, dict) and isinstance(entry.get("mesh"), str):
                    entry["mesh"] = bundled(entry["mesh"])
                material = entry.get("material") if isinstance(entry, dict) else None
                textures = material.get("textures") if isinstance(material, dict) else None
                for texture in textures if isinstance(textures, list) else []:
                    if isinstance(texture, dict) and isinstance(texture.get("image"), str):
                        texture["image"] = bundled(texture["image"])
        bundle.scene_json = json.dumps(document).encode()
        self._scene = bundle

    def pending_shapes(self):
        return len(self._shapes)

    def _parts(self):
        if self._scene is not None:
            yield _messages.ModelUpload(scene=self._scene)
        for index, (name, material, points, triangles, normals, uvs) in enumerate(self._shapes):
            count = max(len(points), len(triangles))
            for start in range(0, max(count, 1), PART_ITEMS):
                part = _messages.ShapePart(shape=index)
                if start == 0:
                    part.name = name
                    part.material.CopyFrom(material)
                end = start + PART_ITEMS
                part.points.extend(points[start:end].ravel().tolist())
                if normals is not None:
                    part.normals.extend(normals[start:end].ravel().tolist())
                if uvs is not None:
                    part.texture_coordinates.extend(
                        numpy.asarray(uvs, dtype=float).reshape(-1, 2)[start:end].ravel().tolist())
                part.triangles.extend(triangles[start:end].ravel().tolist())
                yield _messages.ModelUpload(shape=part)
        yield _messages.ModelUpload(commit=True)

    def commit(self):
        """Sends the shapes given since the last commit as the server's new model; returns the
        receipt (version, shapes, triangles, build_ms, live_ms) once it is live there. A server
        that goes away meanwhile is waited for. ValueError with the server's words for a model it
        refuses (the old model stays); OwnershipEnded (a PermissionError) once this owner's
        ownership has ended (the shapes stay pending); PermissionError for an observer."""
        if self.role != "owner":
            raise PermissionError("commit: this client observes; only the owner changes the model")
        if not self._owns:
            raise self._ownership_lost(self._ownership_end)
        waiting = _Wait(self)
        while True:
            try:
                receipt = self._stub.UploadModel(self._parts(),
                                                 metadata=self._metadata + self._owner_metadata)
                break
            except grpc.RpcError as error:
                if error.code() == grpc.StatusCode.UNAVAILABLE:
                    waiting.until_ready(error)
                    if not self._owns:
                        raise self._ownership_lost(self._ownership_end) from None
                    continue
                if error.code() == grpc.StatusCode.FAILED_PRECONDITION:
                    # An owner's upload always carries its key: the server no longer takes it.
                    raise self._ownership_lost(
                        "the server refused its key (its connection dropped, or the server "
                        "restarted, since the server granted it)") from None
                raise _error(error, self.server) from None
        self._shapes = []
        self._scene = None
        return {"version": receipt.version, "shapes": receipt.shapes,
                "triangles": receipt.triangles, "build_ms": receipt.build_ms,
                "live_ms": receipt.live_ms}

    def stream(self, rate_hz, seconds=None):
        """The server's state, `rate_hz` samples per second (1 to 1000), as dicts (tick, t,
        finger, proxy, force, contacts, shape, flags, model_version, events, dropped_samples,
        bodies as (shape, 4x4 pose) pairs, latency_ms, reconnections), for `seconds` or until
        the caller stops iterating. A server that goes away is waited for, and the stream goes on
        from it (`reconnections` counts); ConnectionError when it does not come back."""
        end = None if seconds is None else time.monotonic() + seconds
        waiting, reconnections = _Wait(self), 0
        while True:
            call = self._stub.StreamState(_messages.StateRequest(rate_hz=rate_hz),
                                          metadata=self._metadata)
            try:
                for message in call:
                    if waiting.waiting:
                        waiting.succeeded()
                        reconnections += 1
                    received = time.time_ns()
                    yield {"tick": message.tick, "t": message.t,
                           "finger": _vector(message.finger), "proxy": _vector(message.proxy),
                           "force": _vector(message.force), "contacts": message.contacts,
                           "shape": message.shape, "flags": message.flags,
                           "model_version": message.model_version,
                           "events": [(e.shape, e.touched) for e in message.events],
                           "dropped_samples": message.dropped_samples,
                           "bodies": [(b.shape, _pose(b)) for b in message.bodies],
                           "latency_ms": (received - message.sent_ns) / 1e6,
                           "reconnections": reconnections}
                    if end is not None and time.monotonic() >= end:
                        return
                return
            except grpc.RpcError as error:
                if error.code() == grpc.StatusCode.UNAVAILABLE:
                    waiting.until_ready(error)
                    continue
                if error.code() != grpc.StatusCode.CANCELLED:
                    raise _error(error, self.server) from None
                return
            finally:
                call.cancel()

    def close(self):
        """Ends the ownership (another client may own the model then) and the connection."""
        self._closing = True
        if self._ownership is not None:
            # The call ends once the server has let go: another client may own the model then.
            self._letting_go.set()
            try:
                for _ in self._ownership:
                    pass
            except grpc.RpcError:
                pass  # the server has gone: nothing is owned there
            self._ownership = None
        self._channel.close()


def _holding(letting_go):
    """The owner's side of HoldOwnership: nothing sent, ended when the client lets go."""
    letting_go.wait()
    return
    yield  # a generator that sends no message


class _Wait:
    """One call's wait for a server that went away (UNAVAILABLE) to answer again: on the
    channel's readiness (gRPC reconnects with its backoff), bounded by the client's `reconnect`
    seconds from the first failure until a call goes through."""

    def __init__(self, client):
        self.client, self.deadline, self.backoff = client, None, FIRST_BACKOFF_MS / 1000.0

    @property
    def waiting(self):
        return self.deadline is not None

    def succeeded(self):
        self.deadline = None

    def _pause_while_ready(self, left):
        """A call refused on a connection that still looks ready (a server closing it): wait for
        the channel to leave READY, at most the next backoff, so that calls are not made again
        at once."""
        known, changed, states = threading.Event(), threading.Event(), []

        def seen(state):  # called at once with the state, then on each change
            states.append(state)
            known.set()
            if state != grpc.ChannelConnectivity.READY:
                changed.set()
        self.client._channel.subscribe(seen)
        try:
            known.wait(left)
            if states and states[0] == grpc.ChannelConnectivity.READY:
                changed.wait(min(self.backoff, left))
                self.backoff = min(2 * self.backoff, MAX_BACKOFF_MS / 1000.0)
        finally:
            self.client._channel.unsubscribe(seen)

    def until_ready(self, error):
        client = self.client
        if self.deadline is None:
            self.deadline = time.monotonic() + client.reconnect
        left = self.deadline - time.monotonic()
        if client.reconnect > 0 and left > 0:
            self._pause_while_ready(left)
            try:
                grpc.channel_ready_future(client._channel).result(
                    timeout=max(self.deadline - time.monotonic(), 0.0))
                return
            except grpc.FutureTimeoutError:
                pass
        if client.reconnect <= 0:
            raise ConnectionError(f"the server at {client.server} went away "
                                  f"({error.details()})") from None
        raise ConnectionError(f"the server at {client.server} went away and did not come back "
                              f"within {client.reconnect:g} s ({error.details()})") from None


def _vector(v):
    return numpy.array([v.x, v.y, v.z])


def _pose(body):
    """A body's pose as a 4x4 matrix: a point p of the shape as committed is now at M (p, 1)."""
    matrix = numpy.eye(4)
    matrix[:3, :3] = [_vector(body.row_x), _vector(body.row_y), _vector(body.row_z)]
    matrix[:3, 3] = _vector(body.translation)
    return matrix


def _error(error, server):
    code = error.code()
    if code == grpc.StatusCode.INVALID_ARGUMENT:
        return ValueError(error.details())
    if code == grpc.StatusCode.UNIMPLEMENTED:
        return ConnectionError(f"the server at {server} owns no device "
                               "(start it with proxima serve --device)")
    if code in (grpc.StatusCode.UNAUTHENTICATED, grpc.StatusCode.FAILED_PRECONDITION):
        return PermissionError(error.details())
    return ConnectionError(f"the server at {server} failed: {error.details()}")
