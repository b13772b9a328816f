// The player page of `vdfx publish` (docs/publish.md): the video on the sphere, the effects'
// parameters evaluated each frame at the view direction by vdfx's own interpolation compiled
// to WebAssembly (vdfx_player.wasm), drawn by the GL compositor's GLSL (renderer.js).
//
// URL query (docs/publish.md): t=SECONDS or frame=N (where to start, as a link to a moment says
// it), view=AZ,ALT, fov=DEG, paused=1 (hold that frame: a still), eye=left|right (the eye a
// stereo video shows on the canvas; key 5 switches). Test hooks: size=WxH (the canvas exactly
// W x H CSS pixels at device pixel ratio 1, nothing drawn over it), xr=1 (that frame in an
// immersive session entered at once, for a test's injected XRSystem), stabilize=1 (the world
// frame: the sidecar's camera motion undone, stabilize.js). Once the starting frame is
// decoded, uploaded and drawn, window.vdfxStats.ready holds it, and with paused=1, size= or
// xr=1 document.title becomes "vdfx-ready"; any error sets "vdfx-error: MESSAGE".
import { Renderer, viewRotation } from './renderer.js';
import { effectLayers } from './layers.js';
import { attachControls } from './controls.js';
import { enterVr, lookDirection, startXr } from './xr.js';
import { cameraStabilizer } from './stabilize.js';

const $ = (id) => document.getElementById(id);
// How long the page waits for a seeked frame's picture before it says so.
const kFrameWaitMs = 10000;

function fail(message) {
  const box = $('message');
  box.textContent = message;
  box.style.display = 'block';
  document.title = `vdfx-error: ${message}`;
  console.error(message);
}

// The query's hooks, each checked (a malformed one is an error on the page, not ignored).
export function parseHooks(search) {
  const q = new URLSearchParams(search);
  const numbers = (name, n) => {
    const text = q.get(name);
    if (text === null) return null;
    const parts = text.split(name === 'size' ? 'x' : ',').map(Number);
    if (parts.length !== n || parts.some((x) => !Number.isFinite(x)))
      throw new Error(`the URL's ${name}=${text} is not ${name === 'size' ? 'WxH' : `${n} numbers`}`);
    return parts;
  };
  const view = numbers('view', 2), fov = numbers('fov', 1), frame = numbers('frame', 1);
  const size = numbers('size', 2), t = numbers('t', 1);
  if (size && !(size[0] >= 1 && size[1] >= 1 && size.every(Number.isInteger)))
    throw new Error(`the URL's size=${q.get('size')} must be whole pixels`);
  if (frame && !(Number.isInteger(frame[0]) && frame[0] >= 0))
    throw new Error(`the URL's frame=${q.get('frame')} must be a frame index`);
  if (t && !(t[0] >= 0)) throw new Error(`the URL's t=${q.get('t')} must be seconds, 0 or more`);
  if (t && frame) throw new Error('the URL gives both t= and frame=: give one');
  if (fov && !(fov[0] >= 1 && fov[0] <= 179)) throw new Error('the URL\'s fov= must be in 1..179');
  const eye = q.get('eye');
  if (eye !== null && eye !== 'left' && eye !== 'right')
    throw new Error(`the URL's eye=${eye} is not left or right`);
  const paused = q.get('paused') === '1', xr = q.get('xr') === '1';
  const stabilize = q.get('stabilize') === '1';
  return {
    eye: eye ?? 'left', stabilize,
    view: view ? { az: view[0], alt: view[1] } : null, fov: fov ? fov[0] : null,
    frame: frame ? frame[0] : null, seconds: t ? t[0] : null, size, paused, xr,
    // A headless test's page: its title says when the frame is on the screen.
    announce: paused || xr || size !== null,
  };
}

