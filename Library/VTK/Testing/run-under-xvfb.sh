#!/usr/bin/env bash
# Runs a command under its own Xvfb. The server picks a free display number itself
# (-displayfd), so concurrent runs cannot race for one the way `xvfb-run -a` can (two runs that
# pick the same number kill each other's windows). Usage: run-under-xvfb.sh COMMAND [ARGS...]
# -noreset: an X server resets when its last client goes; each test case closes its window, and
# the next one, connecting during the reset, got "bad X server connection".
set -euo pipefail
displayfile=$(mktemp)
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3> "$displayfile" 2> /dev/null &
server=$!
trap 'kill "$server" 2> /dev/null || true; wait "$server" 2> /dev/null || true; rm -f "$displayfile"' EXIT
for _ in $(seq 100); do
  if [ -s "$displayfile" ]; then
    break
  fi
  if ! kill -0 "$server" 2> /dev/null; then
    echo "run-under-xvfb: Xvfb did not start" >&2
    exit 1
  fi
  sleep 0.1
done
if [ ! -s "$displayfile" ]; then
  echo "run-under-xvfb: Xvfb gave no display number within 10 s" >&2
  exit 1
fi
export DISPLAY=":$(head -n 1 "$displayfile")"
"$@"
