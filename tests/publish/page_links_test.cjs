// The page of `vdfx publish` opened as a link opens it (CTest: publish.page_links;
// docs/publish.md):
//   node page_links_test.cjs VDFX_BINARY OUTPUT_DIR
// Debian's chromium, headless (browser.cjs), on a tiny clip whose frames all differ.
//  1. A link to a moment, in a cold browser (a fresh profile, the page's first load), served as
//     `python3 -m http.server` serves (no byte ranges: the element cannot seek in what it
//     streams) and with ranges: with paused=1 at frame= and at t= (seconds), the canvas at
//     "vdfx-ready" is that frame (it matches `vdfx render --frame N` and not frame 0), cold and
//     then warm; playing from frame= and t=, the first frame drawn is that frame, and every frame
//     drawn is evaluated at the frame its picture is.
//  2. Files named with what URLs cannot hold as they are ('#', '?', '%', spaces, non-ASCII
//     letters, a leading dash): published under fixed names, and played when player.json names
//     such files (every URL the page builds is encoded).
//  3. A file the page cannot fetch (404) is said to be that, not a codec the browser cannot play;
//     a t= or frame= past the end, or both, is an error naming it.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync } = require('child_process');
const { serve, Browser, decodePng, diff, pageTest, vdfxRunner } = require('./browser.cjs');

const { args, check, runTest } = pageTest('page_links_test.cjs', ['VDFX_BINARY', 'OUTPUT_DIR']);
const [vdfx, outDir] = args;
const run = vdfxRunner(vdfx);
const W = 320, H = 180, MAX = 3, MEAN = 1, FPS = 24, FRAMES = 24;
const VIEW = [30, 5], FOV = 90;

// 256 x 128, 24 frames at 24 fps: smooth colours that wrap at the seam and move fast with the
// frame N, so any two frames differ everywhere. H.264 with B-frames (decode order differs from
// display order, as in real footage).
function writeClip(file) {
  const geq = "geq=r='128+90*sin(2*PI*X/W+0.7*N)':g='128+80*cos(2*PI*Y/H+0.5*N)':" +
              "b='128+70*sin(2*PI*(X/W+Y/H)-0.4*N)'";
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i',
    `nullsrc=s=256x128:r=${FPS},format=rgb24,${geq}`, '-frames:v', String(FRAMES),
    '-vf', 'scale=out_color_matrix=bt709:out_range=tv', '-pix_fmt', 'yuv420p',
    '-colorspace', 'bt709', '-color_primaries', 'bt709', '-color_trc', 'bt709',
    '-color_range', 'tv', '-c:v', 'libx264', '-preset', 'fast', '-qp', '10', file]);
}

// An exposure keyed in time, so that a frame's parameters differ from frame 0's too.
function writeSidecar(file) {
  const key = (frame, stops) => ({ azimuth_deg: 0, altitude_deg: 0, frame, params: { stops } });
  fs.writeFileSync(file, JSON.stringify({
    format: 'vdfx.sidecar', version: 1,
    video: { path: 'clip.mp4', fps: FPS, frames: FRAMES, width: 256, height: 128 },
    interpolation: { exponent: 1.0, time_scale: 1.0 },
    effects: [{ type: 'exposure', keyframes: [key(0, 0.5), key(23, -0.5)] }] }, null, 1));
}

// `vdfx render` of frame n at the test's view, decoded.
const renders = new Map();
function render(site, n) {
  if (!renders.has(n)) {
    const out = path.join(outDir, `render_${n}.png`);
    run(['render', path.join(site, 'video.mp4'), '--sidecar', path.join(site, 'sidecar.vdfx.json'),
         '--view', VIEW.join(','), '--frame', String(n), '--fov', String(FOV), '--size',
         `${W}x${H}`, '--mode', 'view', '--out', out]);
    renders.set(n, decodePng(fs.readFileSync(out)));
  }
  return renders.get(n);
}

const url = (port, site, query) =>
  `http://127.0.0.1:${port}/${site}/index.html?view=${VIEW.join(',')}&fov=${FOV}` +
  `&size=${W}x${H}&${query}`;