// The frame the hooks start at (t= is seconds: the frame on screen at that time), checked
// against the video's length.
export function startFrame(hooks, fps, frames) {
  const n = hooks.seconds !== null ? Math.floor(hooks.seconds * fps + 1e-6) : hooks.frame ?? 0;
  if (n >= frames) {
    const what = hooks.seconds !== null ? `t=${hooks.seconds}` : `frame=${hooks.frame}`;
    throw new Error(`the URL's ${what} is past the video's end (${frames} frames at ${fps} fps: ` +
                    `the last is frame ${frames - 1}, at ${((frames - 1) / fps).toFixed(3)} s)`);
  }
  return n;
}

// A file of the folder as a URL relative to the page: every path segment percent-encoded, so
// that a name holding '#', '?', '%', spaces or non-ASCII letters reaches the server as it is.
export function assetUrl(name) {
  return name.split('/').map(encodeURIComponent).join('/');
}

// Why a file of the folder cannot be fetched ("HTTP 404 Not Found", "network error: ..."), or
// null when it can (a one-byte range: nothing more is downloaded).
async function fetchProblem(name) {
  try {
    const r = await fetch(assetUrl(name), { headers: { Range: 'bytes=0-0' }, cache: 'no-store' });
    r.body?.cancel().catch(() => {});
    return r.ok ? null : `HTTP ${r.status} ${r.statusText}`.trim();
  } catch (e) {
    return `network error: ${e.message}`;
  }
}

async function fetchText(name) {
  let r;
  try {
    r = await fetch(assetUrl(name));
  } catch (e) {
    throw new Error(`${name} could not be fetched (network error: ${e.message})`);
  }
  if (!r.ok) throw new Error(`${name} could not be fetched (HTTP ${r.status} ${r.statusText})`);
  return r.text();
}

// The module with its calls (app/publish/wasm/player_api.cpp).
async function loadModule() {
  if (typeof createVdfxPlayer !== 'function') throw new Error('vdfx_player.js did not load');
  const m = await createVdfxPlayer(); // eslint-disable-line no-undef
  const out = m._malloc(9 * 8);
  const loadText = m.cwrap('vdfx_load', 'number', ['string', 'number']);
  return {
    raw: m, // for layers.js's calls
    // The sidecar's text goes on the module's heap: as a 'string' argument it would be copied
    // onto its stack (5 MB), which a film's keyframes overflow.
    load(name, text) {
      const p = m.allocateUTF8(text);
      try {
        return loadText(name, p);
      } finally {
        m._free(p);
      }
    },
    message: m.cwrap('vdfx_message', 'string', []),
    evalRaw: m.cwrap('vdfx_eval', 'number', ['number', 'number', 'number', 'number']),
    // The 9 stack parameters at a view and frame; null for a frame outside the video.
    eval(az, alt, frame) {
      if (this.evalRaw(az, alt, frame, out) < 0) return null;
      return new Float64Array(m.HEAPF64.buffer, out, 9).slice();
    },
  };
}

async function loadShaders() {
  const names = { vert: 'fullscreen.vert', video: 'video.frag', mip: 'mip_level.frag',
                  blur: 'blur_1d.frag',
                  stack: 'stack.frag', stackBlur: 'stack_blur.frag', flareVert: 'flare.vert',
                  flareFrag: 'flare.frag', grainFrag: 'grain.frag' };
  const out = {};
  for (const [key, file] of Object.entries(names)) out[key] = await fetchText(`shaders/${file}`);
  return out;
}

