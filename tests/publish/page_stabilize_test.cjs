// The page's stabilize=1 hook (CTest: publish.page_stabilize; docs/publish.md, "Stabilised"):
//   node page_stabilize_test.cjs VDFX_BINARY OUTPUT_DIR
// Debian's chromium, headless (browser.cjs). A clip whose sidecar gives the camera turning and
// tilting from frame to frame (source "given") and a direction-dependent exposure: the page at
// view V, frame f, stabilize=1 matches `vdfx render` of the video at Q_f^T R(V) (the contract:
// the picture's direction w shows the video at q_f^-1 w q_f; the view's azimuth, altitude and
// roll computed here) within 3/255 per channel and 1/255 mean, and differs from the page without
// the hook; a sidecar without camera motion is the page's error, naming it.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { serve, Browser, decodePng, diff, pageTest, vdfxRunner } = require('./browser.cjs');

const { args, check, runTest } = pageTest('page_stabilize_test.cjs', ['VDFX_BINARY', 'OUTPUT_DIR']);
const [vdfx, outDir] = args;
const W = 320, H = 180, MAX = 3, MEAN = 1, FRAMES = 8;
const run = vdfxRunner(vdfx);
const DEG = Math.PI / 180;

// Row-major 3x3 helpers: the rotation about an axis, products, transpose.
const rot = (axis, a) => {
  const c = Math.cos(a), s = Math.sin(a);
  if (axis === 'x') return [1, 0, 0, 0, c, -s, 0, s, c];
  if (axis === 'y') return [c, 0, s, 0, 1, 0, -s, 0, c];
  return [c, -s, 0, s, c, 0, 0, 0, 1];
};
const mul = (a, b) => {
  const m = new Array(9).fill(0);
  for (let i = 0; i < 3; ++i)
    for (let j = 0; j < 3; ++j)
      for (let k = 0; k < 3; ++k) m[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return m;
};
const transpose = (a) => [a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]];
// The contract's view rotation (yaw by -azimuth about +y, pitch by altitude, roll about +z).
const view = (az, alt, roll = 0) => mul(mul(rot('y', -az * DEG), rot('x', alt * DEG)),
                                        rot('z', roll * DEG));
// The camera at frame f: yaw 20 degrees a frame, pitch 4.
const camera = (f) => mul(rot('y', 20 * f * DEG), rot('x', 4 * f * DEG));
// Its unit quaternion [w, x, y, z]: the yaw's half-angle quaternion times the pitch's.
function cameraQuat(f) {
  const a = 10 * f * DEG, b = 2 * f * DEG;
  return [Math.cos(a) * Math.cos(b), Math.cos(a) * Math.sin(b), Math.sin(a) * Math.cos(b),
          -Math.sin(a) * Math.sin(b)];
}
// Azimuth, altitude and roll of a view rotation M = view(az, alt, roll).
function angles(m) {
  const f = [-m[2], -m[5], -m[8]];
  const az = Math.atan2(f[0], -f[2]) / DEG, alt = Math.asin(Math.max(-1, Math.min(1, f[1]))) / DEG;
  const r = mul(transpose(view(az, alt)), m);
  return [az, alt, Math.atan2(r[3], r[0]) / DEG];
}

function writeClip(file) {
  const smooth = "r='128+90*sin(2*PI*X/W+0.4*N)':g='128+80*cos(2*PI*Y/H+0.3*N)':" +
                 "b='128+70*sin(2*PI*(X/W+Y/H))'";
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
    `nullsrc=s=512x256:r=24,format=rgb24,geq=${smooth}`, '-frames:v', String(FRAMES),
    '-vf', 'scale=out_color_matrix=bt709:out_range=tv', '-pix_fmt', 'yuv420p',
    '-colorspace', 'bt709', '-color_primaries', 'bt709', '-color_trc', 'bt709',
    '-color_range', 'tv', '-c:v', 'libx264', '-preset', 'fast', '-qp', '8', file]);
}