// The canvas against frame n's render (and, for n > 0, unlike frame 0's).
async function checkCanvas(browser, label, n, site) {
  const png = await browser.screenshot(W, H);
  const d = diff(decodePng(png), render(site, n));
  const d0 = n > 0 ? diff(decodePng(png), render(site, 0)) : null;
  console.log(`${label.padEnd(44)} frame ${n}: max ${d.max}/255 mean ${d.mean.toFixed(3)}` +
              (d0 ? `; against frame 0 mean ${d0.mean.toFixed(2)}` : ''));
  const ok = d.max <= MAX && d.mean <= MEAN && (!d0 || d0.mean > 5);
  if (!ok) fs.writeFileSync(path.join(outDir, `${label.replace(/\W+/g, '_')}.png`), png);
  check(ok, `${label}: against frame ${n} max ${d.max} mean ${d.mean.toFixed(3)}` +
            (d0 ? `, against frame 0 mean ${d0.mean.toFixed(3)}` : ''));
}

// Each case in a browser of its own, with a profile never used: the page's first load.
async function cold(name, body) {
  const browser = await Browser.launch(path.join(outDir, `profile_${name}`), W, H);
  try {
    await body(browser);
  } finally {
    browser.close();
  }
}

// A still at frame n: ready, that frame on the canvas, the video read as `source` ('blob' from a
// server without ranges, 'url' from one with them).
async function checkStill(browser, label, address, n, dir, source) {
  const title = await browser.open(address, W, H);
  if (!title.startsWith('vdfx-ready')) return check(false, `${label}: ${title}`);
  const s = await browser.evaluate('window.vdfxStats');
  check(s.source === source && s.ready.frame === n && s.ready.picture === n,
        `${label}: read as ${s.source} (wanted ${source}), ready ${JSON.stringify(s.ready)}`);
  await checkCanvas(browser, label, n, dir);
}

// Playing from frame n: the first frame drawn is n (evaluated and pictured), and playing on,
// every frame drawn is evaluated at the frame its picture is.
async function checkPlaying(browser, label, address, n) {
  const title = await browser.open(address, W, H);
  if (!title.startsWith('vdfx-ready')) return check(false, `${label}: ${title}`);
  const ready = await browser.evaluate('window.vdfxStats.ready');
  const first = await browser.evaluate('window.vdfxStats.frames[0]');
  check(ready.frame === n && ready.picture === n && first[0] === n && first[1] === n,
        `${label}: ready ${JSON.stringify(ready)}, first drawn ${JSON.stringify(first)}, ` +
        `wanted frame ${n}`);
  let frames = [];
  for (let t0 = Date.now(); Date.now() - t0 < 5000;) {
    frames = await browser.evaluate('window.vdfxStats.frames');
    if (frames.some(([f]) => f !== n)) break;
    await new Promise((r) => setTimeout(r, 100));
  }
  const moved = frames.filter(([f]) => f !== n);
  console.log(`${label.padEnd(44)} frame ${n} first, then ${moved.slice(0, 6).map(([f]) => f).join(' ')}`);
  check(moved.length > 0, `${label}: the video did not move on`);
  check(frames.every(([f, p]) => p === null || f === p),
        `${label}: frames drawn at another frame than their picture's: ${JSON.stringify(frames)}`);
}

// `plain` serves as python3 -m http.server does (no ranges: the case a cold load got wrong),
// `ranged` with byte ranges; each case in a browser never used before.
async function checkMoments(plain, ranged, site) {
  const dir = path.join(outDir, site);
  for (const [query, n] of [['frame=3', 3], ['t=0.5', 12], ['frame=21', 21]])
    await cold(`still_${n}`, async (browser) => {
      const address = url(plain, site, `${query}&paused=1`);
      await checkStill(browser, `cold ${query}&paused=1`, address, n, dir, 'blob');
      // The same address again: warm (the file may now come from the browser's cache).
      if (n === 3) await checkStill(browser, `warm ${query}&paused=1`, address, n, dir, 'blob');
    });
  await cold('ranged_still', (browser) =>
    checkStill(browser, 'cold frame=5&paused=1, ranges', url(ranged, site, 'frame=5&paused=1'), 5,
               dir, 'url'));
  await cold('play_9', (browser) =>
    checkPlaying(browser, 'cold frame=9 playing', url(plain, site, 'frame=9'), 9));
  await cold('play_18', (browser) =>
    checkPlaying(browser, 'cold t=0.75 playing, ranges', url(ranged, site, 't=0.75'), 18));
}