// Where the <video> reads the file from: its URL when the server answers range requests (the
// element then fetches what it plays, and seeks by asking for other ranges), else the whole file
// as a Blob. A server that sends whole files only (python3 -m http.server) leaves the element
// unable to seek (its seekable range stays [0, 0], whatever it has buffered): every seek lands on
// frame 0, and a link to a moment opened on the wrong frame until a reload found the file in the
// browser's cache. The one-byte range request tells them apart; from a server without ranges its
// answer is the whole file, kept as the Blob (nothing is downloaded twice).
async function videoSource(file, shown) {
  let r;
  try {
    r = await fetch(assetUrl(file), { headers: { Range: 'bytes=0-0' }, cache: 'no-store' });
  } catch (e) {
    throw new Error(`the video ${shown} could not be fetched (network error: ${e.message})`);
  }
  if (!r.ok)
    throw new Error(`the video ${shown} could not be fetched (HTTP ${r.status} ${r.statusText}): ` +
                    'the folder is incomplete, or the server does not serve it');
  if (r.status === 206) {
    r.body?.cancel().catch(() => {});
    return { src: assetUrl(file), kind: 'url' };
  }
  return { src: URL.createObjectURL(await r.blob()), kind: 'blob' };
}

// Resolves once the <video> can show a frame. Rejects telling apart a file the browser could not
// fetch (a 404, the network: publishing again with --transcode cannot help) from one it fetched
// but cannot decode (naming the codec and --transcode). Returns where it reads from ('url' or
// 'blob', above).
async function openVideo(video, config) {
  const { file, codec } = config.video;
  const name = config.video.name;
  const shown = name && name !== file ? `${file} (${name})` : file;
  const source = await videoSource(file, shown);
  await new Promise((resolve, reject) => {
    video.addEventListener('loadeddata', () => resolve(), { once: true });
    video.addEventListener('error', async () => {
      const e = video.error;
      const detail = e ? `, ${e.message || `media error ${e.code}`}` : '';
      const problem = source.kind === 'url' ? await fetchProblem(file) : null;
      if (problem)
        reject(new Error(`the video ${shown} could not be fetched (${problem}): the folder is ` +
                         'incomplete, or the server does not serve it'));
      else
        reject(new Error(`this browser cannot play ${shown} (codec ${codec}${detail}); ` +
                         'publish it again with --transcode h264 (or vp9)'));
    }, { once: true });
    video.src = source.src;
    video.load();
  });
  return source.kind;
}

// Seeks to frame n: resolves once the element has seeked there (Player.showFrame then checks
// which frame its picture is); rejects when the element could not seek there.
async function seekTo(video, n, fps) {
  const t = (n + 0.5) / fps;
  if (Math.abs(video.currentTime - t) > 1e-6 || video.seeking)
    await new Promise((resolve) => {
      video.addEventListener('seeked', resolve, { once: true });
      video.currentTime = t;
    });
  if (Math.abs(video.currentTime - t) > 0.25 / fps)
    throw new Error(`cannot seek to frame ${n}: the video stays at ${video.currentTime.toFixed(3)} s`);
}

const nextAnimationFrame = () => new Promise((r) => requestAnimationFrame(r));

// A VideoFrame's Y', Cb, Cr planes ({ data, stride }, rows top first): I420 as it comes, NV12's
// interleaved chroma split in two; null for any other layout.
async function decodedPlanes(frame) {
  if (frame.format !== 'I420' && frame.format !== 'NV12') return null;
  const bytes = new Uint8Array(frame.allocationSize());
  const layout = await frame.copyTo(bytes);
  const plane = (i) => ({ data: bytes.subarray(layout[i].offset), stride: layout[i].stride });
  if (frame.format === 'I420') return [plane(0), plane(1), plane(2)];
  const cw = Math.ceil(frame.visibleRect.width / 2), ch = Math.ceil(frame.visibleRect.height / 2);
  const cb = new Uint8Array(cw * ch), cr = new Uint8Array(cw * ch);
  const { offset, stride } = layout[1];
  for (let y = 0; y < ch; ++y)
    for (let x = 0, src = offset + y * stride, dst = y * cw; x < cw; ++x, src += 2, ++dst) {
      cb[dst] = bytes[src];
      cr[dst] = bytes[src + 1];
    }
  return [plane(0), { data: cb, stride: cw }, { data: cr, stride: cw }];
}

