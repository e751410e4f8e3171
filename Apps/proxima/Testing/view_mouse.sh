#!/usr/bin/env bash
# proxima view with the mouse, driven through X as a person would (ctest proxima.view-mouse, under
# its own Xvfb): the cursor over the sphere's centre, eight wheel notches pressing the finger in
# (half a radius each: 4 mm), the picture key, then q to close. The window must report contact
# and a force when it closes, and have saved its picture.
# Usage: view_mouse.sh PROXIMA MESH
set -euo pipefail
. "$(dirname "$0")/../../../Library/VTK/Testing/xdotool-session.sh"
proxima="$1"
mesh="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$proxima" view --mesh "$mesh" --device mouse --radius 0.001 > out.txt 2> err.txt &
view=$!
# The window appears when VTK has made it.
window=$(find_window "proxima view" "$view" err.txt)
sleep 1
# The window is 800 x 600; the default camera looks down at the sphere's centre.
xdotool mousemove --window "$window" 400 300
sleep 0.5
xdotool mousemove --window "$window" 401 300
sleep 0.5
for _ in 1 2 3 4 5 6 7 8; do
  xdotool click --window "$window" 4
  sleep 0.05
done
sleep 2
xdotool key --window "$window" i
sleep 1
xdotool key --window "$window" q
wait_for_exit "$view" q
wait "$view" || { echo "view-mouse: proxima view failed:" >&2; cat err.txt >&2; exit 1; }
cat out.txt
grep -q "saved the window's picture to proxima-view-1.png" out.txt ||
  { echo "view-mouse: no picture saved" >&2; exit 1; }
[ -s proxima-view-1.png ] || { echo "view-mouse: the picture is empty" >&2; exit 1; }
# Pressed 4 mm into the sphere at 1000 N/m: about 4 N, in contact.
line=$(grep "closed at" out.txt)
contacts=$(echo "$line" | sed -E 's/.* ([0-9]+) contacts.*/\1/')
force=$(echo "$line" | sed -E 's/.*force ([0-9.]+) N.*/\1/')
if [ "$contacts" -lt 1 ] || ! awk -v f="$force" 'BEGIN { exit !(f > 3.0 && f < 5.0) }'; then
  echo "view-mouse: expected contact and about 4 N after pressing 4 mm, got: $line" >&2
  exit 1
fi
echo "view-mouse: pressed with the mouse wheel: $line"
