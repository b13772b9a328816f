// The web player's WebAssembly module against the native vdfx (CTest: publish.wasm_eval).
//   node wasm_eval_test.cjs VDFX_BINARY WASM_DIR OUTPUT_DIR
// 1. A 1000-keyframe exposure plus tint, saturation (its own interpolation override) and
//    vignette tracks, some keyframes only inside part of the clip (the hold-in-time rule) and
//    one effect on a single frame (purely spatial): at 1000 random views the module's
//    parameters match `vdfx eval`'s within 1e-9.
// 2. A broken sidecar: the module's message is what `vdfx validate` prints, line for line.
// 3. A film of 12000 keyframes (interpolated locally in time) loads from the heap and matches.
// 4. The module stays within the page's budget (1.5 MB).
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync, spawnSync } = require('child_process');

const [vdfx, wasmDir, outDir] = process.argv.slice(2);
if (!vdfx || !wasmDir || !outDir) {
  console.error('usage: node wasm_eval_test.cjs VDFX_BINARY WASM_DIR OUTPUT_DIR');
  process.exit(2);
}
fs.mkdirSync(outDir, { recursive: true });
let failures = 0;
function check(ok, what) {
  if (!ok) {
    failures++;
    console.error('FAIL: ' + what);
  }
}

// A seeded generator (mulberry32): the same sidecar and points on every run.
function rng(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const rand = rng(21);
const uniform = (lo, hi) => lo + (hi - lo) * rand();
const frames = 300;

function keyframes(n, frameLo, frameHi, params) {
  const out = [];
  for (let i = 0; i < n; i++) {
    out.push({
      azimuth_deg: uniform(-179, 180),
      altitude_deg: uniform(-85, 85),
      frame: Math.floor(uniform(frameLo, frameHi + 1)),
      params: params(),
    });
  }
  return out;
}
const sidecar = {
  format: 'vdfx.sidecar',
  version: 1,
  video: { path: 'clip.mp4', fps: 30, frames, width: 3840, height: 1920 },
  interpolation: { exponent: 1.0, time_scale: 1.0 },
  effects: [
    { type: 'tint', keyframes: keyframes(40, 100, 200, () => ({ gain: [uniform(0.5, 2), uniform(0.5, 2), uniform(0.5, 2)] })) },
    { type: 'exposure', keyframes: keyframes(1000, 0, frames - 1, () => ({ stops: uniform(-2, 2) })) },
    { type: 'saturation', interpolation: { exponent: 1.5, time_scale: 0.5 },
      keyframes: keyframes(30, 50, 250, () => ({ amount: uniform(0.2, 2) })) },
    { type: 'vignette', keyframes: keyframes(20, 120, 120, () => ({ radius_deg: uniform(20, 90), falloff_deg: uniform(5, 60) })) },
  ],
};
const good = path.join(outDir, 'wasm_eval.vdfx.json');
fs.writeFileSync(good, JSON.stringify(sidecar, null, 1));

const points = [];
for (let i = 0; i < 1000; i++)
  points.push([uniform(-179.999, 180), uniform(-90, 90), Math.floor(uniform(0, frames))]);
const args = ['eval', good];
for (const p of points) args.push('--at', p.join(','));
const native = execFileSync(vdfx, args, { encoding: 'utf8', maxBuffer: 64 << 20 })
  .trim().split('\n').map((l) => JSON.parse(l).effects);

const create = require(path.resolve(wasmDir, 'vdfx_player.js'));
const wasmFile = path.join(wasmDir, 'vdfx_player.wasm');
// wasmBinary: emscripten 3.1.6 would fetch() the file, which node cannot for a path.
create({ wasmBinary: fs.readFileSync(wasmFile) }).then((m) => {
  const loadText = m.cwrap('vdfx_load', 'number', ['string', 'number']);
  // As the page does (app/publish/page/player.js): the text on the heap, not the stack.
  const load = (name, text) => {
    const p = m.allocateUTF8(text);
    try {
      return loadText(name, p);
    } finally {
      m._free(p);
    }
  };
  const message = m.cwrap('vdfx_message', 'string', []);
  const evalJson = m.cwrap('vdfx_eval_json', 'string', ['number', 'number', 'number']);

  check(load(good, fs.readFileSync(good, 'utf8')) === 1, 'the module rejects a valid sidecar: ' + message());
  let worst = 0;
  let worstAt = null;
  points.forEach((p, i) => {
    const w = JSON.parse(evalJson(p[0], p[1], p[2]));
    const n = native[i];
    for (const name of Object.keys(n)) {
      check(name in w, `effect ${name} missing from the module's output`);
      check(w[name].active === n[name].active, `${name} active differs at ${p}`);
      for (const key of Object.keys(n[name])) {
        if (key === 'active') continue;
        const a = [].concat(w[name][key]);
        const b = [].concat(n[name][key]);
        check(a.length === b.length, `${name}.${key} length differs at ${p}`);
        for (let k = 0; k < b.length; k++) {
          const d = Math.abs(a[k] - b[k]);
          if (!(d <= worst)) {
            worst = d;
            worstAt = `${name}.${key}[${k}] at ${p}: wasm ${a[k]}, native ${b[k]}`;
          }
        }
      }
    }
  });
  console.log(`1000 views: largest difference ${worst}` + (worstAt ? ` (${worstAt})` : ''));
  check(worst <= 1e-9, 'the module differs from vdfx eval by more than 1e-9: ' + worstAt);
  // The parameters really vary over the views (a module that returned neutral values would
  // match an inactive sidecar, not this one).
  const stops = new Set(native.map((e) => e.exposure.stops));
  check(stops.size > 900, `vdfx eval gave only ${stops.size} distinct exposures`);

  // A broken sidecar: the same lines as vdfx validate.
  const broken = JSON.parse(JSON.stringify(sidecar));
  broken.effects[1].keyframes[3].frame = frames + 5;
  broken.effects[0].keyframes[0].params.gain = [1, 'red', 1];
  delete broken.video.fps;
  broken.effects.push({ type: 'sparkle', keyframes: [] });
  const bad = path.join(outDir, 'wasm_eval_broken.vdfx.json');
  fs.writeFileSync(bad, JSON.stringify(broken, null, 1));
  const v = spawnSync(vdfx, ['validate', bad], { encoding: 'utf8' });
  check(v.status === 1, `vdfx validate exits ${v.status} on the broken sidecar`);
  check(load(bad, fs.readFileSync(bad, 'utf8')) === 0, 'the module accepts a broken sidecar');
  const wasmMessage = message();
  const lines = wasmMessage.trim().split('\n');
  check(lines.length >= 4, 'the module reports ' + lines.length + ' problems, 4 expected:\n' + wasmMessage);
  check(v.stderr.startsWith(wasmMessage),
    'messages differ:\n--- vdfx validate\n' + v.stderr + '--- module\n' + wasmMessage);

  // A film: 12000 exposure keyframes over 20 minutes, interpolated locally in time (3 MB of
  // text: passed on the module's stack it overflowed it). The module matches vdfx eval.
  const film = {
    format: 'vdfx.sidecar', version: 1,
    video: { path: 'clip.mp4', fps: 30, frames: 36000, width: 3840, height: 1920 },
    interpolation: { exponent: 1.0, time_scale: 1.0 },
    effects: [{ type: 'exposure', keyframes: keyframes(12000, 0, 35999, () => ({ stops: uniform(-2, 2) })) }],
  };
  const filmFile = path.join(outDir, 'wasm_eval_film.vdfx.json');
  fs.writeFileSync(filmFile, JSON.stringify(film, null, 1));
  check(load(filmFile, fs.readFileSync(filmFile, 'utf8')) === 1, 'the module rejects the film: ' + message());
  const filmPoints = points.slice(0, 200).map((p) => [p[0], p[1], Math.floor(p[2] * 120)]);
  const filmArgs = ['eval', filmFile];
  for (const p of filmPoints) filmArgs.push('--at', p.join(','));
  const filmNative = execFileSync(vdfx, filmArgs, { encoding: 'utf8', maxBuffer: 64 << 20 })
    .trim().split('\n').map((l) => JSON.parse(l).effects.exposure.stops);
  let filmWorst = 0;
  filmPoints.forEach((p, i) => {
    const w = JSON.parse(evalJson(p[0], p[1], p[2])).exposure.stops;
    filmWorst = Math.max(filmWorst, Math.abs(w - filmNative[i]));
  });
  console.log(`film (12000 keyframes, local), 200 views: largest difference ${filmWorst}`);
  check(filmWorst <= 1e-9, 'the module differs from vdfx eval on the film by ' + filmWorst);

  const size = fs.statSync(wasmFile).size;
  console.log(`vdfx_player.wasm: ${size} bytes`);
  check(size <= 1.5 * 1024 * 1024, `vdfx_player.wasm is ${size} bytes, over 1.5 MB`);

  if (failures) {
    console.error(`${failures} check(s) failed`);
    process.exit(1);
  }
  console.log('all checks passed');
}).catch((e) => {
  console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exit(1);
});
