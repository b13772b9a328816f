// Flares and grain on the page of `vdfx publish` in a real browser (CTest: publish.page_effects;
// docs/publish.md):
//   node page_effects_test.cjs VDFX_BINARY SOURCE_DIR OUTPUT_DIR
// Debian's chromium, headless, WebGL2 through SwiftShader (browser.cjs). For each site, at three
// views, frames and fields of view, the page's canvas matches `vdfx render --mode view` of the
// same view, frame, FOV and size within 3/255 per channel and 1/255 mean:
//  - flares: a directional flare with a fixed light and a headset flare on a light track;
//  - an auto light: a clip with a bright spot that moves, whose light publish tracks into
//    lights.json (checked to be near the spot) and the page's module reads;
//  - grain: the headset and the surface style (the frame's grain: its refresh from the frame's
//    display time, as vdfx render picks it).
// player.json's left_out names nothing for these, and a volumetric grain stays named there.
// WebXR (a fake XRSystem, fake_xr.cjs): the flares and the headset grain drawn per eye, the eyes
// half the IPD to the head's sides with the asymmetric frusta of xr/headset/profiles/offcentre.json; each
// half of the canvas matches `vdfx render --hmd offcentre.json --eye left|right` (no distortion).
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { serve, Browser, decodePng, diff, pageTest, vdfxRunner } = require('./browser.cjs');
const { fakeXr, viewQuaternion, projectionOf, half } = require('./fake_xr.cjs');

const { args, check, runTest } =
  pageTest('page_effects_test.cjs', ['VDFX_BINARY', 'SOURCE_DIR', 'OUTPUT_DIR']);
const [vdfx, sourceDir, outDir] = args;
const W = 320, H = 180, MAX = 3, MEAN = 1;

const run = vdfxRunner(vdfx);

// 512 x 256, 8 frames at 24 fps, H.264 4:2:0 BT.709 limited range (as page_test.cjs). `spot`:
// a dim frame with a white spot (a Gaussian of 4 px sigma reaching full white) that moves right
// 4 px a frame from (300, 90). Soft, not a hard-edged disc: at a hard white edge on a dark ground
// the subsampled chroma overshoots the RGB range, and the video layer's two paths clamp at
// different places (vdfx render converts and clamps each pixel, then interpolates; the page
// interpolates the planes, then converts and clamps): max 9/255 on the disc's rim with no flare
// at all (docs/publish.md). This test is about the flare.
function writeClip(file, spot) {
  const smooth = "r='128+90*sin(2*PI*X/W+0.4*N)':g='128+80*cos(2*PI*Y/H+0.3*N)':" +
                 "b='128+70*sin(2*PI*(X/W+Y/H))'";
  const s = 'exp(-(pow(X-300-4*N,2)+pow(Y-90,2))/32)';
  const dim = `r='50+20*sin(2*PI*X/W)+${s}*(185-20*sin(2*PI*X/W))':` +
              `g='55+20*cos(2*PI*Y/H)+${s}*(180-20*cos(2*PI*Y/H))':b='60+${s}*175'`;
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
    `nullsrc=s=512x256:r=24,format=rgb24,geq=${spot ? dim : smooth}`, '-frames:v', '8',
    '-vf', 'scale=out_color_matrix=bt709:out_range=tv', '-pix_fmt', 'yuv420p',
    '-colorspace', 'bt709', '-color_primaries', 'bt709', '-color_trc', 'bt709',
    '-color_range', 'tv', '-c:v', 'libx264', '-preset', 'fast', '-qp', '8', file]);
}

const VIDEO = { path: 'clip.mp4', fps: 24, frames: 8, width: 512, height: 256 };
const key = (az, alt, frame, params) => ({ azimuth_deg: az, altitude_deg: alt, frame, params });

