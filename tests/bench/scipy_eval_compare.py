#!/usr/bin/python3
"""The whole `vdfx eval` process against SciPy's RBFInterpolator on the same keyframes and views,
by hand (docs/interpolation.md, "Measured"); needs Debian's python3-scipy:

    /usr/bin/python3 tests/bench/scipy_eval_compare.py build/vdfx OUT_DIR [N] [VIEWS] [RUNS]

One exposure effect with N keyframes (default 1000) at random directions and frames over 20
minutes at 30 fps, the contract's default settings (exponent 1, time_scale 1), VIEWS random views
(default 2000). Timed in turns, RUNS times (default 7): the vdfx eval process from start to
exit (reading and checking the sidecar, the solve, every view, the JSON printed) and SciPy's
RBFInterpolator built on the same points (x, y, z of the unit direction and the frame times
24 / fps * time_scale: the contract's chordal distance) with the linear kernel and a degree-1
polynomial, then evaluated at the same views (inside Python: its start and imports not
counted). Prints both medians, their ratio and the largest difference between the two results,
and beside each median wall time the median CPU time (every thread of the process: vdfx eval's
two threads, SciPy's BLAS threads) with the load average before and after: on a shared machine
the wall times include waits for a core.
"""
import json
import math
import os
import random
import resource
import statistics
import subprocess
import sys
import time

import numpy as np
from scipy.interpolate import RBFInterpolator

vdfx, out_dir = sys.argv[1], sys.argv[2]
n = int(sys.argv[3]) if len(sys.argv) > 3 else 1000
view_count = int(sys.argv[4]) if len(sys.argv) > 4 else 2000
runs = int(sys.argv[5]) if len(sys.argv) > 5 else 7
fps, frames = 30.0, 36000
os.makedirs(out_dir, exist_ok=True)
rng = random.Random(7)


def direction():
    return rng.uniform(-180.0, 180.0), math.degrees(math.asin(rng.uniform(-1.0, 1.0)))


def unit(az, alt):
    a, b = math.radians(az), math.radians(alt)
    return (math.cos(b) * math.sin(a), math.sin(b), -math.cos(b) * math.cos(a))


keyframes = []
for _ in range(n):
    az, alt = direction()
    keyframes.append({"azimuth_deg": az, "altitude_deg": alt,
                      "frame": rng.randrange(frames), "params": {"stops": rng.uniform(-2, 2)}})
sidecar = {"format": "vdfx.sidecar", "version": 1,
           "video": {"path": "clip.mp4", "fps": fps, "frames": frames, "width": 3840,
                     "height": 1920},
           "interpolation": {"exponent": 1.0, "time_scale": 1.0},
           "effects": [{"type": "exposure", "keyframes": keyframes}]}
path = os.path.join(out_dir, "scipy_compare.vdfx.json")
with open(path, "w") as f:
    json.dump(sidecar, f)
lo = min(k["frame"] for k in keyframes)
hi = max(k["frame"] for k in keyframes)
views = [(*direction(), rng.randrange(lo, hi + 1)) for _ in range(view_count)]
args = [vdfx, "eval", path]
for az, alt, fr in views:
    args += ["--at", f"{az!r},{alt!r},{fr}"]

step = 24.0 / fps  # time_scale 1
points = np.array([(*unit(k["azimuth_deg"], k["altitude_deg"]), k["frame"] * step)
                   for k in keyframes])
values = np.array([k["params"]["stops"] for k in keyframes])
targets = np.array([(*unit(az, alt), fr * step) for az, alt, fr in views])


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_vdfx():
    c0, t0 = children_cpu(), time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return time.perf_counter() - t0, children_cpu() - c0, out


def run_scipy():
    c0, t0 = time.process_time(), time.perf_counter()
    got = RBFInterpolator(points, values, kernel="linear", degree=1)(targets)
    return time.perf_counter() - t0, time.process_time() - c0, got


load_before = os.getloadavg()[0]
native, scipy, native_cpu, scipy_cpu = [], [], [], []
for _ in range(runs):
    t, c, out = run_vdfx()
    native.append(t)
    native_cpu.append(c)
    t, c, got = run_scipy()
    scipy.append(t)
    scipy_cpu.append(c)
mine = np.array([json.loads(line)["effects"]["exposure"]["stops"] for line in out.splitlines()])
a, b = statistics.median(native), statistics.median(scipy)
ac, bc = statistics.median(native_cpu), statistics.median(scipy_cpu)
print(f"N={n} views={view_count} runs={runs} load={load_before:.2f} .. {os.getloadavg()[0]:.2f}")
print(f"vdfx eval process: {a * 1e3:.1f} ms wall, {ac * 1e3:.1f} ms CPU (medians)")
print(f"SciPy RBFInterpolator build + evaluate: {b * 1e3:.1f} ms wall, {bc * 1e3:.1f} ms CPU "
      "(medians)")
print(f"ratio vdfx / SciPy: {a / b:.3f} wall, {ac / bc:.3f} CPU")
print(f"largest difference: {np.max(np.abs(mine - got)):.3g} stops")
