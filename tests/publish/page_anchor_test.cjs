// Anchored effects on the page of `vdfx publish` in a real browser (CTest: publish.page_anchor;
// docs/anchors.md):
//   node page_anchor_test.cjs VDFX_BINARY OUTPUT_DIR
// A clip whose camera turns (the sidecar's camera, source "given": 30 degrees right a frame), a
// world-anchored exposure, a track-anchored saturation and a world-anchored directional flare
// with a fixed light. At three views and frames the page's canvas matches `vdfx render --mode
// view` within 3/255 per channel and 1/255 mean, and, so that the comparison is about anchors,
// the render of the same sidecar with every anchor taken out differs there.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync, spawnSync } = require('child_process');
const { serve, Browser, decodePng, diff, pageTest } = require('./browser.cjs');

const { args, check, runTest } = pageTest('page_anchor_test.cjs', ['VDFX_BINARY', 'OUTPUT_DIR']);
const [vdfx, outDir] = args;
const W = 240, H = 136, MAX = 3, MEAN = 1, FRAMES = 6, TURN_DEG = 30;

function run(args) {
  const r = spawnSync(vdfx, args, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`vdfx ${args.join(' ')}: exit ${r.status}\n${r.stderr}`);
  return r;
}

// 512 x 256, smooth colours (as page_effects_test.cjs), H.264 4:2:0 BT.709 limited range.
function writeClip(file) {
  const smooth = "r='128+90*sin(2*PI*X/W+0.4*N)':g='128+80*cos(2*PI*Y/H+0.3*N)':" +
                 "b='128+70*sin(2*PI*(X/W+Y/H))'";
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
    `nullsrc=s=512x256:r=24,format=rgb24,geq=${smooth}`, '-frames:v', String(FRAMES),
    '-vf', 'scale=out_color_matrix=bt709:out_range=tv', '-pix_fmt', 'yuv420p',
    '-colorspace', 'bt709', '-color_primaries', 'bt709', '-color_trc', 'bt709',
    '-color_range', 'tv', '-c:v', 'libx264', '-preset', 'fast', '-qp', '8', file]);
}

const key = (az, alt, frame, params) => ({ azimuth_deg: az, altitude_deg: alt, frame, params });

// The camera turned right by TURN_DEG a frame: q_f about +y by -f * TURN_DEG.
function camera() {
  const orientation = [];
  for (let f = 0; f < FRAMES; ++f) {
    const h = (-f * TURN_DEG * Math.PI) / 360;
    orientation.push([Math.cos(h), 0, Math.sin(h), 0]);
  }
  return { source: 'given', orientation };
}

function sidecar(anchored) {
  const anchor = (a) => (anchored ? { anchor: a } : {});
  return {
    format: 'vdfx.sidecar', version: 1,
    video: { path: 'clip.mp4', fps: 24, frames: FRAMES, width: 512, height: 256 },
    interpolation: { exponent: 1.0, time_scale: 1.0 },
    effects: [
      { type: 'exposure', ...anchor('world'),
        keyframes: [key(20, 0, 0, { stops: 1.0 }), key(-160, 0, 0, { stops: -1.0 })] },
      { type: 'saturation', ...anchor('track:actor'),
        keyframes: [key(-40, 0, 0, { amount: 2.5 }), key(140, 0, 0, { amount: 0.3 })] },
      { type: 'flare', style: 'directional', ...anchor('world'),
        light: { azimuth_deg: 50, altitude_deg: 10 }, settings: { fade_deg: 60, ramp_deg: 10 },
        keyframes: [key(50, 10, 0, { intensity: 1.0 })] },
    ],
    camera: camera(),
    tracks: [{ name: 'actor', points: Array.from({ length: FRAMES }, (_, f) =>
      ({ frame: f, azimuth_deg: -40 + 25 * f, altitude_deg: 0, confidence: 1 })) }],
  };
}

// Views [azimuth, altitude, frame, fov]: frame 0 (where world and video agree) and two frames
// the camera has turned by.
const VIEWS = [[20, 0, 0, 90], [-40, 5, 3, 80], [-100, -5, 5, 100]];

function renderOf(video, side, v, name) {
  const out = path.join(outDir, `${name}_${v.join('_')}.png`);
  run(['render', video, '--sidecar', side, '--view', `${v[0]},${v[1]}`, '--frame', String(v[2]),
       '--fov', String(v[3]), '--size', `${W}x${H}`, '--mode', 'view', '--out', out]);
  return decodePng(fs.readFileSync(out));
}

runTest('publish.page_anchor', async () => {
  const clip = path.join(outDir, 'clip.mp4');
  writeClip(clip);
  const anchored = path.join(outDir, 'anchored.vdfx.json');
  const plain = path.join(outDir, 'plain.vdfx.json');
  fs.writeFileSync(anchored, JSON.stringify(sidecar(true), null, 1));
  fs.writeFileSync(plain, JSON.stringify(sidecar(false), null, 1));
  run(['publish', clip, '--sidecar', anchored, '--out', path.join(outDir, 'site')]);
  const video = path.join(outDir, 'site', 'video.mp4');
  const server = await serve(outDir);
  // A browser per view: in one browser the second load of this site reaches vdfx-ready in 0.3 to
  // 0.5 s and its requestAnimationFrame fires, but DevTools' Page.captureScreenshot is then never
  // answered (a capture not from the surface answered once, and the next call stalled again);
  // each view alone passes. A DevTools capture stall, not the page's: not found further yet.
  let browser = null;
  try {
    for (const v of VIEWS) {
      if (browser) browser.close();
      browser = await Browser.launch(path.join(outDir, `chromium-profile-${v.join('_')}`), W, H);
      const label = `view ${v[0]},${v[1]} frame ${v[2]} fov ${v[3]}`;
      const title = await browser.open(`http://127.0.0.1:${server.address().port}/site/` +
        `index.html?view=${v[0]},${v[1]}&frame=${v[2]}&fov=${v[3]}&size=${W}x${H}&paused=1`, W, H);
      if (!title.startsWith('vdfx-ready')) {
        check(false, `${label}: ${title}`);
        continue;
      }
      const png = await browser.screenshot(W, H);
      fs.writeFileSync(path.join(outDir, `page_${v.join('_')}.png`), png);
      const ref = renderOf(video, anchored, v, 'render');
      const d = diff(decodePng(png), ref);
      console.log(`${label.padEnd(36)} page vs render: max ${d.max}/255  mean ` +
                  `${d.mean.toFixed(3)}/255`);
      check(d.max <= MAX && d.mean <= MEAN,
            `${label}: max ${d.max} mean ${d.mean.toFixed(3)} (allowed ${MAX}, ${MEAN})`);
      if (v[2] === 0) continue;
      const unanchored = diff(ref, renderOf(video, plain, v, 'plain'));
      check(unanchored.mean > 10,
            `${label}: the anchors change the picture (mean ${unanchored.mean.toFixed(2)})`);
    }
  } finally {
    if (browser) browser.close();
    server.close();
  }
});
