#!/usr/bin/python3
"""proxima.remote-runs: `proxima serve` on loopback and `proxima remote ... run` against it.

- A remote run's trace equals a local `proxima run`'s bit for bit but for solve_ns, and its
  summary equals the local one but for the clock's figures and the trace's name (seeded probe
  paths on the shipped featuretype part and liver: STL and glTF read on the server; with
  --shared, proxima.remote-runs-shared, the same on the shared screw's and liver's person-like
  paths, and only that: status 77, a skip to ctest, where PROXIMA_SHARED_DATA lacks them).
- Bad input is refused as a local run refuses it, naming the client's file, and leaves no trace.
- With --token-file, a wrong token is refused (--token-file) and the right one runs.
- A path longer than the server's --max-ticks is refused, whatever the client's own limit.
- A server that is not there is a clear error naming --server; one killed in the middle of a run
  and started again on its address plays the run again from its start, and the trace is the
  same as a local run's.
- Scene files go with their files (meshes, an MJCF file): the crank's mechanism and the lever's
  hinged plate turn on the server as they do locally, bit for bit, and the spheres on the table
  (three objects) too; a scene that names a missing mesh is refused naming it.
- --bodies-out works remotely: the server sends the bodies' poses back, and the file equals a
  local run's bit for bit (ball, hinge and mechanism bodies); on a scene without bodies it is
  refused as locally, and writes nothing.
- The server leaves none of the runs' files behind.
Usage: remote_runs.py BUILD_DIR TEST_DATA_DIR SOURCE_DIR [--shared] (TEST_DATA_DIR: build/TestData)
"""
import csv
import glob
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
import tempfile

import serve_process

build, test_data, source = sys.argv[1], sys.argv[2], sys.argv[3]
shared_only = sys.argv[4:] == ["--shared"]
proxima = os.path.join(build, "bin", "proxima")
meshes, paths = os.path.join(test_data, "meshes"), os.path.join(test_data, "paths")
work = tempfile.mkdtemp(prefix="proxima-remote-test-")
# The servers' run folders go to a folder of this test's own (TMPDIR, which the servers started
# here inherit), so that another test's server at work at the same time (proxima.live-server's
# scene upload, under ctest -j) is not taken for one of these runs' leftovers.
SERVER_TMP = os.path.join(work, "tmp")
os.makedirs(SERVER_TMP)
os.environ["TMPDIR"] = SERVER_TMP
TIMED = ("solve_ns", "read_ms", "tree_build_ms", "run_ms", "dynamics_ns")


def fail(message):
    sys.exit(f"remote-runs: {message}")


def start_server(*extra, listen="127.0.0.1:0"):
    return serve_process.start_server(proxima, fail, *extra, listen=listen)


class HoldingProxy:
    """A TCP relay on a free loopback port to the server at `target` ("HOST:PORT"), so that a test
    knows where a run is when its server is killed: on the first connection it passes `held`
    bytes from the server to the client, then passes no more (set `holding`) and drops that
    connection when told; later connections pass everything, to whatever listens at `target`
    then (a restarted server), or are closed at once when nothing does."""

    def __init__(self, target, held):
        host, port = target.rsplit(":", 1)
        self.target, self.held = (host, int(port)), held
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.address = f"127.0.0.1:{self.listener.getsockname()[1]}"
        self.holding, self.drop = threading.Event(), threading.Event()
        self.connections = 0
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self):
        while True:
            client, _ = self.listener.accept()
            self.connections += 1
            try:
                server = socket.create_connection(self.target)
            except OSError:
                client.close()
                continue
            first = self.connections == 1
            threading.Thread(target=self._pass, args=(client, server, None), daemon=True).start()
            threading.Thread(target=self._pass, args=(server, client, self.held if first else None),
                             daemon=True).start()

    def _pass(self, source, sink, limit):
        passed = 0
        try:
            while limit is None or passed < limit:
                data = source.recv(65536 if limit is None else min(65536, limit - passed))
                if not data:
                    break
                sink.sendall(data)
                passed += len(data)
        except OSError:
            pass
        if limit is not None and passed >= limit:
            self.holding.set()
            self.drop.wait()
            # Closed as when the server's process dies. shutdown, not only close: the other
            # direction's thread still reads from the client, and a socket is not closed while it
            # does; shutdown ends both directions at once and wakes that thread.
            for end in (sink, source):
                try:
                    end.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass
        for end in (source, sink):
            try:
                end.close()
            except OSError:
                pass


