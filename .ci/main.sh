#!/usr/bin/env bash
# The README's main job: installs what is missing, builds, and runs vdfx on the bundled demo
# (a CC0 hotel-room panorama from Debian's blender-data with the demo sidecar
# app/demo/interior.vdfx.json): exposure adapts when the viewer turns to the window, the bed is
# warmer, and looking away from the window desaturates and closes a vignette to guide the gaze.
# It renders those views in both modes and prints the interpolated parameters.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
"$root/.ci/build.sh"
build=${VDFX_BUILD_DIR:-$root/build}
out=${VDFX_OUT:-$root/out}
mkdir -p "$out"
vdfx="$build/vdfx"
demo="$root/app/demo/interior.vdfx.json"
pano=/usr/share/blender/datafiles/studiolights/world/interior.exr

"$vdfx" validate "$demo"
"$vdfx" eval "$demo" --at 31,5,0 --at -75,-10,0 --at 75,-15,0 --at -150,0,0
for view in "window 31,5" "desk -75,-10" "bed 75,-15" "behind -150,0"; do
  set -- $view
  "$vdfx" render "$pano" --sidecar "$demo" --view "$2" --frame 0 --fov 100 --size 1280x720 \
    --out "$out/demo-$1.png"
  "$vdfx" render "$pano" --sidecar "$demo" --view "$2" --frame 0 --fov 100 --size 1280x720 \
    --mode pixel --out "$out/demo-$1-pixel.png"
done
echo "vdfx: demo views written to $out (demo-*.png: view-dependent; demo-*-pixel.png: per-pixel baseline)"
# The baked export (docs/export.md): the panorama as a one-frame 360 video, effects per pixel.
"$vdfx" export "$pano" --sidecar "$demo" --baked "$out/demo-baked.mp4"

# The editor: the demo session (recordings/demo.vdrec.jsonl) replayed in the editor's window on
# the bundled demo (not saved), in the desktop view it was recorded in (1280 x 720), written as
# a screenshot (Xvfb when there is no display), then the same session replayed headless (--force:
# the sidecar is this script's own output, replaced each run): the
# sidecar it authors and a few frames.
"$root/.ci/with_display.sh" "$vdfx" edit --input replay:"$root/recordings/demo.vdrec.jsonl" --frames 433 --hidden \
  --screenshot "$out/editor.png"
"$vdfx" replay "$root/recordings/demo.vdrec.jsonl" --video "$pano" \
  --sidecar-out "$out/demo-authored.vdfx.json" --force --frames "$out/replay"
echo "vdfx: editor window $out/editor.png, authored sidecar $out/demo-authored.vdfx.json"
# With a display, finish in the real editor on the demo, in the desktop view (VDFX_NO_WINDOW=1
# skips it).
if [ -n "${DISPLAY:-}" ] && [ "${VDFX_NO_WINDOW:-0}" != 1 ]; then
  "$vdfx" edit
fi