class Player {
  constructor(config, module, renderer, hooks) {
    Object.assign(this, { config, module, renderer, hooks });
    this.canvas = $('view');
    this.video = document.createElement('video');
    this.video.muted = true;
    this.video.playsInline = true;
    this.video.loop = true;
    this.view = { az: hooks.view?.az ?? 0, alt: hooks.view?.alt ?? 0, fov: hooks.fov ?? 90 };
    // The frame the effects are evaluated at, and the frame the uploaded picture is (from the
    // decoded frame's timestamp; null where the browser does not say): the same once shown.
    this.frame = 0;
    this.pictureFrame = null;
    // The eye a stereo video shows on the canvas (a headset draws each eye its own).
    this.eye = hooks.eye;
    renderer.setLayout(config.video);
    // frames: [evaluated frame, picture's frame] of each draw; ready: the same for the frame
    // the page started at, once it is on the screen.
    this.stats = { evalMs: [], drawMs: [], uploadMs: [], frames: [], conversion: null,
                   view: this.view, eye: this.eye, ready: null };
    window.vdfxStats = this.stats;
  }

  fps() { return this.config.video.fps; }

  stereo() { return (this.config.video.layout ?? 'mono') !== 'mono'; }

  // Key 5 and the bar's eye button: the other eye on the canvas (stereo video only).
  switchEye() {
    if (!this.stereo()) return;
    this.eye = this.eye === 'left' ? 'right' : 'left';
    this.stats.eye = this.eye;
    this.dirty = true;
    $('eye').textContent = `${this.eye === 'left' ? 'Left' : 'Right'} eye`;
  }

  // Canvas size in device pixels (exactly the hook's W x H at device pixel ratio 1).
  resize() {
    const dpr = this.hooks.size ? 1 : window.devicePixelRatio || 1;
    const w = this.hooks.size ? this.hooks.size[0] : Math.round(this.canvas.clientWidth * dpr);
    const h = this.hooks.size ? this.hooks.size[1] : Math.round(this.canvas.clientHeight * dpr);
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
  }

  // A view's eye -> world rotation as the video frame shows it: stabilize=1 turns it by the
  // camera's q_f^-1 at the current frame; otherwise it is the video frame already.
  turn(rot) {
    return this.stabilizer ? this.stabilizer.turn(rot, this.frame) : rot;
  }

  // The effects at a view and frame: the view's rotation and the module's parameters (null
  // where it has none), the flares' and grain's layout from the head's pose at the origin.
  evaluate(view, frame) {
    const rot = this.turn(viewRotation(view.az, view.alt));
    const at = lookDirection(rot);
    const p = this.module.eval(at.az, at.alt, frame);
    this.renderer.layers?.update(rot, [0, 0, 0], frame);
    return { rot, p };
  }

  // Chromium first runs WebAssembly and JavaScript from a quick baseline compile and optimises
  // what runs often: at 8 effects x 10000 keyframes the first frames' evaluations took 1.5 to
  // 2.1 ms, warm ones under 0.1 ms. Evaluations at spread views and frames before the first
  // frame (at most 0.4 s of them) make the path hot before anything is drawn.
  warmUp() {
    const t0 = performance.now(), n = this.config.video.frames;
    for (let i = 0; i < 256 && performance.now() - t0 < 400; ++i)
      this.evaluate({ az: -179 + (i * 137.5) % 359, alt: -80 + (i * 61.8) % 160 },
                    Math.floor((i * n) / 256));
  }

  // Evaluates the effects at the view and draws the current video frame.
  draw() {
    this.resize();
    const t0 = performance.now();
    const { rot, p } = this.evaluate(this.view, this.frame);
    const t1 = performance.now();
    if (!p) return;
    this.renderer.draw({ ...this.view, rot, eye: this.eye }, this.canvas.width,
                       this.canvas.height, p);
    const t2 = performance.now();
    this.#record(this.stats.evalMs, t1 - t0);
    this.#record(this.stats.drawMs, t2 - t1);
    this.#record(this.stats.frames, [this.frame, this.pictureFrame]);
  }

