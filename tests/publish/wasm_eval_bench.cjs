// The web player's per-frame cost of the parameters (docs/publish.md, "Measured"), by hand:
//   node wasm_eval_bench.cjs VDFX_BINARY WASM_DIR OUTPUT_DIR [--page] [--keyframes N] [--frames F]
// A sidecar with every stack effect keyed 1000 times (or N, over 1000 or F frames; above 4096
// keyframes an effect is interpolated locally): the median time of one vdfx_eval (the six
// effects at one view, what the page calls once per frame) over 21 runs of 2000 views, in node;
// the peer in the same run is the native vdfx: (vdfx eval with 2001 views - with 1 view) / 2000,
// median of 5. With --page, also writes OUTPUT_DIR/bench.html, which measures the same in a
// browser (its title is the result) when served next to the module with the sidecar.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');

const [vdfx, wasmDir, outDir] = process.argv.slice(2);
fs.mkdirSync(outDir, { recursive: true });
let seed = 7;
const rand = () => {
  seed = (seed * 1103515245 + 12345) % 2147483648;
  return seed / 2147483648;
};
const uniform = (lo, hi) => lo + (hi - lo) * rand();
const option = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const keyframes = option('--keyframes', 1000);
const frames = option('--frames', 1000);
const kf = (params) => Array.from({ length: keyframes }, () => ({
  azimuth_deg: uniform(-179, 180), altitude_deg: uniform(-85, 85),
  frame: Math.floor(uniform(0, frames)), params: params(),
}));
const sidecar = {
  format: 'vdfx.sidecar', version: 1,
  video: { path: 'clip.mp4', fps: 30, frames, width: 3840, height: 1920 },
  interpolation: { exponent: 1.0, time_scale: 1.0 },
  effects: [
    { type: 'blur', keyframes: kf(() => ({ sigma_deg: uniform(0, 2) })) },
    { type: 'tint', keyframes: kf(() => ({ gain: [uniform(0.5, 2), uniform(0.5, 2), uniform(0.5, 2)] })) },
    { type: 'exposure', keyframes: kf(() => ({ stops: uniform(-2, 2) })) },
    { type: 'saturation', keyframes: kf(() => ({ amount: uniform(0.2, 2) })) },
    { type: 'contrast', keyframes: kf(() => ({ amount: uniform(0.5, 1.5) })) },
    { type: 'vignette', keyframes: kf(() => ({ radius_deg: uniform(20, 90), falloff_deg: uniform(5, 60) })) },
  ],
};
const file = path.join(outDir, 'bench.vdfx.json');
fs.writeFileSync(file, JSON.stringify(sidecar));
const views = Array.from({ length: 2000 }, () => [uniform(-179, 180), uniform(-90, 90), Math.floor(uniform(0, frames))]);
const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];

function nativeRun(n) {
  const args = ['eval', file];
  for (const v of views.slice(0, n)) args.push('--at', v.join(','));
  const t0 = process.hrtime.bigint();
  execFileSync(vdfx, args, { maxBuffer: 256 << 20 });
  return Number(process.hrtime.bigint() - t0) / 1e6;
}
const native = [];
for (let r = 0; r < 5; r++) native.push((nativeRun(views.length) - nativeRun(1)) / views.length);

const create = require(path.resolve(wasmDir, 'vdfx_player.js'));
create({ wasmBinary: fs.readFileSync(path.join(wasmDir, 'vdfx_player.wasm')) }).then((m) => {
  const loadText = m.cwrap('vdfx_load', 'number', ['string', 'number']);
  const load = (name, text) => {  // the text on the heap, as the page passes it
    const p = m.allocateUTF8(text);
    try {
      return loadText(name, p);
    } finally {
      m._free(p);
    }
  };
  const t0 = process.hrtime.bigint();
  if (load(file, fs.readFileSync(file, 'utf8')) !== 1) throw new Error(m.UTF8ToString(m._vdfx_message()));
  const loadMs = Number(process.hrtime.bigint() - t0) / 1e6;
  const out = m._malloc(9 * 8);
  const runs = [];
  for (let r = 0; r < 21; r++) {
    const s = process.hrtime.bigint();
    for (const v of views) m._vdfx_eval(v[0], v[1], v[2], out);
    runs.push(Number(process.hrtime.bigint() - s) / 1e6 / views.length);
  }
  console.log(`load and solve (6 x ${keyframes} keyframes): ${loadMs.toFixed(0)} ms`);
  console.log(`one evaluation of the 6 effects, median: wasm (node ${process.version}) ` +
    `${(median(runs) * 1000).toFixed(1)} us, native vdfx ${(median(native) * 1000).toFixed(1)} us`);
  if (process.argv.includes('--page')) {
    fs.writeFileSync(path.join(outDir, 'bench.html'), `<!doctype html><script src="vdfx_player.js"></script><script>
createVdfxPlayer().then(async (m) => {
  const text = await (await fetch('bench.vdfx.json')).text();
  const p = m.allocateUTF8(text);
  m.ccall('vdfx_load', 'number', ['string', 'number'], ['bench.vdfx.json', p]);
  const views = ${JSON.stringify(views.slice(0, 500))};
  const out = m._malloc(72), runs = [];
  for (let r = 0; r < 21; r++) {
    const s = performance.now();
    for (const v of views) m._vdfx_eval(v[0], v[1], v[2], out);
    runs.push((performance.now() - s) / views.length);
  }
  runs.sort((a, b) => a - b);
  document.title = 'median ' + (runs[10] * 1000).toFixed(1) + ' us';
});
</script>`);
  }
});
