#!/usr/bin/env bash
# @file
# @brief The bad-input and fault probe behind docs/reliability.md: runs one vdfx executable
# against every class of bad input and prints one line per case (exit code or signal, wall time,
# peak memory, what happened to the files involved, the start of the message).
#
# usage: tests/fault/probe.sh VDFX [FAULT_SO]
#   VDFX      the executable to probe (run it on a build before and after a change)
#   FAULT_SO  tests/fault/fault_inject.c built as a shared object (LD_PRELOAD), for the
#             fsync/rename/kill/ENOSPC cases; those are skipped without it
# Needs ffmpeg (test inputs) and xvfb-run (GPU cases). Each case runs under a time limit
# ($PROBE_TIMEOUT, default 30 s: a case that reaches it is reported as a hang) and a 4 GiB
# address-space cap, so a runaway allocation fails instead of taking the machine.
set -uo pipefail
vdfx=$(realpath "$1")
fault_so=${2:+$(realpath "$2")}
limit=${PROBE_TIMEOUT:-30}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d /tmp/vdfx-probe.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work"
export LIBGL_ALWAYS_SOFTWARE=1

# [SECTION] inputs
ffmpeg -v error -f lavfi -i testsrc=size=256x128 -frames:v 1 -y pano.png
ffmpeg -v error -f lavfi -i testsrc=size=256x128:rate=30 -t 1 -pix_fmt yuv420p -y clip.mp4
ffmpeg -v error -f lavfi -i color=c=red:size=100000x2 -frames:v 1 -y wide.png
sidecar() {  # sidecar FPS FRAMES EFFECTS_JSON
  printf '{"format":"vdfx.sidecar","version":1,"video":{"path":"pano.png","fps":%s,"frames":%s,"width":256,"height":128},"interpolation":{"exponent":1.0,"time_scale":1.0},"effects":[%s]}\n' "$1" "$2" "$3"
}
exposure='{"type":"exposure","keyframes":[{"azimuth_deg":90,"altitude_deg":0,"frame":0,"params":{"stops":1}},{"azimuth_deg":-90,"altitude_deg":0,"frame":1,"params":{"stops":-1}}]}'
sidecar 30 2 "$exposure" > s.vdfx.json
keys() {  # keys N: an exposure effect with N keyframes on a spiral
  awk -v n="$1" 'BEGIN{printf "{\"type\":\"exposure\",\"keyframes\":["; for(i=0;i<n;i++){a=(i*137.50776)%359-179; z=2*(i+0.5)/n-1; h=atan2(z,sqrt(1-z*z))*57.29578; printf "%s{\"azimuth_deg\":%.6f,\"altitude_deg\":%.6f,\"frame\":0,\"params\":{\"stops\":%.3f}}", (i?",":""), a, h, (i%17)/4-2}; printf "]}"}'
}
head -2 "$root/recordings/sim_look_and_place.vdrec.jsonl" > rec.vdrec.jsonl
cp "$root/xr/headset/profiles/generic90.json" hmd.json
render="render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32"

# [SECTION] one case
# case ID NOTE CMD...: runs CMD (a shell string), prints ID, exit/signal, seconds, MiB, NOTE
# (evaluated after the run, so it can inspect files), and the first line of the output.
case_() {
  local id=$1 note=$2 cmd=$3
  local start end rc mem first lines bytes
  start=$(date +%s.%N)
  (ulimit -v 4194304; timeout -s KILL "$limit" /usr/bin/time -f '%M' -o "$work/.mem" bash -c "$cmd" \
     > "$work/.out" 2>&1 < /dev/null)
  rc=$?
  end=$(date +%s.%N)
  mem=$(tail -1 "$work/.mem" 2>/dev/null | grep -E '^[0-9]+$' || echo 0)
  [ "$rc" -ge 128 ] && rc="signal $((rc - 128))"
  [ "$rc" = "signal 9" ] && [ "$(echo "$end - $start >= $limit - 1" | bc)" = 1 ] && rc="timeout (hang)"
  # the exit status line /usr/bin/time adds for a failed command is not vdfx's output
  grep -v '^Command exited with non-zero status' "$work/.out" > "$work/.msg"
  bytes=$(wc -c < "$work/.msg")
  lines=$(wc -l < "$work/.msg")
  first=$(head -c 400 "$work/.msg" | head -1 | cut -c1-140)
  printf '%-5s | %-16s | %6.1f s | %5d MiB | %s | %s lines %s bytes | %s\n' "$id" "$rc" \
    "$(echo "$end - $start" | bc)" "$((mem / 1024))" "$(eval "$note")" "$lines" "$bytes" "$first"
}
intact() { cmp -s "$1" "$2" && echo "intact" || echo "CHANGED"; }

