# Sourced by the tests that drive a program's window through X with xdotool (view_mouse.sh,
# trainer_window_program.sh, inspector_window_program.sh), under their own Xvfb.

# find_window NAME PID ERRORS: prints the id of the first visible window whose name matches NAME,
# within 60 s (a loaded machine makes a window slowly); fails at once, with the program's ERRORS
# file, if the program PID ends first. The window is looked up again half a second after it first
# shows: one found while the toolkit was still setting up can be gone by then (CI once sent a
# view's events to such a window: BadWindow).
find_window() {
  local id=""
  for _ in $(seq 600); do
    id=$(xdotool search --onlyvisible --name "$1" 2> /dev/null | head -1 || true)
    if [ -n "$id" ]; then
      sleep 0.5
      id=$(xdotool search --onlyvisible --name "$1" 2> /dev/null | head -1 || true)
      [ -n "$id" ] && { echo "$id"; return 0; }
    fi
    kill -0 "$2" 2> /dev/null || { echo "$(basename "$0"): the program ended early:" >&2; cat "$3" >&2; return 1; }
    sleep 0.1
  done
  echo "$(basename "$0"): no window named '$1' within 60 s" >&2
  return 1
}

# wait_for_exit PID WHAT: waits up to 30 s for the program PID to end after being told to close;
# kills it and fails if it does not, naming WHAT (the key that should have closed it).
wait_for_exit() {
  for _ in $(seq 300); do
    kill -0 "$1" 2> /dev/null || return 0
    sleep 0.1
  done
  echo "$(basename "$0"): the window did not close on $2" >&2
  kill "$1"
  return 1
}
