#!/usr/bin/env bash
# @file
# @brief The probe behind docs/reliability.md ("One author's work"): runs one vdfx
# executable through every case with the real thing where this machine allows it: two real
# `vdfx edit` processes under Xvfb on one sidecar, another program rewriting the open sidecar,
# and every writer onto a real, small, full tmpfs (mounted here when run as root; else those
# cases are skipped). One line per case: exit code, what happened to the files, the message.
#
# usage: tests/fault/probe_one_author.sh VDFX        (run it on a build before and after a change)
# Needs ffmpeg, xvfb-run, gnuplot; root for the tmpfs cases.
set -uo pipefail
vdfx=$(realpath "$1")
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d /tmp/vdfx-probe_one_author.XXXXXX)
full="$work/full"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
  mountpoint -q "$full" && umount "$full"
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe

# [SECTION] inputs
ffmpeg -v error -f lavfi -i testsrc=size=256x128 -frames:v 1 -y pano.png
ffmpeg -v error -f lavfi -i testsrc=size=512x256:rate=30 -t 2 -pix_fmt yuv420p -y clip.mp4
exposure='{"type":"exposure","keyframes":[{"azimuth_deg":90,"altitude_deg":0,"frame":0,"params":{"stops":1}}]}'
printf '{"format":"vdfx.sidecar","version":1,"video":{"path":"pano.png","fps":30,"frames":1,"width":256,"height":128},"interpolation":{"exponent":1.0,"time_scale":1.0},"effects":[%s]}\n' "$exposure" > s.vdfx.json
sed 's/pano.png/clip.mp4/;s/"frames":1,"width":256,"height":128/"frames":60,"width":512,"height":256/' s.vdfx.json > c.vdfx.json
head -2 "$root/recordings/sim_look_and_place.vdrec.jsonl" > rec.vdrec.jsonl
place="$root/recordings/editor_place_exposure.vdrec.jsonl"

# case ID NOTE CMD: runs CMD, prints ID, exit code, NOTE (evaluated afterwards) and the last
# line of the output that is not progress.
case_() {
  local id=$1 note=$2 cmd=$3 rc
  timeout -s KILL 120 bash -c "$cmd" > "$work/.out" 2>&1 < /dev/null
  rc=$?
  [ "$rc" -ge 128 ] && rc="signal $((rc - 128))"
  printf '%-4s | exit %-8s | %s | %s\n' "$id" "$rc" "$(eval "$note")" \
    "$(grep -e '^vdfx [a-z]*: ' "$work/.out" | grep -v -e '^vdfx export: [0-9][0-9]*/' -e 'frames (' \
       -e '^vdfx [a-z]*: \(baked\|flare\|viewer\|wrote\)' | tail -2 | tr '\n' ' ' | cut -c1-260)"
}
intact() { cmp -s "$1" "$2" && echo "intact" || echo "CHANGED"; }
# A first editor, running until killed: the sim with no input, hidden, under its own Xvfb.
first_editor() {
  xvfb-run -a "$vdfx" edit --sidecar "$1" --hidden --scale 0.05 --window 64x64 > first.log 2>&1 &
  pids+=($!)
  sleep 4
}

echo "probe_one_author of $vdfx"
# [SECTION] two editors on one sidecar
cp s.vdfx.json s.orig
first_editor s.vdfx.json
case_ 23a 'intact s.vdfx.json s.orig; ls s-copy-*.vdfx.json 2>/dev/null | head -1' \
  "xvfb-run -a $vdfx edit --sidecar s.vdfx.json --input replay:$place --hidden --scale 0.05 --window 64x64"
cp s.orig s.vdfx.json
case_ 23b 'intact s.vdfx.json s.orig' \
  "xvfb-run -a $vdfx edit --sidecar s.vdfx.json --access write --input replay:$place --hidden --frames 2"
cp s.orig s.vdfx.json
case_ 23c 'intact s.vdfx.json s.orig' \
  "$vdfx replay $place --video pano.png --sidecar-out s.vdfx.json"
case_ 23d 'echo -' \
  "$vdfx export clip.mp4 --sidecar s.vdfx.json --baked s.vdfx.json.mp4 --frames 0-1"