echo "probe of $vdfx"
# [SECTION] 1 data loss through output paths
cp s.vdfx.json s.orig; cp pano.png pano.orig; cp rec.vdrec.jsonl rec.orig; cp clip.mp4 clip.orig
case_ 1a 'intact s.vdfx.json s.orig' "$vdfx $render --out s.vdfx.json"
cp s.orig s.vdfx.json
case_ 1b 'intact pano.png pano.orig' "$vdfx $render --out pano.png"
cp pano.orig pano.png
case_ 1c 'intact rec.vdrec.jsonl rec.orig' "$vdfx replay rec.vdrec.jsonl --video pano.png --sidecar-out rec.vdrec.jsonl"
cp rec.orig rec.vdrec.jsonl
case_ 1d 'intact clip.mp4 clip.orig' "$vdfx replay rec.vdrec.jsonl --video clip.mp4 --sidecar-out clip.mp4"
cp clip.orig clip.mp4
echo old > target.png; ln -sf target.png link.png
case_ 1e '[ -L link.png ] && echo "link kept, target $(head -c4 target.png | od -An -c | tr -d " ")" || echo "link REPLACED by a file"' "$vdfx $render --out link.png"
mknod nulldev c 1 3 2>/dev/null || true
case_ 1f '[ -c nulldev ] && echo "device kept" || echo "device REPLACED by a file"' "$vdfx $render --out nulldev"
mkfifo fifo.png
case_ 1g '[ -p fifo.png ] && echo "fifo kept" || echo "fifo REPLACED by a file"' "$vdfx $render --out fifo.png"
rm -f fifo.png
mkdir -p frames; ln -sf ../s.vdfx.json frames/replay_000.png
case_ 1h 'intact s.vdfx.json s.orig' "$vdfx replay rec.vdrec.jsonl --video pano.png --sidecar-out out.vdfx.json --frames frames"
cp s.orig s.vdfx.json; rm -rf frames
case_ 1i 'intact s.vdfx.json s.orig' "xvfb-run -a $vdfx play pano.png --sidecar s.vdfx.json --input replay:rec.vdrec.jsonl --record s.vdfx.json --hidden --frames 2"
cp s.orig s.vdfx.json

# [SECTION] 2 hangs and unbounded reads
mkfifo fifo.json fifo.vdrec.jsonl fifo.png
case_ 2a 'echo -' "$vdfx validate /dev/zero"
case_ 2b 'echo -' "$vdfx validate fifo.json"
case_ 2c 'echo -' "$vdfx render fifo.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32 --out o.png"
case_ 2d 'echo -' "$vdfx render pano.png --sidecar fifo.json --view 0,0 --fov 90 --size 64x32 --out o.png"
case_ 2e 'echo -' "$vdfx replay fifo.vdrec.jsonl --video pano.png --sidecar-out o.vdfx.json"
case_ 2f 'echo -' "$vdfx hmd show fifo.json"
truncate -s 8G huge.vdfx.json
case_ 2g 'echo -' "$vdfx validate huge.vdfx.json"
{ head -1 rec.vdrec.jsonl; } > huge.vdrec.jsonl; truncate -s 8G huge.vdrec.jsonl
case_ 2h 'echo -' "$vdfx replay huge.vdrec.jsonl --video pano.png --sidecar-out o.vdfx.json"
cp hmd.json huge-hmd.json; truncate -s 8G huge-hmd.json
case_ 2i 'echo -' "$vdfx hmd show huge-hmd.json"
rm -f huge.vdfx.json huge.vdrec.jsonl huge-hmd.json fifo.json fifo.vdrec.jsonl fifo.png

# [SECTION] 3 unbounded sizes from the command line
case_ 3a 'echo -' "xvfb-run -a $vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32 --gpu --mode pixel --bake 16384x16384 --out o.png"
case_ 3b 'echo -' "$vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 16384x16384 --out o.png"
case_ 3c 'echo -' "xvfb-run -a $vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 16384x16384 --gpu --out o.png"
case_ 3d 'echo -' "xvfb-run -a $vdfx render wide.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32 --gpu --out o.png"
case_ 3e 'echo -' "$vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 100000x1 --out o.png"

# [SECTION] 4 files that validate but produce NaN
sidecar 1e-200 2 "$exposure" > nan.vdfx.json
case_ 4a 'echo -' "$vdfx validate nan.vdfx.json"
case_ 4b 'echo -' "$vdfx eval nan.vdfx.json --at 0,0,1"
case_ 4c '[ -f o.png ] && echo "image written" || echo "no image"' "rm -f o.png; $vdfx render clip.mp4 --sidecar nan.vdfx.json --view 0,0 --frame 1 --fov 90 --size 64x32 --out o.png"
sidecar 30 9223372036854775807 "${exposure/\"frame\":1/\"frame\":9223372036854775806}" > big.vdfx.json
case_ 4d 'echo -' "$vdfx eval big.vdfx.json --at 0,0,5"