def run(*arguments):
    return subprocess.run([proxima, *arguments], capture_output=True, text=True)


def rows(file):
    with open(file) as source:
        return [row[:13] + row[14:] for row in csv.reader(source)]  # all but solve_ns


def untimed(summary):
    kept = {k: v for k, v in summary.items() if k not in TIMED + ("trace",)}
    kept["budget"] = {k: v for k, v in summary["budget"].items() if k != "replay_ms"}
    return kept


def leftovers():
    return set(glob.glob(os.path.join(SERVER_TMP, "proxima-remote-??????")))


def compare_with_local(name, options, bodies=False):
    """Runs `options` here and on the server; fails unless the traces are the same (but for
    solve_ns) and the summaries too (but for the clock), and with `bodies` the --bodies-out files
    byte for byte. Returns the rows and the summary."""
    local_bodies, remote_bodies = (os.path.join(work, f"{name}-{where}-bodies.csv")
                                   for where in ("local", "remote"))
    local = run("run", *options, "--out", os.path.join(work, f"{name}-local.csv"),
                *(["--bodies-out", local_bodies] if bodies else []))
    remote = run("remote", "--server", address, "run", *options,
                 "--out", os.path.join(work, f"{name}-remote.csv"),
                 *(["--bodies-out", remote_bodies] if bodies else []))
    if local.returncode != 0 or remote.returncode != 0:
        fail(f"{name}: local {local.returncode} {local.stderr} remote {remote.returncode} "
             f"{remote.stderr}")
    local_rows = rows(os.path.join(work, f"{name}-local.csv"))
    remote_rows = rows(os.path.join(work, f"{name}-remote.csv"))
    if local_rows != remote_rows:
        first = next(i for i, (a, b) in enumerate(zip(local_rows, remote_rows)) if a != b)
        fail(f"{name}: the remote trace differs from the local one at row {first}")
    if bodies:
        with open(local_bodies, "rb") as here, open(remote_bodies, "rb") as there:
            local_poses, remote_poses = here.read(), there.read()
        if local_poses != remote_poses or local_poses.count(b"\n") < 1000:
            fail(f"{name}: the remote --bodies-out differs from the local one "
                 f"({len(remote_poses)} bytes, {len(local_poses)} here)")
    local_summary, remote_summary = json.loads(local.stdout), json.loads(remote.stdout)
    if untimed(local_summary) != untimed(remote_summary):
        fail(f"{name}: the remote summary differs: {untimed(local_summary)} "
             f"{untimed(remote_summary)}")
    return remote_rows, remote_summary


def compare_cases(cases):
    """Each (name, mesh, scale, radius, path) run here and on the server, with enough contact."""
    for name, mesh, scale, radius, path in cases:
        remote_rows, summary = compare_with_local(
            name, ["--mesh", mesh, "--scale", scale, "--radius", radius, "--path", path])
        contact = summary["contact_ticks"]
        if contact < 1000:
            fail(f"{name}: only {contact} contact ticks: the comparison says little")
        print(f"{name}: {len(remote_rows) - 1} ticks ({contact} in contact), the same as "
              "proxima run")


before = leftovers()
if shared_only:
    # The shared screw's and liver's person-like paths (../shared/data/paths/README.md).
    cases = [(name, os.path.join(meshes, mesh), scale, radius,
              os.path.join(paths, f"{name}-probe.csv"))
             for name, mesh, scale, radius in (("screw", "M3x10_screw.stl", "0.005", "0.0005"),
                                               ("liver", "VH_M_Liver.glb", "0.5", "0.002"))]
    missing = [f for case in cases for f in case[1::3] if not os.path.exists(f)]
    if missing:
        print(f"remote-runs: {', '.join(missing)} absent (PROXIMA_SHARED_DATA): skipped")
        sys.exit(77)
    server, address = start_server()
    compare_cases(cases)
    server.send_signal(signal.SIGTERM)
    if server.wait(timeout=30) != 0:
        fail(f"the server ended with {server.returncode}")
    if leftovers() - before:
        fail(f"the server left its runs' files: {sorted(leftovers() - before)}")
    print("remote runs: the same traces as local runs on the shared person-like paths")
    sys.exit(0)

# Seeded probe paths on the shipped STL part and glTF liver, made here by proxima path.
cases = []
for name, mesh, scale, radius in (("featuretype", "featuretype.STL", "0.03", "0.001"),
                                  ("liver", "VH_M_Liver.glb", "0.5", "0.002")):
    mesh, path = os.path.join(meshes, mesh), os.path.join(work, f"{name}-probe.csv")
    made = run("path", "probe", "--mesh", mesh, "--scale", scale, "--radius", radius,
               "--seed", "1", "--duration", "8", "--out", path)
    if made.returncode != 0:
        fail(f"proxima path probe on {mesh}: {made.stderr}")
    cases.append((name, mesh, scale, radius, path))
