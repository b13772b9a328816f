#!/usr/bin/env bash
# Makes docs/figures/anchor_track_strip.jpg (the README's "Effects that follow the camera and subjects"):
# a test card walks across Blender's interior panorama (60 frames, x264); `vdfx track subject`
# follows it; one saturation effect (colour at the card, grey around it) is baked once anchored to
# the video and once to the track; frames 0, 25 and 50 of each, cropped to the band it walks in.
# usage: docs/figures/anchor_track_strip.sh VDFX [WORK]
set -euo pipefail
vdfx=$(realpath "$1")
work=${2:-$(mktemp -d)}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work" && cd "$work"
ffmpeg -v error -y -apply_trc iec61966_2_1 \
  -i /usr/share/blender/datafiles/studiolights/world/interior.exr -vf scale=1024:512 bg.png
ffmpeg -v error -y -f lavfi -i "testsrc2=size=72x96:rate=30" -frames:v 1 card.png
ffmpeg -v error -y -loop 1 -framerate 30 -i bg.png -loop 1 -framerate 30 -i card.png \
  -filter_complex "[0:v]format=rgb24[b];[b][1:v]overlay=x='200+8*n':y=250,format=yuv420p" \
  -frames:v 60 -c:v libx264 -crf 18 -g 30 walk.mp4
rm -f walk.vdfx.json
# The card's centre at frame 0: x = 236, y = 298 of 1024x512.
"$vdfx" track subject walk.mp4 --name actor --at -97,-15,0 --size 12 --sidecar-out walk.vdfx.json
python3 - <<'PY'
import json
s = json.load(open("walk.vdfx.json"))
def key(az, alt, amount):
    return {"azimuth_deg": az, "altitude_deg": alt, "frame": 0, "params": {"amount": amount}}
keys = [key(-97, -15, 1.6), key(-47, -15, 0.0), key(-147, -15, 0.0), key(-97, 35, 0.0),
        key(-97, -65, 0.0), key(83, 0, 0.0)]
for name, anchor in [("video", "video"), ("track", "track:actor")]:
    s["effects"] = [{"type": "saturation", "anchor": anchor, "keyframes": keys}]
    json.dump(s, open(f"walk_{name}.vdfx.json", "w"), indent=1)
PY
for n in video track; do
  rm -f "baked_$n.mp4"
  "$vdfx" export walk.mp4 --sidecar "walk_$n.vdfx.json" --baked "baked_$n.mp4"
  for f in 0 25 50; do
    ffmpeg -v error -y -i "baked_$n.mp4" -vf "select=eq(n\,$f),crop=1024:240:0:170,scale=640:150" \
      -frames:v 1 "${n}_$f.png"
  done
done
ffmpeg -v error -y -i video_0.png -i video_25.png -i video_50.png -i track_0.png -i track_25.png \
  -i track_50.png -filter_complex \
  "[0][1][2]vstack=3[a];[3][4][5]vstack=3[b];[a]pad=iw+8:ih:0:0:white[a2];[a2][b]hstack" \
  -q:v 3 "$here/anchor_track_strip.jpg"
echo "wrote $here/anchor_track_strip.jpg"
