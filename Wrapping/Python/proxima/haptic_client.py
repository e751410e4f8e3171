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


class HapticClient:
    def __init__(self, server, token=None, timeout=10.0, role="owner", tls_ca=None):
        """Connects to `server` (HOST:PORT) as the model's "owner" or as an "observer", over TLS
        when `tls_ca` names the PEM file that signs the server's certificate. ConnectionError
        when nothing answers there, PermissionError when another client owns the model."""
        if role not in ("owner", "observer"):
            raise ValueError(f"role: 'owner' or 'observer', not {role!r}")
        self.server = server
        self.role = role
        options = [("grpc.max_send_message_length", -1), ("grpc.max_receive_message_length", -1)]
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
        if role == "owner":
            # Held open for the client's life: the server keeps the model this client's until
            # the call ends (close(), or the process or its connection goes).
            self._letting_go = threading.Event()
            self._ownership = self._stub.HoldOwnership(self._holding(), metadata=self._metadata)
            try:
                grant = next(self._ownership)
            except grpc.RpcError as error:
                self._letting_go.set()
                self._ownership = None
                if error.code() == grpc.StatusCode.FAILED_PRECONDITION:
                    raise PermissionError(error.details()) from None
                raise _error(error, server) from None
            self._owner_metadata = (("proxima-owner", grant.key),)

    def _holding(self):
        """The owner's side of HoldOwnership: nothing sent, ended when the client lets go."""
        self._letting_go.wait()
        return
        yield  # a generator that sends no message

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
        receipt (version, shapes, triangles, build_ms, live_ms) once it is live there. ValueError
        with the server's words for a model it refuses (the old model stays); PermissionError for
        an observer."""
        if self.role != "owner":
            raise PermissionError("commit: this client observes; only the owner changes the model")
        try:
            receipt = self._stub.UploadModel(self._parts(),
                                             metadata=self._metadata + self._owner_metadata)
        except grpc.RpcError as error:
            raise _error(error, self.server) from None
        self._shapes = []
        self._scene = None
        return {"version": receipt.version, "shapes": receipt.shapes,
                "triangles": receipt.triangles, "build_ms": receipt.build_ms,
                "live_ms": receipt.live_ms}

    def stream(self, rate_hz, seconds=None):
        """The server's state, `rate_hz` samples per second (1 to 1000), as dicts (tick, t,
        finger, proxy, force, contacts, shape, flags, model_version, events, dropped_samples,
        bodies as (shape, 4x4 pose) pairs, latency_ms), for `seconds` or until the caller stops
        iterating."""
        call = self._stub.StreamState(_messages.StateRequest(rate_hz=rate_hz),
                                      metadata=self._metadata)
        end = None if seconds is None else time.monotonic() + seconds
        try:
            for message in call:
                received = time.time_ns()
                yield {"tick": message.tick, "t": message.t,
                       "finger": _vector(message.finger), "proxy": _vector(message.proxy),
                       "force": _vector(message.force), "contacts": message.contacts,
                       "shape": message.shape, "flags": message.flags,
                       "model_version": message.model_version,
                       "events": [(e.shape, e.touched) for e in message.events],
                       "dropped_samples": message.dropped_samples,
                       "bodies": [(b.shape, _pose(b)) for b in message.bodies],
                       "latency_ms": (received - message.sent_ns) / 1e6}
                if end is not None and time.monotonic() >= end:
                    break
        except grpc.RpcError as error:
            if error.code() != grpc.StatusCode.CANCELLED:
                raise _error(error, self.server) from None
        finally:
            call.cancel()

    def close(self):
        """Ends the ownership (another client may own the model then) and the connection."""
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