part, part_path = cases[0][1], cases[0][4]
server, address = start_server()
compare_cases(cases)

# Scene files, sent with the files they name; bodies move on the server as they do here.
scenes, body_paths = os.path.join(source, "Data", "Scenes"), os.path.join(source, "Data", "Paths")
for name, scene, path in (("crank", "crank.json", "Bodies/crank-turn.csv"),
                          ("lever", "lever.json", "Bodies/lever-press-hold.csv"),
                          ("ball", "ball-pendulum.json", "Bodies/ball-pendulum-push-release.csv"),
                          ("spheres", "spheres-on-table.json", "spheres-on-table-press-stroke.csv")):
    _, summary = compare_with_local(name, ["--scene", os.path.join(scenes, scene), "--path",
                                           os.path.join(body_paths, path)],
                                    bodies=name != "spheres")
    print(f"{name} scene: {summary['ticks']} ticks, {len(summary.get('bodies', []))} bodies, "
          "the same as proxima run")
# --bodies-out on a scene without bodies: refused as a local run refuses it, nothing written.
no_bodies = os.path.join(work, "no-bodies.csv")
refused = run("remote", "--server", address, "run", "--scene",
              os.path.join(scenes, "spheres-on-table.json"), "--path",
              os.path.join(body_paths, "spheres-on-table-press-stroke.csv"), "--out",
              os.path.join(work, "no-bodies-trace.csv"), "--bodies-out", no_bodies)
local = run("run", "--scene", os.path.join(scenes, "spheres-on-table.json"), "--path",
            os.path.join(body_paths, "spheres-on-table-press-stroke.csv"), "--out",
            os.path.join(work, "no-bodies-trace.csv"), "--bodies-out", no_bodies)
if (refused.returncode != 2 or refused.stderr != local.stderr
        or not refused.stderr.startswith("proxima: --bodies-out: the scene has no bodies")):
    fail(f"--bodies-out without bodies: status {refused.returncode}, {refused.stderr!r}, "
         f"locally {local.stderr!r}")
if os.path.exists(no_bodies) or os.path.exists(os.path.join(work, "no-bodies-trace.csv")):
    fail("a refused --bodies-out left a file")
missing_scene = os.path.join(work, "missing-mesh.json")
with open(missing_scene, "w") as out:
    out.write('{"version": 1, "objects": [{"mesh": "no-such-mesh.obj"}]}')
refused = run("remote", "--server", address, "run", "--scene", missing_scene, "--path",
              os.path.join(body_paths, "spheres-on-table-press-stroke.csv"), "--out",
              os.path.join(work, "missing.csv"))
if refused.returncode != 2 or "no-such-mesh.obj" not in refused.stderr:
    fail(f"a scene naming a missing mesh: status {refused.returncode}, {refused.stderr!r}")

# Bad input: the client's file named, as locally; no trace written.
bad_path = os.path.join(work, "bad-path.csv")
with open(bad_path, "w") as out:
    out.write("t,x,y,z\n0,1,2\n")
bad_trace = os.path.join(work, "bad.csv")
refused = run("remote", "--server", address, "run", "--mesh", part, "--scale", "0.03", "--path",
              bad_path, "--out", bad_trace)
if refused.returncode != 2 or f"{bad_path}: line 2: expected 4 values" not in refused.stderr:
    fail(f"a bad path: status {refused.returncode}, {refused.stderr!r}")
if os.path.exists(bad_trace):
    fail("a refused run left a trace")
server.send_signal(signal.SIGTERM)
if server.wait(timeout=30) != 0:
    fail(f"the server ended with {server.returncode}")

# The token.
token_file = os.path.join(work, "token")
with open(token_file, "w") as out:
    out.write("s3cret-token\n")
wrong_file = os.path.join(work, "wrong-token")
with open(wrong_file, "w") as out:
    out.write("guess\n")
server, address = start_server("--token-file", token_file)
short = os.path.join(work, "short.csv")
with open(part_path) as source, open(short, "w") as out:
    out.writelines(source.readlines()[:500])
options = ["--mesh", part, "--scale", "0.03", "--radius", "0.001", "--path", short, "--out",
           os.path.join(work, "token.csv")]