// The video and the sidecar under names no URL holds as they are: `vdfx publish` names them
// video.mp4 and sidecar.vdfx.json; a folder whose player.json names such files plays too.
async function checkNames(browser, plain, ranged) {
  const odd = path.join(outDir, 'names');
  fs.mkdirSync(odd);
  const video = '-take#2 50%? \u00e9t\u00e9.mp4', sidecar = '-s #1 100%?.vdfx.json';
  fs.copyFileSync(path.join(outDir, 'clip.mp4'), path.join(odd, video));
  fs.copyFileSync(path.join(outDir, 'clip.vdfx.json'), path.join(odd, sidecar));
  run(['publish', '--sidecar', sidecar, '--out', '../named', '--', video], { cwd: odd });
  const named = path.join(outDir, 'named');
  const m = JSON.parse(fs.readFileSync(path.join(named, 'player.json')));
  check(m.video.file === 'video.mp4' && m.video.name === video && m.title === video &&
        m.sidecar === 'sidecar.vdfx.json' && m.sidecar_name === sidecar,
        `published names: ${JSON.stringify({ video: m.video, sidecar: m.sidecar, title: m.title })}`);
  let title = await browser.open(url(plain, 'named', 'frame=5&paused=1'), W, H);
  if (title.startsWith('vdfx-ready')) await checkCanvas(browser, 'published from odd names', 5, named);
  else check(false, `published from odd names: ${title}`);

  // player.json naming such files (as a folder edited by hand would): every URL encoded (the
  // video's too: from a server with ranges the element fetches it by its URL).
  const edited = path.join(outDir, 'edited');
  fs.cpSync(named, edited, { recursive: true });
  fs.renameSync(path.join(edited, 'video.mp4'), path.join(edited, video));
  fs.renameSync(path.join(edited, 'sidecar.vdfx.json'), path.join(edited, sidecar));
  fs.writeFileSync(path.join(edited, 'player.json'),
                   JSON.stringify({ ...m, video: { ...m.video, file: video }, sidecar }, null, 2));
  title = await browser.open(url(ranged, 'edited', 'frame=5&paused=1'), W, H);
  if (title.startsWith('vdfx-ready')) await checkCanvas(browser, 'player.json naming odd files', 5, named);
  else check(false, `player.json naming odd files: ${title}`);
}

// Errors: a file missing from the folder is a fetch failure (404), not a codec; a moment past the
// end, or given twice, names the URL's parameter.
async function checkErrors(browser, port, site) {
  const missing = (name, file) => {
    fs.cpSync(path.join(outDir, site), path.join(outDir, name), { recursive: true });
    fs.rmSync(path.join(outDir, name, file));
  };
  missing('no_video', 'video.mp4');
  let t = await browser.open(url(port, 'no_video', 'paused=1'), W, H);
  check(t.startsWith('vdfx-error: the video video.mp4 (clip.mp4) could not be fetched (HTTP 404') &&
        !t.includes('--transcode') && !t.includes('codec'), `a missing video: ${t}`);
  missing('no_sidecar', 'sidecar.vdfx.json');
  t = await browser.open(url(port, 'no_sidecar', 'paused=1'), W, H);
  check(t.startsWith('vdfx-error: sidecar.vdfx.json could not be fetched (HTTP 404'),
        `a missing sidecar: ${t}`);
  const cases = [['t=1.0&paused=1', "the URL's t=1 is past the video's end (24 frames at 24 fps"],
                 ['frame=24', "the URL's frame=24 is past the video's end"],
                 ['frame=2&t=0.1', 'the URL gives both t= and frame=']];
  for (const [query, text] of cases) {
    t = await browser.open(url(port, site, query), W, H);
    check(t.startsWith(`vdfx-error: ${text}`), `${query}: ${t}`);
  }
}

runTest('publish.page_links', async () => {
  const t0 = Date.now();
  writeClip(path.join(outDir, 'clip.mp4'));
  writeSidecar(path.join(outDir, 'clip.vdfx.json'));
  run(['publish', path.join(outDir, 'clip.mp4'), '--sidecar', path.join(outDir, 'clip.vdfx.json'),
       '--out', path.join(outDir, 'site')]);
  const plain = await serve(outDir, { ranges: false }), ranged = await serve(outDir);
  try {
    await checkMoments(plain.address().port, ranged.address().port, 'site');
    await cold('names', async (browser) => {
      await checkNames(browser, plain.address().port, ranged.address().port);
      await checkErrors(browser, ranged.address().port, 'site');
    });
  } finally {
    plain.close();
    ranged.close();
  }
  console.log(`${((Date.now() - t0) / 1000).toFixed(1)} s`);
});
