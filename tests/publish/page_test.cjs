// The page of `vdfx publish` in a real browser (CTest: publish.page; docs/publish.md):
//   node page_test.cjs VDFX_BINARY SOURCE_DIR OUTPUT_DIR
// Debian's chromium, headless, WebGL2 through SwiftShader, driven over the DevTools protocol
// (browser.cjs). Checks:
//  1. for each of the six stack effects (keyed in space and time) and for the demo's sidecar, at
//     three views, frames and fields of view: the page's canvas (its still-frame hooks) matches
//     `vdfx render --mode view` of the same view, frame, FOV and size within 3/255, mean 1/255;
//  2. a broken sidecar in the folder: the page shows the lines `vdfx validate` prints;
//  3. a video the browser cannot decode: the page names the codec and --transcode.
// The clip is smooth H.264 written here with ffmpeg; the page and vdfx render decode the same
// file, so only the Y'CbCr -> RGB conversion and the renderers differ.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { serve, Browser, decodePng, diff, pageTest, vdfxRunner } = require('./browser.cjs');
const { fakeXr, viewQuaternion, projection } = require('./fake_xr.cjs');

const { args, check, runTest } =
  pageTest('page_test.cjs', ['VDFX_BINARY', 'SOURCE_DIR', 'OUTPUT_DIR']);
const [vdfx, sourceDir, outDir] = args;
const W = 320, H = 180, MAX = 3, MEAN = 1;

// 512 x 256, 8 frames at 24 fps: smooth colours that wrap at the seam and move with the frame.
function writeClip(file) {
  const geq = "geq=r='128+90*sin(2*PI*X/W+0.4*N)':g='128+80*cos(2*PI*Y/H+0.3*N)':" +
              "b='128+70*sin(2*PI*(X/W+Y/H))'";
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
    `nullsrc=s=512x256:r=24,format=rgb24,${geq}`, '-frames:v', '8',
    '-vf', 'scale=out_color_matrix=bt709:out_range=tv', '-pix_fmt', 'yuv420p',
    '-colorspace', 'bt709', '-color_primaries', 'bt709', '-color_trc', 'bt709',
    '-color_range', 'tv', '-c:v', 'libx264', '-preset', 'fast', '-qp', '8', file]);
}

// Each effect keyed at three places and frames, so views between them interpolate in space
// and time.
const EFFECTS = {
  blur: [{ sigma_deg: 0.6 }, { sigma_deg: 2.0 }, { sigma_deg: 0.0 }],
  tint: [{ gain: [1.5, 1.0, 0.6] }, { gain: [0.7, 1.0, 1.4] }, { gain: [1, 1, 1] }],
  exposure: [{ stops: 0.8 }, { stops: -1.2 }, { stops: 0.2 }],
  saturation: [{ amount: 1.8 }, { amount: 0.3 }, { amount: 1.0 }],
  contrast: [{ amount: 1.6 }, { amount: 0.6 }, { amount: 1.1 }],
  vignette: [{ radius_deg: 20, falloff_deg: 30 }, { radius_deg: 40, falloff_deg: 10 },
             { radius_deg: 60, falloff_deg: 60 }],
};
const PLACES = [[0, 0, 0], [120, 20, 7], [-120, -30, 3]];
// View (azimuth, altitude), frame, horizontal FOV: the centre, across the seam looking up, and
// low on the far side.
const VIEWS = [[0, 0, 0, 90], [170, 40, 3, 70], [-100, -25, 7, 100]];

function sidecarOf(type) {
  const keyframes = EFFECTS[type].map((params, i) => ({
    azimuth_deg: PLACES[i][0], altitude_deg: PLACES[i][1], frame: PLACES[i][2], params }));
  return { format: 'vdfx.sidecar', version: 1,
           video: { path: 'clip.mp4', fps: 24, frames: 8, width: 512, height: 256 },
           interpolation: { exponent: 1.0, time_scale: 1.0 },
           effects: [{ type, keyframes }] };
}

const run = vdfxRunner(vdfx);