  // The video's current picture into the renderer; returns the index of the frame it is (the
  // decoded frame's timestamp), or null where the browser does not say (no WebCodecs). An 8-bit
  // 4:2:0 frame goes in as its decoded planes (WebCodecs), converted to R'G'B' by the shared
  // shader with the stream's own matrix, range and chroma siting (player.json, from io/ycbcr.h),
  // as vdfx converts it; otherwise (no WebCodecs, another layout) the browser's own conversion
  // (texImage2D of the <video>).
  async uploadFrame() {
    const t0 = performance.now();
    const index = await this.#upload();
    this.#record(this.stats.uploadMs, performance.now() - t0);
    return index;
  }

  async #upload() {
    let frame = null;
    try {
      if (typeof VideoFrame === 'function') frame = new VideoFrame(this.video);
    } catch (e) {
      console.warn(`the decoded frame is not available (${e.message}); the browser converts`);
    }
    try {
      // Frame k starts at k / fps; the timestamp is in microseconds, rounded.
      const index = frame ? Math.floor(frame.timestamp * 1e-6 * this.fps() + 1e-3) : null;
      const info = this.config.video.ycbcr;
      if (frame && info && info.bit_depth === 8) {
        const planes = await decodedPlanes(frame).catch((e) => {
          console.warn(`decoded planes not available (${e.message}); the browser converts`);
          return null;
        });
        const r = frame.visibleRect;
        if (planes && this.renderer.uploadPlanes(planes, r.width, r.height, info)) {
          this.stats.conversion = 'vdfx';
          return index;
        }
      }
      this.renderer.upload(this.video);
      this.stats.conversion = 'browser';
      return index;
    } finally {
      if (frame) frame.close();
    }
  }

  // Seeks to frame n and puts that frame's picture into the renderer. 'seeked' can come before
  // the element holds the new picture (on a cold load it does: the picture was still frame 0),
  // so the decoded frame's own timestamp is checked and the upload repeated each animation frame
  // until it is frame n. Without WebCodecs (no timestamp) it waits for the element's next frame.
  async showFrame(n) {
    await seekTo(this.video, n, this.fps());
    const t0 = performance.now();
    let got = await this.uploadFrame();
    if (got === null) {
      await this.#videoFrameSettled();
      got = await this.uploadFrame();
    }
    while (got !== null && got !== n) {
      if (performance.now() - t0 > kFrameWaitMs)
        throw new Error(`frame ${n} did not arrive: the browser still shows frame ${got} ` +
                        `${kFrameWaitMs / 1000} s after seeking to it`);
      await nextAnimationFrame();
      got = await this.uploadFrame();
    }
    this.frame = n;
    this.pictureFrame = got;
    this.shownTime = this.video.currentTime;
  }

  // The element's next frame (requestVideoFrameCallback, where it fires), else half a second.
  #videoFrameSettled() {
    return new Promise((resolve) => {
      this.video.requestVideoFrameCallback?.(() => resolve());
      setTimeout(resolve, 500);
    });
  }

  // The starting frame is on the screen: said in the stats, and (a test's still) the title.
  async #ready() {
    // After the frame reached the screen (two animation frames: the next one composites it).
    await nextAnimationFrame();
    await nextAnimationFrame();
    this.stats.ready = { frame: this.frame, picture: this.pictureFrame };
    if (this.hooks.announce) document.title = 'vdfx-ready';
  }

  #record(list, ms) {
    list.push(ms);
    if (list.length > 240) list.shift();
  }

  // A new frame of the playing (or seeked) video: uploaded, then drawn at the frame the picture
  // is (its timestamp; the element's time where the browser gives none). Polled once per
  // animation frame: requestVideoFrameCallback does not fire for a <video> that is not on the
  // page (this one is only a texture source).
  // After a seek (the bar, the keys) the picture can come an animation frame or two after the
  // element's time moved: while it is not yet the frame at that time, it is looked at again (a
  // few dozen times at most, so a stream whose timestamps do not start at 0 costs nothing).
  #pollFrame() {
    const t = this.video.currentTime;
    if (this.uploading || t === this.shownTime) return;
    if (t !== this.polledTime) this.retries = 0;
    this.polledTime = t;
    this.uploading = true;
    this.shownTime = t;
    this.uploadFrame().then((got) => {
      const last = this.config.video.frames - 1;
      const at = Math.min(last, Math.floor(t * this.fps() + 1e-6));
      this.frame = Math.min(last, got ?? at);
      this.pictureFrame = got;
      if (got !== null && got !== at && this.retries++ < 30) this.shownTime = null;
      this.uploading = false;
      this.dirty = true;
    });
  }

  // The xr=1 hook: frame n in an immersive session entered at once (no button press: a test's
  // injected XRSystem asks for none), ready after its first XR frame is drawn.
  async xrStill(button, n) {
    if (!button) throw new Error('xr=1: this browser offers no immersive-vr session');
    this.resize();
    await this.showFrame(n);
    const drawn = new Promise((resolve) => { this.onXrFrame = resolve; });
    await enterVr(this, button);
    await drawn;
    this.onXrFrame = null;
    await this.#ready();
  }

  // paused=1: frame n, held.
  async stillFrame(n) {
    await this.showFrame(n);
    this.draw();
    await this.#ready();
  }

  // Plays from frame n, muted (browsers allow that without a gesture; the bar's Sound button
  // unmutes), drawing whenever a new frame arrives or the view changes. Frame n is drawn (and
  // ready) before the video moves on.
  async run(n) {
    await this.showFrame(n);
    this.draw();
    await this.#ready();
    this.video.play().catch(() => {});
    const loop = () => {
      this.#pollFrame();
      if (this.dirty && !this.xrSession) {
        this.dirty = false;
        this.draw();
      }
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }
}

