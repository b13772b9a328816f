#!/usr/bin/env bash
# The README's main job: installs what is missing, builds, and runs vdfx on the bundled demo
# (a CC0 sunrise panorama from Debian's blender-data with the demo sidecar app/demo/sunrise.vdfx.json).
# It renders the view towards the sun and the view away from it, so the view-dependent exposure,
# saturation and vignette are visible side by side, and prints the interpolated parameters.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/.ci/deps.sh"
"$root/.ci/build.sh"
build=${VDFX_BUILD_DIR:-$root/build}
out=${VDFX_OUT:-$root/out}
mkdir -p "$out"
vdfx="$build/vdfx"
demo="$root/app/demo/sunrise.vdfx.json"
pano=/usr/share/blender/datafiles/studiolights/world/sunrise.exr

"$vdfx" validate "$demo"
"$vdfx" eval "$demo" --at 36,8,0 --at -144,0,0
for view in "sun 36,8" "away -144,0" "ground 0,-60"; do
  set -- $view
  "$vdfx" render "$pano" --sidecar "$demo" --view "$2" --frame 0 --fov 100 --size 1280x720 \
    --out "$out/demo-$1.png"
  "$vdfx" render "$pano" --sidecar "$demo" --view "$2" --frame 0 --fov 100 --size 1280x720 \
    --mode pixel --out "$out/demo-$1-pixel.png"
done
echo "vdfx: demo views written to $out (demo-*.png: view-dependent; demo-*-pixel.png: per-pixel baseline)"
