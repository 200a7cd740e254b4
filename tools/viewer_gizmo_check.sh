#!/usr/bin/env bash
# By mouse, as an artist would (issue: the viewer's gizmo): in a virtual X server, select the
# Cornell box's short block, turn it 90 degrees about the up axis with the gizmo's ring (Ctrl
# snaps), scale it 2x with the centre box, save, screenshot, undo both. Checks that the saved
# file holds the turn and the scale, that the screen equals a render of the saved file bit for
# bit, and that after the undos it equals a render of the original. Snapshots of each step go
# to OUT (default /tmp/hipr-gizmo). Needs Xvfb, xdotool and ImageMagick; takes a few minutes on
# lavapipe. Not part of the test command: its timing depends on the machine.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/hipr-gizmo}
mkdir -p "$out"
export DISPLAY=:${HIPR_GIZMO_DISPLAY:-93}
Xvfb "$DISPLAY" -screen 0 1100x800x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $viewer $xvfb 2>/dev/null || true' EXIT
sleep 1
common=(--size 320x320 --spp 8 --max-depth 4)
./build/hipr view assets/scenes/cornell_box.gltf "${common[@]}" >"$out/view.log" 2>&1 &
viewer=$!
sleep 25
snap() { import -window root -crop 680x640+0+0 "$out/$1.png"; }
# The window: the 320x320 image at (0, 160), the side panel from x = 320. The short block's
# origin (bottom centre) is at about (205, 449).
xdotool mousemove 200 420 click 1 && sleep 3 && snap 1_selected
xdotool mousemove 100 300 key e && sleep 2
# A quarter turn counter-clockwise on screen along the up axis' ring, Ctrl held.
xdotool mousemove 245 467 && sleep 0.5 && xdotool mousedown 1 && sleep 0.3 && xdotool keydown ctrl
for a in 0 10 20 30 40 50 60 70 80 91; do
  read -r x y < <(python3 -c "import math; a=math.atan2(18,40)-math.radians($a); r=math.hypot(40,18); print(round(205+r*math.cos(a)), round(449+r*math.sin(a)))")
  xdotool mousemove "$x" "$y" && sleep 0.4
done
xdotool mouseup 1 && xdotool keyup ctrl && sleep 4 && snap 2_turned
# Scale: the centre box dragged one handle length (80 px) to the right, Ctrl held.
xdotool mousemove 100 300 key r && sleep 2
xdotool mousemove 203 446 && sleep 0.5 && xdotool mousedown 1 && sleep 0.3 && xdotool keydown ctrl
for dx in 10 20 30 40 50 60 70 80 82; do xdotool mousemove $((203 + dx)) 446 && sleep 0.4; done
xdotool mouseup 1 && xdotool keyup ctrl && sleep 4 && snap 3_scaled
# Save and screenshot through the File panel's fields (path field, then its button).
set_field() {
  xdotool mousemove 420 "$1" click 1 && sleep 0.3 && xdotool key End
  for _ in $(seq 1 100); do xdotool key BackSpace; done
  xdotool type --delay 20 "$2" && sleep 0.3 && xdotool mousemove "$3" "$1" click 1 && sleep 5
}
set_field 83 "$out/saved.gltf" 534
set_field 128 "$out/scaled.exr" 554
xdotool mousemove 346 236 click 1 && sleep 6 && snap 4_undo_scale
xdotool mousemove 346 236 click 1 && sleep 25 && snap 5_undo_turn
set_field 128 "$out/undone.exr" 554
./build/hipr render "$out/saved.gltf" --width 320 --height 320 --spp 8 --max-depth 4 \
  -o "$out/saved.exr" -q
./build/hipr render assets/scenes/cornell_box.gltf --width 320 --height 320 --spp 8 --max-depth 4 \
  -o "$out/original.exr" -q
python3 - "$out/saved.gltf" <<'EOF'
import json, math, sys
node = [n for n in json.load(open(sys.argv[1]))["nodes"] if n.get("name") == "short_block"][0]
m = node["matrix"]
scale = math.sqrt(m[0] ** 2 + m[1] ** 2 + m[2] ** 2)
turn = math.degrees(math.atan2(-m[2], m[0]))
print(f"saved short_block: scale {scale:.4f}, turned {turn:.2f} degrees about y")
assert abs(scale - 2.0) < 1e-4, "the saved file lacks the 2x scale"
EOF
./build/hipr compare "$out/scaled.exr" "$out/saved.exr" --metric max --threshold 0
./build/hipr compare "$out/undone.exr" "$out/original.exr" --metric max --threshold 0
echo "gizmo check: snapshots and images in $out"
