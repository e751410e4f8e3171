"""`proxima serve` as a child process on a free loopback port, for the command-line tests of the
server (remote_runs.py, live_server.py)."""
import subprocess


def start_server(proxima, fail, *extra):
    """Starts `proxima serve --listen 127.0.0.1:0 EXTRA...`; returns (process, "HOST:PORT") from
    the line it prints, or calls fail(message) when it does not start."""
    server = subprocess.Popen([proxima, "serve", "--listen", "127.0.0.1:0", *extra],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = server.stdout.readline()
    if "listening on" not in line:
        fail(f"the server did not start: {line!r} {server.stderr.read()}")
    return server, line.strip().rsplit(" ", 1)[1]