wrong = run("remote", "--server", address, "--token-file", wrong_file, "run", *options)
if wrong.returncode != 2 or "--token-file" not in wrong.stderr:
    fail(f"a wrong token: status {wrong.returncode}, {wrong.stderr!r}")
right = run("remote", "--server", address, "--token-file", token_file, "run", *options)
if right.returncode != 0:
    fail(f"the right token: status {right.returncode}, {right.stderr!r}")
server.send_signal(signal.SIGTERM)
server.wait(timeout=30)

# The server's own tick limit: the 500-row path (499 ticks) runs under a limit of 499, and is
# refused under 498 however many ticks the client allows, naming the client's path; no trace.
for limit, expected in (("499", 0), ("498", 2)):
    server, address = start_server("--max-ticks", limit)
    limited_trace = os.path.join(work, f"limited-{limit}.csv")
    limited = run("remote", "--server", address, "run", *options[:-1], limited_trace)
    server.send_signal(signal.SIGTERM)
    server.wait(timeout=30)
    if limited.returncode != expected:
        fail(f"a server limit of {limit} ticks: status {limited.returncode}, {limited.stderr!r}")
    if expected == 2 and (f"--max-ticks: {short} needs more ticks than this server plays in one "
                          f"run ({limit}, proxima serve --max-ticks)" not in limited.stderr
                          or os.path.exists(limited_trace)):
        fail(f"a server limit of {limit} ticks: {limited.stderr!r}")

# The server killed (SIGKILL) in the middle of a run and started again on its address: the client
# waits for it, plays the run again from its start there, says so, and writes the same trace as a
# local run. A relay holds the run's replies after its first megabyte (its first ticks, of about
# 3 MB), so the kill comes in the middle of the run however loaded the machine is.
long_path = os.path.join(work, "long-probe.csv")
made = run("path", "probe", "--mesh", part, "--scale", "0.03", "--radius", "0.001", "--seed", "2",
           "--duration", "30", "--out", long_path)
if made.returncode != 0:
    fail(f"proxima path probe: {made.stderr}")
long_options = ["--mesh", part, "--scale", "0.03", "--radius", "0.001", "--path", long_path]
server, address = start_server()
relay = HoldingProxy(address, 1 << 20)
client = subprocess.Popen([proxima, "remote", "--server", relay.address, "run", *long_options,
                           "--out", os.path.join(work, "restarted-remote.csv")],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
if not relay.holding.wait(timeout=120):
    client.kill()
    fail(f"the run's first megabyte never came: {client.communicate()}")
server.kill()
server.wait(timeout=30)
# A killed server cannot remove its run's folder (one that stops does: checked at the end).
for folder in leftovers() - before:
    shutil.rmtree(folder)
relay.drop.set()
server, restarted = start_server(listen=address)
try:
    out, error = client.communicate(timeout=120)
except subprocess.TimeoutExpired:
    client.kill()
    fail("a run whose server restarted did not end within 120 s")
if client.returncode != 0 or "playing the run again from its start" not in error:
    fail(f"a run whose server restarted: status {client.returncode}, {error!r}")
local = run("run", *long_options, "--out", os.path.join(work, "restarted-local.csv"))
if local.returncode != 0:
    fail(f"the local run: {local.stderr}")
if (rows(os.path.join(work, "restarted-local.csv"))
        != rows(os.path.join(work, "restarted-remote.csv"))):
    fail("a run played again after a restart differs from the local run")
if untimed(json.loads(out)) != untimed(json.loads(local.stdout)):
    fail(f"a run played again after a restart: its summary differs: {out}")
server.send_signal(signal.SIGTERM)
server.wait(timeout=30)
print(f"a run whose server was killed after its first megabyte of ticks and restarted was played "
      f"again there ({relay.connections} connections to the relay): the same trace as proxima run")

# No server there: refused at the first failed connection, not after the 10 s a slow network gets
# (8 s allows for a loaded machine; it took the whole 10 s before the client watched the
# channel's state).
started = time.monotonic()
gone = run("remote", "--server", address, "run", *options)
waited = time.monotonic() - started
if gone.returncode != 2 or "--server: no Proxima server answers" not in gone.stderr:
    fail(f"no server: status {gone.returncode}, {gone.stderr!r}")
if waited > 8.0:
    fail(f"no server: the client waited {waited:.1f} s to say so")
if leftovers() - before:
    fail(f"the server left its runs' files: {sorted(leftovers() - before)}")
print("remote runs: the same traces as local runs; bad input, tokens and a missing server "
      "refused clearly")