# Killed as a crash would end it: the editor itself (its id from its lock, or its log), not
# only the xvfb-run around it; a lock it held stays behind.
editor_pid=$(python3 -c 'import json; print(json.load(open("s.vdfx.json.lock"))["pid"])' 2>/dev/null)
[ -n "$editor_pid" ] && kill -KILL "$editor_pid" 2>/dev/null
pkill -KILL -P "${pids[0]}" 2>/dev/null; kill -KILL "${pids[@]}" 2>/dev/null; wait 2>/dev/null; pids=()
case_ 23e 'ls s.vdfx.json.lock 2>/dev/null || echo "no lock left"' \
  "xvfb-run -a $vdfx edit --sidecar s.vdfx.json --recover no --input replay:$place --hidden --frames 2 --scale 0.05 --window 64x64"
rm -f s.vdfx.json.lock*; cp s.orig s.vdfx.json

# [SECTION] a file changed under the editor
# The other program rewrites the sidecar (a different interpolation exponent) right after the
# editor's first save; the replayed session then makes more changes.
cp s.orig t.vdfx.json
( for _ in $(seq 600); do cmp -s t.vdfx.json s.orig || break; sleep 0.02; done
  sed 's/"exponent":1.0/"exponent":1.5/' s.orig > t.other; mv t.other t.vdfx.json ) &
exponent() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["interpolation"]["exponent"])' "$1"; }
case_ 23f 'echo "t.vdfx.json exponent $(exponent t.vdfx.json) (theirs 1.5)"; ls t-yours-*.vdfx.json 2>/dev/null | head -1' \
  "xvfb-run -a $vdfx edit --sidecar t.vdfx.json --input replay:$place --hidden --scale 0.05 --window 64x64"
wait

# [SECTION] writers onto a full disk (a real 512 KiB tmpfs, filled)
mkdir -p "$full"
if mount -t tmpfs -o size=512k tmpfs "$full" 2>/dev/null; then
  # fill N: the disk full up to N KiB left (a filler file written until ENOSPC, then cut).
  fill() {
    rm -f "$full/filler"
    dd if=/dev/zero of="$full/filler" bs=4k 2>/dev/null
    [ "$1" -gt 0 ] && truncate -s "-$1K" "$full/filler"
    true
  }
  clear_full() { rm -rf "${full:?}"/*; }
  fill 64   # 64 KiB left: the header fits, the frames do not
  case_ 23g 'ls -A "$full" | grep -v filler | tr "\n" " "; echo' \
    "$vdfx export clip.mp4 --sidecar c.vdfx.json --baked $full/out.mp4 --crf 0"
  clear_full; fill 0
  case_ 23h 'ls -A "$full" | grep -v filler | tr "\n" " "; echo' \
    "$vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 256x128 --out $full/o.png"
  case_ 23i 'ls -A "$full" | grep -v filler | tr "\n" " "; echo' \
    "$vdfx replay $place --video pano.png --sidecar-out o.vdfx.json --frames $full/frames"
  clear_full; fill 0
  case_ 23j 'ls -A "$full" | grep -v filler | tr "\n" " "; echo' \
    "$vdfx bench --quick --filter '^rbf\\.solve/N=10\$' --json $full/r.json"
  case_ 23k 'ls -A "$full" | grep -v filler | tr "\n" " "; echo' \
    "TMPDIR=$full $vdfx bench --quick --filter '^rbf\\.solve/N=10\$' --plot plots"
  clear_full; fill 2
  case_ 23l 'wc -l < "$full/r.vdrec.jsonl" | sed "s/^/lines kept: /"' \
    "xvfb-run -a $vdfx play pano.png --sidecar s.vdfx.json --input replay:$root/recordings/sim_look_and_place.vdrec.jsonl --record $full/r.vdrec.jsonl --hidden --scale 0.05 --window 64x64"
  clear_full; sed "s|\"pano.png\"|\"$work/pano.png\"|" s.orig > "$full/e.vdfx.json"; cp "$full/e.vdfx.json" e.orig; fill 0
  case_ 23m 'intact "$full/e.vdfx.json" e.orig' \
    "xvfb-run -a $vdfx edit --sidecar $full/e.vdfx.json --input replay:$place --hidden --scale 0.05 --window 64x64"
  umount "$full"
else
  echo "(the full-disk cases need root to mount a tmpfs: skipped)"
fi
