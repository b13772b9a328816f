#!/usr/bin/env bash
# The editor driven by real X input (xdotool, XTEST): a test card walks to the right across a
# panorama; the author, looking at it, presses "Track subject", picks Saturation, anchors it to
# the track, drops a saturated keyframe on the card and a grey one 60 degrees away, then plays.
# Checked afterwards on what the editor saved: the track follows the card, the effect is
# anchored to it, and `vdfx eval` finds the saturated value on the card wherever it has walked
# (not where it started); then renames the track "card" on the on-screen keyboard, and the effect's
# anchor follows. Screenshots before and after playing and of the keyboard are left in the output
# folder.
# Button places are those of the desktop layout in a 1280 x 720 window
# (tests/app/golden/edit_desktop_view.png shows them).
# usage: editor_x_input_track.sh VDFX OUT_DIR   (needs $DISPLAY; ctest runs it under Xvfb)
set -euo pipefail
vdfx=$(realpath "$1")
out=$2
fail() {
  echo "FAIL: $*" >&2
  [ -f "$out/edit.log" ] && sed 's/^/  edit: /' "$out/edit.log" >&2
  exit 1
}
command -v xdotool > /dev/null || fail "xdotool not found: install Debian's xdotool (.ci/deps.sh)"
[ -n "${DISPLAY:-}" ] || fail "no DISPLAY: run it under Xvfb (.ci/with_display.sh)"
rm -rf "$out" && mkdir -p "$out" && cd "$out"

# The clip: Blender's interior panorama at 1024 x 512, a 48 x 64 card whose centre is at
# azimuth 0, altitude 0 at frame 0 and moves 4 pixels (1.40625 degrees) right a frame.
ffmpeg -v error -y -apply_trc iec61966_2_1 \
  -i /usr/share/blender/datafiles/studiolights/world/interior.exr -vf scale=1024:512 bg.png
ffmpeg -v error -y -f lavfi -i "testsrc2=size=48x64:rate=30" -frames:v 1 card.png
ffmpeg -v error -y -loop 1 -framerate 30 -i bg.png -loop 1 -framerate 30 -i card.png \
  -filter_complex "[0:v]format=rgb24[b];[b][1:v]overlay=x='488+4*n':y=224,format=yuv420p" \
  -frames:v 60 -c:v libx264 -crf 18 -g 30 walk.mp4

"$vdfx" edit walk.mp4 --window 1280x720 --no-vsync > edit.log 2>&1 &
pid=$!
trap 'kill -9 $pid 2> /dev/null || true' EXIT
win=$(timeout 60 xdotool search --sync --onlyvisible --name '^vdfx$' | head -1) ||
  fail "the editor's window did not open"
shot() { ffmpeg -v error -y -f x11grab -video_size 1280x720 -i "$DISPLAY+0,0" -frames:v 1 "$1"; }
click() {  # window x, y
  xdotool mousemove --window "$win" "$1" "$2" && sleep 0.3 && xdotool click 1 && sleep 0.5
}
# Waits (at most $2 s) until the sidecar holds the Python expression $1 over `s`.
wait_for() {
  for _ in $(seq 1 $(($2 * 4))); do
    python3 - "$1" <<'PY' 2> /dev/null && return 0
import json, sys
s = json.load(open("walk.vdfx.json"))
sys.exit(0 if eval(sys.argv[1]) else 1)
PY
    sleep 0.25
  done
  fail "the sidecar never had: $1"
}
xdotool windowmove "$win" 0 0
sleep 3  # the first frames (the thumbnails, the panels)
shot before.png

click 1034 43  # Track subject: the card is under the reticle
wait_for 'any(t["name"] == "subject1" for t in s.get("tracks", []))' 120
click 213 108  # Saturation
click 1181 80  # Anchor: video -> track:subject1 (no camera tracked: no world)
wait_for 'any(e["type"] == "saturation" and e.get("anchor") == "track:subject1"
              for e in s.get("effects", []))' 30