# [SECTION] 5 scale limits
sidecar 30 1 "$(keys 100000)" > k100k.vdfx.json
case_ 5a 'echo -' "$vdfx validate k100k.vdfx.json"
case_ 5b 'echo -' "$vdfx eval k100k.vdfx.json --at 0,0,0"
sidecar 30 1 "$(keys 5000)" > k5k.vdfx.json
case_ 5c 'echo -' "$vdfx eval k5k.vdfx.json --at 0,0,0"

# [SECTION] 6 input errors reported as internal
mkdir -p adir.vdrec.jsonl adir.json
case_ 6a 'echo -' "$vdfx replay adir.vdrec.jsonl --video pano.png --sidecar-out o.vdfx.json"
case_ 6b 'echo -' "$vdfx hmd show adir.json"
sed 's/"refresh_hz": *[0-9.]*/"refresh_hz": 1e400/' hmd.json > big-number-hmd.json
case_ 6c 'echo -' "$vdfx hmd show big-number-hmd.json"
case_ 6d 'echo -' "$vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov nan --size 64x32 --out o.png"
case_ 6e 'echo -' "xvfb-run -a $vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov nan --size 64x32 --gpu --out o.png"
echo x > afile
case_ 6f 'echo -' "$vdfx replay rec.vdrec.jsonl --video pano.png --sidecar-out o.vdfx.json --frames afile/sub"
case_ 6g 'echo -' "xvfb-run -a $vdfx play pano.png --sidecar s.vdfx.json --input replay:rec.vdrec.jsonl --record /dev/full --hidden --frames 2"
case_ 6h 'echo -' "$vdfx render pano.png --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32 --out afile/o.png"

# [SECTION] 7 wrong values
{ head -1 rec.vdrec.jsonl; echo '{"t_ns":9223372036854775808,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}}'; } > wrap.vdrec.jsonl
case_ 7a 'echo -' "$vdfx replay wrap.vdrec.jsonl --video pano.png --sidecar-out o.vdfx.json"
case_ 7b 'echo -' "$vdfx $render --frame 9223372036854775808 --out o.png"
case_ 7c 'echo -' "$vdfx $render --frame -1 --out o.png"
case_ 7d 'echo -' "$vdfx eval s.vdfx.json --at 0,0,9007199254740993"

# [SECTION] 8 messages
sidecar "1$(head -c 10000000 /dev/zero | tr '\0' 0)" 2 "$exposure" > long.vdfx.json
case_ 8a 'echo -' "$vdfx validate long.vdfx.json"
{ sidecar 30 2 "$exposure" | tr -d '\n'; printf '\0garbage'; } > nul.vdfx.json
case_ 8b 'echo -' "$vdfx validate nul.vdfx.json"
{ printf '{"format":"vdfx.sidecar",\0'; } > nul2.vdfx.json
case_ 8c 'echo -' "$vdfx validate nul2.vdfx.json"
head -c 4096 /dev/urandom > broken.mp4
case_ 8d 'echo -' "$vdfx render broken.mp4 --sidecar s.vdfx.json --view 0,0 --fov 90 --size 64x32 --out o.png"
sed 's/"name":/"ipd_m": 0.05, "name":/' hmd.json > dup-hmd.json
case_ 8e 'echo -' "$vdfx hmd show dup-hmd.json"
case_ 8f 'echo -' "$vdfx $render --eye right --out o.png"
cp s.vdfx.json r.vdfx.json; echo '{broken' > r.vdfx.json.autosave
case_ 8g 'echo -' "$vdfx edit pano.png --sidecar r.vdfx.json --recover yes --hidden --frames 1"
if [ -n "$fault_so" ]; then
  cp s.orig out.vdfx.json
  case_ 8h 'echo "$(intact out.vdfx.json s.orig) (render wrote it: CHANGED expected)"' "LD_PRELOAD=$fault_so VDFX_FAULT=fsync_dir $vdfx $render --out out.vdfx.json"
  mkdir -p kill; cp s.orig kill/s.vdfx.json
  case_ 8i 'echo "temp files left: $(ls -A kill | grep -c tmp)"' "LD_PRELOAD=$fault_so VDFX_FAULT=rename_kill $vdfx $render --out kill/o.png"
  case_ 8j 'echo "temp files left after a clean save: $(ls -A kill | grep -c tmp)"' "$vdfx $render --out kill/o.png"
  cp s.orig full.vdfx.json
  case_ 8k 'intact full.vdfx.json s.orig' "LD_PRELOAD=$fault_so VDFX_FAULT=write_enospc $vdfx $render --out full.vdfx.json"
  case_ 8l 'echo -' "xvfb-run -a env LD_PRELOAD=$fault_so VDFX_FAULT=write_enospc VDFX_FAULT_AFTER=2000 $vdfx play pano.png --sidecar s.vdfx.json --input replay:$root/recordings/sim_look_and_place.vdrec.jsonl --record rec-out.vdrec.jsonl --hidden --frames 30"
fi