const key = (az, alt, params) => ({ azimuth_deg: az, altitude_deg: alt, frame: 0, params });
function sidecar(withCamera) {
  const s = { format: 'vdfx.sidecar', version: 1,
              video: { path: 'clip.mp4', fps: 24, frames: FRAMES, width: 512, height: 256 },
              interpolation: { exponent: 1.0, time_scale: 1.0 },
              effects: [{ type: 'exposure', keyframes: [key(0, 0, { stops: 0.8 }),
                                                        key(180, 0, { stops: -0.8 })] }] };
  if (withCamera)
    s.camera = { source: 'given', orientation: [...Array(FRAMES).keys()].map(cameraQuat) };
  return s;
}

async function shot(browser, port, site, query) {
  const title = await browser.open(`http://127.0.0.1:${port}/${site}/index.html?${query}` +
                                   `&size=${W}x${H}&paused=1`, W, H);
  return { title, png: title.startsWith('vdfx-ready') ? await browser.screenshot(W, H) : null };
}

runTest('publish.page_stabilize', async () => {
  const clip = path.join(outDir, 'clip.mp4');
  writeClip(clip);
  for (const [name, withCamera] of [['turning', true], ['plain', false]]) {
    const file = path.join(outDir, `${name}.vdfx.json`);
    fs.writeFileSync(file, JSON.stringify(sidecar(withCamera), null, 1));
    run(['publish', clip, '--sidecar', file, '--out', path.join(outDir, name)]);
  }
  // The quaternions written are the rotations the references use.
  for (let f = 0; f < FRAMES; ++f) {
    const [w, x, y, z] = cameraQuat(f);
    const m = [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
               2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
               2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)];
    check(m.every((v, i) => Math.abs(v - camera(f)[i]) < 1e-12), `frame ${f}: quaternion`);
  }
  const server = await serve(outDir);
  const port = server.address().port;
  const browser = await Browser.launch(path.join(outDir, 'chromium-profile'), W, H);
  const video = path.join(outDir, 'turning', 'video.mp4');
  const side = path.join(outDir, 'turning.vdfx.json');
  try {
    for (const [az, alt, f, fov] of [[10, 5, 2, 90], [-40, 10, 6, 80], [120, -5, 7, 70]]) {
      const label = `view ${az},${alt} frame ${f} fov ${fov}`;
      const q = `view=${az},${alt}&frame=${f}&fov=${fov}`;
      const page = await shot(browser, port, 'turning', `${q}&stabilize=1`);
      if (!page.png) {
        check(false, `${label}: ${page.title}`);
        continue;
      }
      const [vaz, valt, vroll] = angles(mul(transpose(camera(f)), view(az, alt)));
      const ref = path.join(outDir, `render_${f}.png`);
      run(['render', video, '--sidecar', side, '--view', `${vaz},${valt},${vroll}`, '--frame',
           String(f), '--fov', String(fov), '--size', `${W}x${H}`, '--mode', 'view', '--out', ref]);
      const d = diff(decodePng(page.png), decodePng(fs.readFileSync(ref)));
      const plain = await shot(browser, port, 'turning', q);
      const moved = diff(decodePng(page.png), decodePng(plain.png));
      console.log(`${label.padEnd(32)} against render at ${vaz.toFixed(1)},${valt.toFixed(1)},` +
                  `${vroll.toFixed(1)}: max ${d.max}/255 mean ${d.mean.toFixed(3)}/255; ` +
                  `unstabilised differs by mean ${moved.mean.toFixed(1)}/255`);
      if (d.max > MAX || d.mean > MEAN) fs.writeFileSync(path.join(outDir, `page_${f}.png`), page.png);
      check(d.max <= MAX && d.mean <= MEAN, `${label}: max ${d.max} mean ${d.mean.toFixed(3)}`);
      check(moved.mean > 10, `${label}: stabilize=1 changes the picture (${moved.mean.toFixed(1)})`);
    }
    const none = await shot(browser, port, 'plain', 'frame=1&stabilize=1');
    check(none.title === 'vdfx-error: stabilize=1: plain.vdfx.json has no camera motion: run ' +
          'vdfx track camera', `no camera: ${none.title}`);
  } finally {
    browser.close();
    server.close();
  }
});
