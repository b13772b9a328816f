// The page's per-frame cost in Chromium (docs/publish.md, "Measured"), by hand:
//   node page_bench.cjs VDFX_BINARY OUTPUT_DIR [VIDEO_WxH] [KEYFRAMES] [FRAMES]
// Publishes a clip (ffmpeg's testsrc2, 512 x 256 or VIDEO_WxH, 48 frames or FRAMES at 24 fps)
// with a sidecar of 8 effects keyed 1000 (or KEYFRAMES) times each (the six stack effects, a
// directional flare and a surface grain; above 4096 keyframes interpolated locally), plays the
// page in headless Chromium (SwiftShader) at 1280 x 720 for a few seconds, and prints the medians
// of window.vdfxStats: the module's evaluation (vdfx_eval and the flare and grain layout, once
// per drawn frame) and the draw (the GL calls; SwiftShader renders on the CPU), the load and
// solve time, and the folder's size (what a viewer downloads, the video included).
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { serve, Browser } = require('./browser.cjs');

const [vdfx, outDir] = process.argv.slice(2, 4).map((p) => p && path.resolve(p));
const [VW, VH] = (process.argv[4] || '512x256').split('x').map(Number);
if (!vdfx || !outDir) {
  console.error('usage: node page_bench.cjs VDFX_BINARY OUTPUT_DIR [VIDEO_WxH] [KEYFRAMES] [FRAMES]');
  process.exit(2);
}
fs.rmSync(outDir, { recursive: true, force: true });
fs.mkdirSync(outDir, { recursive: true });
let seed = 11;
const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
const uniform = (lo, hi) => lo + (hi - lo) * rand();
const keyframes = Number(process.argv[5] || 1000);
const frames = Number(process.argv[6] || 48);
const kf = (params) => Array.from({ length: keyframes }, () => ({
  azimuth_deg: uniform(-179, 180), altitude_deg: uniform(-85, 85),
  frame: Math.floor(uniform(0, frames)), params: params() }));
const sidecar = {
  format: 'vdfx.sidecar', version: 1,
  video: { path: 'clip.mp4', fps: 24, frames, width: VW, height: VH },
  interpolation: { exponent: 1.0, time_scale: 1.0 },
  effects: [
    { type: 'blur', keyframes: kf(() => ({ sigma_deg: uniform(0, 1) })) },
    { type: 'tint', keyframes: kf(() => ({ gain: [uniform(0.5, 2), uniform(0.5, 2), uniform(0.5, 2)] })) },
    { type: 'exposure', keyframes: kf(() => ({ stops: uniform(-2, 2) })) },
    { type: 'saturation', keyframes: kf(() => ({ amount: uniform(0.2, 2) })) },
    { type: 'contrast', keyframes: kf(() => ({ amount: uniform(0.5, 1.5) })) },
    { type: 'vignette', keyframes: kf(() => ({ radius_deg: uniform(20, 90), falloff_deg: uniform(5, 60) })) },
    { type: 'flare', style: 'directional', light: { azimuth_deg: 30, altitude_deg: 10 },
      settings: { fade_deg: 60 }, keyframes: kf(() => ({ intensity: uniform(0.2, 2) })) },
    { type: 'grain', style: 'surface', seed: 4,
      keyframes: kf(() => ({ intensity: uniform(0.1, 1), size: uniform(1, 4) })) },
  ],
};
const clip = path.join(outDir, 'clip.mp4'), file = path.join(outDir, 'bench.vdfx.json');
execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
  `testsrc2=s=${VW}x${VH}:r=24`,
  '-frames:v', String(frames), '-pix_fmt', 'yuv420p', '-c:v', 'libx264', clip]);
fs.writeFileSync(file, JSON.stringify(sidecar));
const site = path.join(outDir, 'site');
execFileSync(vdfx, ['publish', clip, '--sidecar', file, '--out', site]);
const bytes = fs.readdirSync(site, { recursive: true })
  .map((f) => path.join(site, f)).filter((f) => fs.statSync(f).isFile())
  .reduce((n, f) => n + fs.statSync(f).size, 0);
const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];

