#!/usr/bin/env bash
# proxima-inspector's window driven through X as an engineer would (ctest Inspector.window-program,
# under its own Xvfb): open the slot's two blocks, put the cursor over the left block, press in
# with four wheel notches, drop a marker with M, move over the right block, drop another, close
# with Ctrl+Q. It must print that the session closed with two markers some distance apart.
# Usage: inspector_window_program.sh PROXIMA_INSPECTOR PART
set -euo pipefail
. "$(dirname "$0")/../../../Library/VTK/Testing/xdotool-session.sh"
inspector="$1"
part="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$inspector" --mesh "$part" --scale 0.001 --tool-radius 0.0005 > out.txt 2> err.txt &
program=$!
window=$(find_window "Proxima inspector: gap-blocks.obj" "$program" err.txt)
sleep 1.5
xdotool windowfocus --sync "$window"
# press X: move the cursor over the block at X pixels (the window is 1024 x 720, the slot in its
# middle), press in, wait for the finger (0.5 m/s at most, a loaded machine's window lags), mark.
press() {
  xdotool mousemove --window "$window" "$1" 270
  sleep 0.5
  xdotool mousemove --window "$window" "$(($1 + 1))" 270
  sleep 1
  # Wheel notches through XTEST, as a real wheel (a click sent to the window's id with
  # XSendEvent reached Qt but not always the view under the cursor).
  for _ in 1 2 3 4; do
    xdotool click 4
    sleep 0.05
  done
  sleep 3
  xdotool key --clearmodifiers m
  sleep 0.5
  xdotool key --clearmodifiers BackSpace
  sleep 1
}
press 362
press 662
xdotool key --clearmodifiers ctrl+q
wait_for_exit "$program" Ctrl+Q
wait "$program" || { echo "inspector-window: proxima-inspector failed:" >&2; cat err.txt >&2; exit 1; }
cat out.txt
line=$(grep "proxima-inspector: closed gap-blocks.obj" out.txt) ||
  { echo "inspector-window: no closing line" >&2; exit 1; }
echo "$line" | grep -q ": 2 markers, last two " ||
  { echo "inspector-window: expected two markers: $line" >&2; exit 1; }
apart=$(echo "$line" | sed -E 's/.*last two ([0-9.]+) mm apart.*/\1/')
# The blocks' tops are 2 mm apart at the slot and 22 mm at their far ends: the markers on the two
# blocks are more than the slot apart.
awk -v d="$apart" 'BEGIN { exit !(d > 2.0 && d < 25.0) }' ||
  { echo "inspector-window: expected the markers on the two blocks: $line" >&2; exit 1; }
echo "inspector-window: probed, marked and measured with the mouse: $line"