click 292 273  # the value slider near its right end: saturated
xdotool keydown space && sleep 0.4 && xdotool keyup space && sleep 0.5
wait_for 'sum(len(e["keyframes"]) for e in s["effects"] if e["type"] == "saturation") == 1' 30
# Look about 60 degrees to the left: two right-button drags of 280 pixels to the right (the
# drag follows the cursor: 0.107 degrees a pixel at the centre of a 1280-pixel, 100-degree view).
for _ in 1 2; do
  xdotool mousemove --window "$win" 500 300 mousedown 3
  for x in $(seq 528 28 780); do xdotool mousemove --window "$win" "$x" 300 && sleep 0.05; done
  xdotool mouseup 3 && sleep 0.5
done
click 50 273  # the slider's left end: grey
xdotool keydown space && sleep 0.4 && xdotool keyup space && sleep 0.5
wait_for 'sum(len(e["keyframes"]) for e in s["effects"] if e["type"] == "saturation") == 2' 30
click 383 515  # play
sleep 3
shot playing.png
# Rename the track on the on-screen keyboard (over the view, above the timeline): its name
# rubbed out with Back, "card" typed, Rename; the effect's anchor follows.
click 1034 117  # Rename subject1
for _ in $(seq 8); do click 877 393; done  # Back
for key in "587 439" "376 393" "534 347" "481 393"; do click $key; done  # c a r d
shot rename.png
click 877 260  # Rename
wait_for '[t["name"] for t in s["tracks"]] == ["card"] and any(e.get("anchor") == "track:card"
              for e in s["effects"])' 30
kill -INT $pid
wait $pid || true
trap - EXIT
grep -q "stopped by SIGINT: saved walk.vdfx.json" edit.log || fail "no clean stop"

python3 - "$vdfx" <<'PY'
import json, math, subprocess, sys
vdfx = sys.argv[1]
s = json.load(open("walk.vdfx.json"))
track = next(t for t in s["tracks"] if t["name"] == "card")
sat = next(e for e in s["effects"] if e["type"] == "saturation")
keys = sorted(sat["keyframes"], key=lambda k: -k["params"]["amount"])
def truth(f):
    return 1.40625 * f
def fail(msg):
    sys.exit("FAIL: " + msg)
on, off = keys[0], keys[1]
if abs(on["azimuth_deg"]) > 3 or abs(on["altitude_deg"]) > 3:
    fail(f"the saturated keyframe is not on the card at frame 0: {on}")
if not -66 < off["azimuth_deg"] < -54:
    fail(f"two drags of 280 pixels did not turn the view about 60 degrees: {off}")
if on["params"]["amount"] - off["params"]["amount"] < 1.0:
    fail(f"the two keyframes' values are not far apart: {keys}")
points = {p["frame"]: p for p in track["points"]}
for f in (0, 20, 40):
    p = points[f]
    if abs(p["azimuth_deg"] - truth(f)) > 2.0 or abs(p["altitude_deg"]) > 2.0:
        fail(f"the track at frame {f} is at {p}, the card at {truth(f)}, 0")
def amount(az, alt, f):
    out = subprocess.run([vdfx, "eval", "walk.vdfx.json", "--at", f"{az},{alt},{f}"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["effects"]["saturation"]["amount"]
at_card = [amount(truth(f), 0, f) for f in (0, 20, 40)]
where_it_was = amount(0, 0, 40)
print("saturation on the card at frames 0, 20, 40:", at_card, "; at its start at 40:", where_it_was)
for v in at_card:
    if abs(v - on["params"]["amount"]) > 0.05:
        fail(f"the effect did not follow the card: {at_card} against {on['params']['amount']}")
if on["params"]["amount"] - where_it_was < 0.3:
    fail(f"the effect stayed where the card started: {where_it_was}")
print("ok")
PY