async function start() {
  const hooks = parseHooks(window.location.search);
  if (hooks.size) {
    document.body.classList.add('still');
    const c = $('view');
    c.style.width = `${hooks.size[0]}px`;
    c.style.height = `${hooks.size[1]}px`;
  }
  const config = JSON.parse(await fetchText('player.json'));
  const first = startFrame(hooks, config.video.fps, config.video.frames);
  const module = await loadModule();
  // A sidecar that fails validation: the validator's own lines (vdfx validate's), nothing played.
  const sidecarText = await fetchText(config.sidecar);
  if (!module.load(config.sidecar, sidecarText))
    throw new Error(module.message().replace(/\n+$/, ''));
  const gl = $('view').getContext('webgl2', { antialias: false, alpha: false });
  if (!gl) throw new Error('this browser has no WebGL2');
  const shaders = await loadShaders();
  const renderer = new Renderer(gl, shaders);
  renderer.layers = await effectLayers(gl, shaders, module, config, fetchText);
  const player = new Player(config, module, renderer, hooks);
  if (hooks.stabilize) player.stabilizer = cameraStabilizer(sidecarText, config.sidecar_name ?? config.sidecar);
  window.vdfxPlayer = player; // for benchmarks and debugging (docs/publish.md)
  player.warmUp();
  player.stats.source = await openVideo(player.video, config);
  if (config.left_out.length)
    $('left-out').textContent = `not drawn here: ${config.left_out.join(', ')}`;
  if (hooks.xr) {
    await player.xrStill(await startXr(player, fail), first);
    return;
  }
  if (hooks.paused) {
    await player.stillFrame(first);
    return;
  }
  attachControls(player);
  await startXr(player, fail);
  await player.run(first);
}

start().catch((e) => fail(e && e.message ? e.message : String(e)));