// The folders the browser loads: one per effect, the demo, and two broken ones.
function publishSites() {
  const clip = path.join(outDir, 'clip.mp4');
  writeClip(clip);
  const sites = [];
  for (const type of Object.keys(EFFECTS)) {
    const sidecar = path.join(outDir, `${type}.vdfx.json`);
    fs.writeFileSync(sidecar, JSON.stringify(sidecarOf(type), null, 1));
    run(['publish', clip, '--sidecar', sidecar, '--out', path.join(outDir, type)]);
    sites.push({ name: type, video: path.join(outDir, type, 'video.mp4'), sidecar, views: VIEWS });
  }
  // The demo's sidecar (tint, exposure, saturation, vignette together) on the same clip.
  const demo = JSON.parse(fs.readFileSync(path.join(sourceDir, 'app/demo/interior.vdfx.json')));
  demo.video = sidecarOf('blur').video;
  const demoSidecar = path.join(outDir, 'demo.vdfx.json');
  fs.writeFileSync(demoSidecar, JSON.stringify(demo, null, 1));
  run(['publish', clip, '--sidecar', demoSidecar, '--out', path.join(outDir, 'demo')]);
  sites.push({ name: 'demo', video: path.join(outDir, 'demo', 'video.mp4'), sidecar: demoSidecar,
               views: [[31, 5, 0, 90], [-75, -10, 5, 80], [-150, 0, 2, 100]] });
  return sites;
}

function pageUrl(port, site, [az, alt, frame, fov]) {
  return `http://127.0.0.1:${port}/${site}/index.html?view=${az},${alt}&frame=${frame}` +
         `&fov=${fov}&size=${W}x${H}&paused=1`;
}

async function comparePixels(browser, port, sites) {
  const rows = [];
  for (const site of sites) {
    for (const v of site.views) {
      const label = `${site.name} view ${v[0]},${v[1]} frame ${v[2]} fov ${v[3]}`;
      const title = await browser.open(pageUrl(port, site.name, v), W, H);
      if (!title.startsWith('vdfx-ready')) {
        check(false, `${label}: ${title}`);
        continue;
      }
      // The page converts the decoded planes itself (the shared shader, the stream's tags);
      // the browser's own conversion differs from vdfx's in the chroma siting.
      const conversion = await browser.evaluate('window.vdfxStats.conversion');
      check(conversion === 'vdfx', `${label}: the page's colour conversion is ${conversion}`);
      const shot = await browser.screenshot(W, H);
      const ref = path.join(outDir, `${site.name}_${v.join('_')}_render.png`);
      run(['render', site.video, '--sidecar', site.sidecar, '--view', `${v[0]},${v[1]}`,
           '--frame', String(v[2]), '--fov', String(v[3]), '--size', `${W}x${H}`,
           '--mode', 'view', '--out', ref]);
      const d = diff(decodePng(shot), decodePng(fs.readFileSync(ref)));
      rows.push(`${label.padEnd(48)} max ${d.max}/255  mean ${d.mean.toFixed(3)}/255`);
      const ok = d.max <= MAX && d.mean <= MEAN;
      if (!ok || v === site.views[0])
        fs.writeFileSync(path.join(outDir, `${site.name}_${v.join('_')}_page.png`), shot);
      check(ok, `${label}: max ${d.max} mean ${d.mean.toFixed(3)} (allowed ${MAX}, ${MEAN})`);
    }
  }
  console.log(rows.join('\n'));
}

// A copy of a published folder with `file` replaced by `bytes`.
function brokenSite(from, name, file, bytes) {
  const dir = path.join(outDir, name);
  fs.cpSync(path.join(outDir, from), dir, { recursive: true });
  fs.writeFileSync(path.join(dir, file), bytes);
  return dir;
}

async function checkErrors(browser, port) {
  const text = '{"format": "vdfx.sidecar", "version": 1,\n "video": {"path": "clip.mp4", ' +
    '"fps": 0, "frames": 8, "width": 512, "height": 256},\n "effects": [{"type": "glow"}]}\n';
  const dir = brokenSite('exposure', 'broken_sidecar', 'sidecar.vdfx.json', text);
  const v = run(['validate', 'sidecar.vdfx.json'], { cwd: dir, allowFail: true });
  const lines = v.stderr.trim().split('\n').filter((l) => !/: \d+ problems?$/.test(l));
  check(v.status === 1 && lines.length >= 2, `vdfx validate on the broken sidecar: ${v.stderr}`);
  const title = await browser.open(`http://127.0.0.1:${port}/broken_sidecar/index.html`, W, H);
  const shown = await browser.evaluate("document.getElementById('message').textContent");
  check(title.startsWith('vdfx-error: '), `broken sidecar: title ${title}`);
  check(shown === lines.join('\n'), `broken sidecar: the page shows\n${shown}\n` +
        `and vdfx validate prints\n${lines.join('\n')}`);

  brokenSite('exposure', 'broken_video', 'video.mp4', Buffer.alloc(4096, 7));
  const t2 = await browser.open(`http://127.0.0.1:${port}/broken_video/index.html`, W, H);
  check(t2.startsWith('vdfx-error: ') && t2.includes('codec h264') &&
        t2.includes('--transcode'), `undecodable video: title ${t2}`);
}