// The sites: each its sidecar's flares and grains (and an exposure, so the stack runs under
// them), the clip, and the views [azimuth, altitude, frame, fov].
const SITES = {
  flares: {
    clip: 'smooth',
    flares: [
      { type: 'flare', style: 'directional', light: { azimuth_deg: 20, altitude_deg: 10 },
        settings: { fade_deg: 40, ramp_deg: 10, rings: 6 },
        keyframes: [key(0, 0, 0, { intensity: 1.2 }), key(40, 10, 7, { intensity: 0.6 })] },
      { type: 'flare', style: 'headset',
        light: [{ frame: 0, azimuth_deg: -30, altitude_deg: 0 },
                { frame: 7, azimuth_deg: -10, altitude_deg: 15 }],
        settings: { fade_deg: 35, plane_m: 0.08 },
        keyframes: [key(-20, 0, 0, { intensity: 0.8 })] },
    ],
    views: [[10, 5, 2, 90], [-15, 5, 6, 70], [30, -5, 4, 100]],
  },
  auto_light: {
    clip: 'spot',
    flares: [{ type: 'flare', style: 'directional', light: 'auto',
               settings: { fade_deg: 40, ramp_deg: 10 },
               keyframes: [key(0, 0, 0, { intensity: 1.0 })] }],
    views: [[25, 20, 4, 90], [45, 25, 7, 80], [5, 10, 1, 100]],
  },
  grain_headset: {
    clip: 'smooth',
    grains: [{ type: 'grain', style: 'headset', seed: 5,
               keyframes: [key(0, 0, 0, { intensity: 0.7, size: 3 }),
                           key(90, 0, 7, { intensity: 0.4, size: 4 })] }],
    views: [[0, 0, 0, 60], [60, 20, 5, 70], [-80, -20, 3, 50]],
  },
  grain_surface: {
    clip: 'smooth',
    grains: [{ type: 'grain', style: 'surface', seed: 9, settings: { sphere_m: 5 },
               keyframes: [key(0, 0, 0, { intensity: 0.8, size: 3.5 }),
                           key(-90, 30, 7, { intensity: 0.5, size: 2.5 })] }],
    views: [[20, 10, 1, 60], [-70, 25, 6, 70], [160, -10, 2, 50]],
  },
};

function sidecarOf(site) {
  return { format: 'vdfx.sidecar', version: 1, video: VIDEO,
           interpolation: { exponent: 1.0, time_scale: 1.0 },
           effects: [{ type: 'exposure', keyframes: [key(0, 0, 0, { stops: 0.3 })] },
                     ...(site.flares ?? []), ...(site.grains ?? [])] };
}

function publishSites() {
  const clips = { smooth: path.join(outDir, 'clip.mp4'), spot: path.join(outDir, 'spot.mp4') };
  writeClip(clips.smooth, false);
  writeClip(clips.spot, true);
  for (const [name, site] of Object.entries(SITES)) {
    site.sidecar = path.join(outDir, `${name}.vdfx.json`);
    fs.writeFileSync(site.sidecar, JSON.stringify(sidecarOf(site), null, 1));
    run(['publish', clips[site.clip], '--sidecar', site.sidecar, '--out', path.join(outDir, name)]);
    site.video = path.join(outDir, name, 'video.mp4');
    const manifest = JSON.parse(fs.readFileSync(path.join(outDir, name, 'player.json')));
    check(manifest.left_out.length === 0, `${name}: left_out ${JSON.stringify(manifest.left_out)}`);
  }
}

// The auto light's lights.json: a light on every frame, near the spot's centre.
function checkLights() {
  const lights = JSON.parse(fs.readFileSync(path.join(outDir, 'auto_light', 'lights.json')));
  check(lights.format === 'vdfx.lights' && lights.lights.length === 8, 'lights.json: 8 frames');
  lights.lights.forEach((l, f) => {
    // Pixel (300 + 4f, 90) of 512 x 256: azimuth (u - 0.5) 360, altitude (0.5 - v) 180.
    const az = ((300.5 + 4 * f) / 512 - 0.5) * 360, alt = (0.5 - 90.5 / 256) * 180;
    check(l && Math.abs(l.azimuth_deg - az) < 1.5 && Math.abs(l.altitude_deg - alt) < 1.5,
          `lights.json frame ${f}: ${JSON.stringify(l)}, the spot at ` +
          `${az.toFixed(1)},${alt.toFixed(1)}`);
  });
}

// A volumetric grain is not drawn by the page: player.json names it.
function checkLeftOut() {
  const sidecar = path.join(outDir, 'cloud.vdfx.json');
  const site = { grains: [{ type: 'grain', style: 'free_cloud', seed: 3,
                            keyframes: [key(0, 0, 0, { intensity: 0.5, size: 1 })] }] };
  fs.writeFileSync(sidecar, JSON.stringify(sidecarOf(site), null, 1));
  run(['publish', path.join(outDir, 'clip.mp4'), '--sidecar', sidecar, '--out',
       path.join(outDir, 'cloud')]);
  const manifest = JSON.parse(fs.readFileSync(path.join(outDir, 'cloud', 'player.json')));
  check(JSON.stringify(manifest.left_out) === '["grain #1 (free_cloud)"]',
        `volumetric grain: left_out ${JSON.stringify(manifest.left_out)}`);
}

