#!/usr/bin/env python3
"""The live server under load (Documentation/Server.md): `proxima serve --device sim`
holding a still finger at 1 kHz for RUN_SECONDS, once with no client (the floor of the same
server), once with a client following the state at 1 kHz (the stream's latency), once with
that client and another uploading the shared 1.5M-triangle skull, and once with that client and
another killed (SIGKILL) KILL_SECONDS into its upload of the skull. Each run's servo statistics
come from the server's --summary; the table goes to Documentation/ServerLoadTable.md (Server.md
links it).

Usage (from the repository's root, after a build): /usr/bin/python3 Tools/server_load.py
    [--proxima build/bin/proxima] [--mesh ../shared/data/meshes/cranium_bone_iso075mm.ply]
"""
import argparse
import json
import os
import platform
import signal
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUN_SECONDS = 10.0
FOLLOW_SECONDS = 8.0
#: Into `proxima remote upload` of the skull: reading it and streaming it (it commits at about
#: 0.5 s on this VM).
KILL_SECONDS = 0.3


def start_server(proxima, work, name):
    path = os.path.join(work, "still.csv")
    with open(path, "w") as stream:
        stream.write("t,x,y,z\n0,0,0,0.3\n600,0,0,0.3\n")
    summary = os.path.join(work, name + "-server.json")
    server = subprocess.Popen([proxima, "serve", "--listen", "127.0.0.1:0", "--device", "sim",
                               "--path", path, "--rate", "1000", "--summary", summary],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = server.stdout.readline()
    if "listening on" not in line:
        raise SystemExit("the server did not start: %r %s" % (line, server.stderr.read()))
    return server, line.strip().rsplit(" ", 1)[1], summary


def client(proxima, address, command, *arguments):
    return subprocess.Popen([proxima, "remote", "--server", address, command, *arguments],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def finish(process):
    out, err = process.communicate(timeout=120)
    if process.returncode != 0:
        raise SystemExit("a client failed: " + err)
    return json.loads(out)


def killed_upload(proxima, address, mesh):
    """Starts an upload of `mesh` and kills it KILL_SECONDS in; what the table says of it."""
    uploader = client(proxima, address, "upload", "--mesh", mesh, "--scale", "0.001")
    time.sleep(KILL_SECONDS)
    ended = uploader.poll()
    uploader.send_signal(signal.SIGKILL)
    uploader.communicate()
    return {"killed": ended is None}


def last_model_version(state_csv):
    with open(state_csv) as stream:
        rows = stream.read().splitlines()
    return int(rows[-1].split(",")[14])


def run(proxima, work, name, follow, upload, mesh):
    server, address, summary = start_server(proxima, work, name)
    start = time.monotonic()
    follower = uploader = None
    tiny = os.path.join(ROOT, "Data", "Meshes", "box.obj")
    time.sleep(0.5)
    if follow:
        # A small model to follow the proxy on (its client owns the model while it uploads),
        # then an observer's stream at 1 kHz.
        finish(client(proxima, address, "upload", "--mesh", tiny))
        state = os.path.join(work, name + "-state.csv")
        follower = client(proxima, address, "follow", "--follow", str(FOLLOW_SECONDS),
                          "--rate", "1000", "--state-out", state)
    killed = None
    if upload == "kill":
        time.sleep(1.0)
        killed = killed_upload(proxima, address, mesh)
    elif upload:
        time.sleep(1.0)
        uploader = client(proxima, address, "upload", "--mesh", mesh, "--scale", "0.001")
    followed = finish(follower) if follower else None
    uploaded = finish(uploader) if uploader else None
    if killed is not None:
        # The model the follower saw last: the small one, if the killed upload changed nothing.
        killed["model_version"] = last_model_version(state)
        uploaded = killed
    time.sleep(max(0.0, RUN_SECONDS - (time.monotonic() - start)))
    server.send_signal(signal.SIGINT)
    server.wait(timeout=60)
    with open(summary) as stream:
        return json.load(stream), followed, uploaded


def upload_cell(uploaded):
    if not uploaded:
        return ""
    if "killed" in uploaded:
        return ("killed %.1f s in%s; the model stayed version %d (the small one)" % (
            KILL_SECONDS, "" if uploaded["killed"] else " (it had already ended)",
            uploaded["model_version"]))
    return "%d triangles: built %.0f ms, live %.0f ms later" % (
        uploaded["triangles"], uploaded["build_ms"], uploaded["live_ms"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--proxima", default="build/bin/proxima")
    parser.add_argument("--mesh", default=os.path.join(
        os.path.dirname(ROOT), "shared", "data", "meshes", "cranium_bone_iso075mm.ply"))
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="server-load-")
    rows = []
    for number, (name, follow, upload) in enumerate([("no client", False, False),
                                 ("a client following at 1 kHz", True, False),
                                 ("following, and another uploading the skull", True, True),
                                 ("following, and another killed mid-upload", True, "kill")]):
        server, followed, uploaded = run(args.proxima, work, "run%d" % number, follow, upload,
                                         args.mesh)
        servo = server["servo"]
        latency = followed["latency_ms"] if followed else None
        rows.append("| %s | %d | %d (%.2f %%) | %d | %.0f / %.0f / %.0f | %s | %s | %s |" % (
            name, servo["wake_ups"], servo["late_wake_ups"],
            100.0 * servo["late_wake_ups"] / max(1, servo["wake_ups"]), servo["missed_deadlines"],
            servo["wake_latency_us"]["p50"], servo["wake_latency_us"]["p99"],
            servo["wake_latency_us"]["max"],
            "%.3f / %.3f / %.3f" % (latency["median"], latency["p99"], latency["max"])
            if latency else "",
            "%d of %d" % (followed["dropped_samples"], followed["samples"]) if followed else "",
            upload_cell(uploaded)))
        print(rows[-1])
        scheduling = servo.get("scheduling", "")
    with open(os.path.join(ROOT, "Documentation", "ServerLoadTable.md"), "w") as out:
        out.write("Measured by `Tools/server_load.py` on %s, %d cores, Linux %s: `proxima serve "
                  "--device sim` with a still finger, servo at 1000 Hz (%s), %.0f s per run, "
                  "each run its own server; the state followed for %.0f s; the upload read on the "
                  "client from `%s`.\n\n" % (
                      platform.processor() or platform.machine(), os.cpu_count(),
                      platform.release(), scheduling, RUN_SECONDS, FOLLOW_SECONDS,
                      os.path.basename(args.mesh)))
        out.write("| run | servo wake-ups | late wake-ups | missed deadlines | p50 / p99 / max "
                  "wake-up latency (us) | state latency median / p99 / max (ms) | samples dropped "
                  "| upload |\n|---|---|---|---|---|---|---|---|\n")
        out.write("\n".join(rows) + "\n")
    print("wrote Documentation/ServerLoadTable.md")


if __name__ == "__main__":
    main()