(async () => {
  const server = await serve(outDir);
  const W = 1280, H = 720;
  const browser = await Browser.launch(path.join(outDir, 'profile'), W, H);
  try {
    await browser.send('Emulation.setDeviceMetricsOverride',
                       { width: W, height: H, deviceScaleFactor: 1, mobile: false });
    const t0 = Date.now();
    await browser.send('Page.navigate',
                       { url: `http://127.0.0.1:${server.address().port}/site/index.html` });
    while (!(await browser.evaluate('(window.vdfxStats?.evalMs.length ?? 0) > 0')))
      await new Promise((r) => setTimeout(r, 20));
    const firstMs = Date.now() - t0;
    await new Promise((r) => setTimeout(r, 6000));
    const s = await browser.evaluate('window.vdfxStats');
    // performance.now() ticks in 100 us steps on a page that is not cross-origin isolated, so
    // one call is timed as 2000 calls (the page's own module.eval: cwrap, the heap copy) at
    // random views and frames, 21 times.
    // The 6 stack effects alone (module.eval), then all 8: module.eval, the flare and grain
    // layout at the head's pose (layers.update) and each grain layer's uniforms for the eye.
    const perCall = (all) => browser.evaluate(`(() => {
      const p = window.vdfxPlayer, m = p.module, layers = p.renderer.layers, runs = [];
      // The head's rotation at (azimuth a, altitude b), row-major (renderer.js, viewRotation).
      const rotation = (a, b) => {
        const ca = Math.cos(-a * Math.PI / 180), sa = Math.sin(-a * Math.PI / 180);
        const cb = Math.cos(b * Math.PI / 180), sb = Math.sin(b * Math.PI / 180);
        return [ca, sa * sb, sa * cb, 0, cb, -sb, -sa, ca * sb, ca * cb];
      };
      let seed = 3;
      const r = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
      const views = Array.from({ length: 2000 }, () => [360 * r() - 179, 180 * r() - 90,
                                                         Math.floor(${frames} * r())]);
      for (let k = 0; k < 21; ++k) {
        const t = performance.now();
        for (const v of views) {
          m.eval(v[0], v[1], v[2]);
          if (!${all}) continue;
          const eye = { rot: rotation(v[0], v[1]), pos: [0, 0, 0], tan: [-1, 1, -0.5625, 0.5625] };
          layers.update(eye.rot, eye.pos, v[2]);
          for (let g = 0; g < layers.frame.grains; ++g) layers.calls.grain(g, eye);
        }
        runs.push((performance.now() - t) / views.length);
      }
      return runs.sort((a, b) => a - b)[10];
    })()`);
    // Alternated, the better of two each: the shared machine's load moves between runs.
    const eightA = await perCall(true), six = Math.min(await perCall(false), await perCall(false));
    const eight = Math.min(eightA, await perCall(true));
    // The draw path itself, warm: 60 more draws of the current frame at turning views, each
    // timed by the page as during playback (its evaluation: the view's rotation, module.eval,
    // the flare and grain layout).
    const warm = await browser.evaluate(`(() => {
      const p = window.vdfxPlayer, before = p.stats.evalMs.length;
      for (let k = 0; k < 60; ++k) {
        p.view.az = -179 + 6 * k;
        p.draw();
      }
      return p.stats.evalMs.slice(before);
    })()`);
    console.log(`first frame after ${firstMs} ms (module, sidecar load and solve of 8 x ` +
                `${keyframes} keyframes, shaders, video)`);
    console.log(`one evaluation, median of 21 runs of 2000 random views and frames: the 6 stack ` +
                `effects ${(six * 1000).toFixed(1)} us; all 8 (the page's per-frame calls: the ` +
                `stack, the flare and grain layout, the grain's uniforms) ` +
                `${(eight * 1000).toFixed(1)} us`);
    console.log(`${s.evalMs.length} frames drawn: evaluation median ${(median(s.evalMs) * 1000).toFixed(0)} us, ` +
                `draw median ${median(s.drawMs).toFixed(1)} ms (${W}x${H}, SwiftShader), ` +
                `conversion ${s.conversion}, frame upload median ${median(s.uploadMs).toFixed(1)} ms ` +
                `(${VW}x${VH}: WebCodecs copy, chroma split, three texture uploads with mipmaps)`);
    console.log(`playback evaluations (ms): ${s.evalMs.map((x) => x.toFixed(1)).join(" ")}`);
    console.log(`${warm.length} more draws, warm, at turning views: evaluation median ` +
                `${(median(warm) * 1000).toFixed(0)} us (performance.now() steps of 100 us here)`);
    console.log(`folder ${(bytes / 1e6).toFixed(2)} MB, of which the video ${(fs.statSync(path.join(site, 'video.mp4')).size / 1e6).toFixed(2)} MB`);
  } finally {
    browser.close();
    server.close();
  }
})().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