async function comparePixels(browser, port) {
  const rows = [];
  for (const [name, site] of Object.entries(SITES)) {
    for (const v of site.views) {
      const label = `${name} view ${v[0]},${v[1]} frame ${v[2]} fov ${v[3]}`;
      const title = await browser.open(`http://127.0.0.1:${port}/${name}/index.html?view=` +
        `${v[0]},${v[1]}&frame=${v[2]}&fov=${v[3]}&size=${W}x${H}&paused=1`, W, H);
      if (!title.startsWith('vdfx-ready')) {
        check(false, `${label}: ${title}`);
        continue;
      }
      const shot = await browser.screenshot(W, H);
      const ref = path.join(outDir, `${name}_${v.join('_')}_render.png`);
      run(['render', site.video, '--sidecar', site.sidecar, '--view', `${v[0]},${v[1]}`,
           '--frame', String(v[2]), '--fov', String(v[3]), '--size', `${W}x${H}`,
           '--mode', 'view', '--out', ref]);
      const d = diff(decodePng(shot), decodePng(fs.readFileSync(ref)));
      rows.push(`${label.padEnd(44)} max ${d.max}/255  mean ${d.mean.toFixed(3)}/255`);
      const ok = d.max <= MAX && d.mean <= MEAN;
      if (!ok || v === site.views[0])
        fs.writeFileSync(path.join(outDir, `${name}_${v.join('_')}_page.png`), shot);
      check(ok, `${label}: max ${d.max} mean ${d.mean.toFixed(3)} (allowed ${MAX}, ${MEAN})`);
    }
  }
  console.log(rows.join('\n'));
}

// The eyes of xr/headset/profiles/offcentre.json: tangents of its fov_deg (left, right, down, up) and
// its IPD. The canvas is 640 x 360, each eye 320 x 360: at 160 px across its 90 degrees the
// grain's lattice would be finer than a pixel, and the band limit would leave no grain to test.
const XW = 640, XH = 360;
const OFFCENTRE = { ipd: 0.064, eyes: [
  { eye: 'left', deg: [-60, 30, -35, 45] }, { eye: 'right', deg: [-30, 60, -35, 45] }] };

// One XR frame of `site` with the head at (az, alt) at the origin: each eye at
// head.orientation * (-+ipd/2, 0, 0), parallel to the head, its own projection.
async function checkXr(browser, port, name, [az, alt, frame]) {
  const profile = path.join(sourceDir, 'xr', 'headset', 'profiles', 'offcentre.json');
  const q = viewQuaternion(az, alt);
  // The head's x axis (right) in LOCAL: the first column of its rotation (renderer.js,
  // viewRotation), which the altitude does not tilt.
  const a = (az * Math.PI) / 180, right = [Math.cos(a), 0, Math.sin(a)];
  const views = OFFCENTRE.eyes.map((e, i) => ({
    eye: e.eye, q, P: projectionOf(e.deg.map((d) => Math.tan((d * Math.PI) / 180))),
    pos: right.map((x) => ((i ? 0.5 : -0.5) * OFFCENTRE.ipd) * x) }));
  const script = await browser.send('Page.addScriptToEvaluateOnNewDocument',
                                    { source: fakeXr({ head: q, headPos: [0, 0, 0], views }) });
  const title = await browser.open(`http://127.0.0.1:${port}/${name}/index.html?frame=${frame}` +
                                   `&size=${XW}x${XH}&xr=1`, XW, XH);
  await browser.send('Page.removeScriptToEvaluateOnNewDocument', script);
  if (!title.startsWith('vdfx-ready')) return check(false, `WebXR ${name}: ${title}`);
  const png = await browser.screenshot(XW, XH), shot = decodePng(png);
  fs.writeFileSync(path.join(outDir, `xr_${name}_page.png`), png);
  const site = SITES[name];
  for (const [i, e] of OFFCENTRE.eyes.entries()) {
    const ref = path.join(outDir, `xr_${name}_${e.eye}_render.png`);
    run(['render', site.video, '--sidecar', site.sidecar, '--view', `${az},${alt}`, '--frame',
         String(frame), '--hmd', profile, '--eye', e.eye, '--distort', 'none', '--size',
         `${XW / 2}x${XH}`, '--mode', 'view', '--out', ref]);
    const d = diff(half(shot, i), decodePng(fs.readFileSync(ref)));
    const label = `WebXR ${name} ${e.eye} eye, head ${az},${alt} frame ${frame}`;
    console.log(`${label.padEnd(44)} max ${d.max}/255  mean ${d.mean.toFixed(3)}/255`);
    check(d.max <= MAX && d.mean <= MEAN, `${label}: max ${d.max} mean ${d.mean.toFixed(3)}`);
  }
}

runTest('publish.page_effects', async () => {
  const t0 = Date.now();
  publishSites();
  checkLights();
  checkLeftOut();
  const t1 = Date.now();
  const server = await serve(outDir);
  const browser = await Browser.launch(path.join(outDir, 'chromium-profile'), W, H);
  try {
    await comparePixels(browser, server.address().port);
    await checkXr(browser, server.address().port, 'flares', [-5, 5, 3]);
    await checkXr(browser, server.address().port, 'grain_headset', [20, 10, 4]);
  } finally {
    browser.close();
    server.close();
  }
  console.log(`publish ${((t1 - t0) / 1000).toFixed(1)} s, browser ` +
              `${((Date.now() - t1) / 1000).toFixed(1)} s`);
});
