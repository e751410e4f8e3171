"""`proxima serve` as a child process on a free loopback port, for the command-line tests of the
server (remote_runs.py, live_server.py)."""
import subprocess


def start_server(proxima, fail, *extra, listen="127.0.0.1:0"):
    """Starts `proxima serve --listen LISTEN EXTRA...`; returns (process, "HOST:PORT") from the
    line it prints once it listens, or calls fail(message) when it does not start. LISTEN is a free
    port by default; a restart gives the address its first start printed."""
    server = subprocess.Popen([proxima, "serve", "--listen", listen, *extra],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = server.stdout.readline()
    if "listening on" not in line:
        fail(f"the server did not start: {line!r} {server.stderr.read()}")
    return server, line.strip().rsplit(" ", 1)[1]