// A sidecar whose every active effect is constant at its value at `at` (one keyframe each).
function constantSidecar(sidecar, at, file) {
  const r = run(['eval', sidecar, '--at', at]);
  const effects = Object.entries(JSON.parse(r.stdout).effects)
    .filter(([, v]) => v.active)
    .map(([type, v]) => {
      const params = { ...v };
      delete params.active;
      return { type, keyframes: [{ azimuth_deg: 0, altitude_deg: 0, frame: 0, params }] };
    });
  fs.writeFileSync(file, JSON.stringify({ ...sidecarOf('blur'), effects }, null, 1));
  return file;
}

// WebXR: the head at (40, 10), the eyes turned to azimuth 25 and 55 with FOVs 80 and 70. Each
// half of the canvas must be vdfx render of that eye's view with the parameters of the head's
// view (rendered from a sidecar holding them constant).
async function checkXr(browser, port) {
  const head = [40, 10], frame = 3, w = W / 2;
  const eyes = [{ eye: 'left', az: 25, fov: 80 }, { eye: 'right', az: 55, fov: 70 }];
  const config = { head: viewQuaternion(...head), views: eyes.map((e) => ({
    eye: e.eye, q: viewQuaternion(e.az, head[1]), P: projection(e.fov, w, H) })) };
  const script = await browser.send('Page.addScriptToEvaluateOnNewDocument',
                                    { source: fakeXr(config) });
  const title = await browser.open(`http://127.0.0.1:${port}/demo/index.html?frame=${frame}` +
                                   `&size=${W}x${H}&xr=1`, W, H);
  await browser.send('Page.removeScriptToEvaluateOnNewDocument', script);
  if (!title.startsWith('vdfx-ready')) return check(false, `WebXR: ${title}`);
  const xr = await browser.evaluate('window.vdfxStats.xr');
  check(Math.abs(xr.head.az - head[0]) < 1e-6 && Math.abs(xr.head.alt - head[1]) < 1e-6,
        `WebXR: the head's direction read back as ${JSON.stringify(xr.head)}`);
  const shot = decodePng(await browser.screenshot(W, H));
  fs.writeFileSync(path.join(outDir, 'xr_page.png'), await browser.screenshot(W, H));
  const headSidecar = constantSidecar(path.join(outDir, 'demo.vdfx.json'),
                                      `${head[0]},${head[1]},${frame}`,
                                      path.join(outDir, 'xr_head.vdfx.json'));
  for (const [i, e] of eyes.entries()) {
    const ref = path.join(outDir, `xr_${e.eye}_render.png`);
    run(['render', path.join(outDir, 'demo', 'video.mp4'), '--sidecar', headSidecar, '--view',
         `${e.az},${head[1]}`, '--frame', String(frame), '--fov', String(e.fov), '--size',
         `${w}x${H}`, '--mode', 'view', '--out', ref]);
    const half = { width: w, height: H, rgb: Buffer.alloc(w * H * 3) };
    for (let y = 0; y < H; ++y)
      shot.rgb.copy(half.rgb, y * w * 3, (y * W + i * w) * 3, (y * W + i * w + w) * 3);
    const d = diff(half, decodePng(fs.readFileSync(ref)));
    console.log(`${`WebXR ${e.eye} eye az ${e.az} fov ${e.fov}, head 40,10`.padEnd(48)} ` +
                `max ${d.max}/255  mean ${d.mean.toFixed(3)}/255`);
    check(d.max <= MAX && d.mean <= MEAN, `WebXR ${e.eye} eye: max ${d.max} mean ${d.mean}`);
  }
}

runTest('publish.page', async () => {
  const t0 = Date.now();
  const sites = publishSites();
  const t1 = Date.now();
  const server = await serve(outDir);
  const browser = await Browser.launch(path.join(outDir, 'chromium-profile'), W, H);
  try {
    await comparePixels(browser, server.address().port, sites);
    await checkErrors(browser, server.address().port);
    await checkXr(browser, server.address().port);
  } finally {
    browser.close();
    server.close();
  }
  console.log(`publish ${((t1 - t0) / 1000).toFixed(1)} s, browser ` +
              `${((Date.now() - t1) / 1000).toFixed(1)} s`);
});
