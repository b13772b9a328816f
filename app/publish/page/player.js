// The player page of `vdfx publish` (docs/publish.md): the video on the sphere, the effects'
// parameters evaluated each frame at the view direction by vdfx's own interpolation compiled
// to WebAssembly (vdfx_player.wasm), drawn by the GL compositor's GLSL (renderer.js).
//
// Test hooks (URL query): view=AZ,ALT  frame=N  fov=DEG  size=WxH  paused=1. With size= the
// canvas is exactly W x H CSS pixels at device pixel ratio 1, nothing drawn over it; with
// frame= or paused=1 the page shows that one frame paused and sets document.title to
// "vdfx-ready" once it is drawn; xr=1 draws that frame in an immersive session entered at once
// (for a test's injected XRSystem); eye=left|right picks the eye a stereo video shows on the
// canvas (default left; key 5 switches). Any error sets document.title to "vdfx-error: MESSAGE".
import { Renderer, viewRotation } from './renderer.js';
import { effectLayers } from './layers.js';
import { attachControls } from './controls.js';
import { enterVr, startXr } from './xr.js';

const $ = (id) => document.getElementById(id);

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
  const size = numbers('size', 2);
  if (size && !(size[0] >= 1 && size[1] >= 1 && size.every(Number.isInteger)))
    throw new Error(`the URL's size=${q.get('size')} must be whole pixels`);
  if (frame && !(Number.isInteger(frame[0]) && frame[0] >= 0))
    throw new Error(`the URL's frame=${q.get('frame')} must be a frame index`);
  if (fov && !(fov[0] >= 1 && fov[0] <= 179)) throw new Error('the URL\'s fov= must be in 1..179');
  const eye = q.get('eye');
  if (eye !== null && eye !== 'left' && eye !== 'right')
    throw new Error(`the URL's eye=${eye} is not left or right`);
  return {
    eye: eye ?? 'left',
    view: view ? { az: view[0], alt: view[1] } : null, fov: fov ? fov[0] : null,
    frame: frame ? frame[0] : null, size, paused: q.get('paused') === '1', xr: q.get('xr') === '1',
  };
}

async function fetchText(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: ${r.status} ${r.statusText}`);
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
  const names = { vert: 'fullscreen.vert', video: 'video.frag', blur: 'blur_1d.frag',
                  stack: 'stack.frag', stackBlur: 'stack_blur.frag', flareVert: 'flare.vert',
                  flareFrag: 'flare.frag', grainFrag: 'grain.frag' };
  const out = {};
  for (const [key, file] of Object.entries(names)) out[key] = await fetchText(`shaders/${file}`);
  return out;
}

// Resolves once the <video> can show a frame; rejects, naming the codec, when it cannot decode.
function openVideo(video, config) {
  return new Promise((resolve, reject) => {
    video.addEventListener('loadeddata', () => resolve(), { once: true });
    video.addEventListener('error', () => {
      const codec = config.video.codec;
      reject(new Error(`this browser cannot play ${config.video.file} (codec ${codec}` +
        `${video.error ? `, ${video.error.message || `media error ${video.error.code}`}` : ''}); ` +
        'publish it again with --transcode h264 (or vp9)'));
    }, { once: true });
    video.src = config.video.file;
    video.load();
  });
}

// Seeks to frame n and waits until that frame can be drawn.
async function seekFrame(video, n, fps) {
  await new Promise((resolve) => {
    video.addEventListener('seeked', resolve, { once: true });
    video.currentTime = (n + 0.5) / fps;
  });
  if (video.requestVideoFrameCallback)
    await new Promise((resolve) => {
      video.requestVideoFrameCallback(resolve);
      setTimeout(resolve, 500);
    });
}

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
    this.frame = hooks.frame ?? 0;
    // The eye a stereo video shows on the canvas (a headset draws each eye its own).
    this.eye = hooks.eye;
    renderer.setLayout(config.video);
    this.stats = { evalMs: [], drawMs: [], uploadMs: [], conversion: null, view: this.view,
                   eye: this.eye };
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

  // Evaluates the effects at the view and draws the current video frame.
  draw() {
    this.resize();
    const t0 = performance.now();
    const p = this.module.eval(this.view.az, this.view.alt, this.frame);
    // The flares' and grain's layout from the head's pose: the view's, at the origin.
    this.renderer.layers?.update(viewRotation(this.view.az, this.view.alt), [0, 0, 0], this.frame);
    const t1 = performance.now();
    if (!p) return;
    this.renderer.draw({ ...this.view, eye: this.eye }, this.canvas.width, this.canvas.height, p);
    const t2 = performance.now();
    this.#record(this.stats.evalMs, t1 - t0);
    this.#record(this.stats.drawMs, t2 - t1);
  }

  // The video's current frame into the renderer. An 8-bit 4:2:0 frame goes in as its decoded
  // planes (WebCodecs), converted to R'G'B' by the shared shader with the stream's own matrix,
  // range and chroma siting (player.json, from io/ycbcr.h), as vdfx converts it; otherwise (no
  // WebCodecs, another layout) the browser's own conversion (texImage2D of the <video>).
  async uploadFrame() {
    const t0 = performance.now();
    await this.#upload();
    this.#record(this.stats.uploadMs, performance.now() - t0);
  }

  async #upload() {
    const info = this.config.video.ycbcr;
    if (info && info.bit_depth === 8 && typeof VideoFrame === 'function') {
      let frame = null;
      try {
        frame = new VideoFrame(this.video);
        const planes = await decodedPlanes(frame);
        const r = frame.visibleRect;
        if (planes && this.renderer.uploadPlanes(planes, r.width, r.height, info)) {
          this.stats.conversion = 'vdfx';
          return;
        }
      } catch (e) {
        console.warn(`decoded planes not available (${e.message}); the browser converts`);
      } finally {
        if (frame) frame.close();
      }
    }
    this.renderer.upload(this.video);
    this.stats.conversion = 'browser';
  }

  #record(list, ms) {
    list.push(ms);
    if (list.length > 240) list.shift();
  }

  // A new frame of the playing (or seeked) video: uploaded, then drawn. Polled once per
  // animation frame: requestVideoFrameCallback does not fire for a <video> that is not on the
  // page (this one is only a texture source).
  #pollFrame() {
    const t = this.video.currentTime;
    if (this.uploading || t === this.shownTime) return;
    this.uploading = true;
    this.shownTime = t;
    this.uploadFrame().then(() => {
      this.frame = Math.min(this.config.video.frames - 1, Math.floor(t * this.fps() + 1e-6));
      this.uploading = false;
      this.dirty = true;
    });
  }

  // The xr=1 hook: the still frame in an immersive session entered at once (no button press:
  // a test's injected XRSystem asks for none), "vdfx-ready" after its first XR frame is drawn.
  async xrStill(button) {
    if (!button) throw new Error('xr=1: this browser offers no immersive-vr session');
    this.resize();
    await seekFrame(this.video, this.frame, this.fps());
    await this.uploadFrame();
    const drawn = new Promise((resolve) => { this.onXrFrame = resolve; });
    await enterVr(this, button);
    await drawn;
    this.onXrFrame = null;
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    document.title = 'vdfx-ready';
  }

  async stillFrame() {
    await seekFrame(this.video, this.frame, this.fps());
    await this.uploadFrame();
    this.draw();
    // Title after the frame reached the screen (the next animation frame).
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    document.title = 'vdfx-ready';
  }

  // Plays from the first frame, muted (browsers allow that without a gesture; the bar's Sound
  // button unmutes), drawing whenever a new frame arrives or the view changes.
  async run() {
    await seekFrame(this.video, 0, this.fps());
    await this.uploadFrame();
    this.shownTime = this.video.currentTime;
    this.dirty = true;
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
  const module = await loadModule();
  // A sidecar that fails validation: the validator's own lines (vdfx validate's), nothing played.
  if (!module.load(config.sidecar, await fetchText(config.sidecar)))
    throw new Error(module.message().replace(/\n+$/, ''));
  const gl = $('view').getContext('webgl2', { antialias: false, alpha: false });
  if (!gl) throw new Error('this browser has no WebGL2');
  const shaders = await loadShaders();
  const renderer = new Renderer(gl, shaders);
  renderer.layers = await effectLayers(gl, shaders, module, config, fetchText);
  const player = new Player(config, module, renderer, hooks);
  window.vdfxPlayer = player; // for benchmarks and debugging (docs/publish.md)
  await openVideo(player.video, config);
  if (config.left_out.length)
    $('left-out').textContent = `not drawn here: ${config.left_out.join(', ')}`;
  if (hooks.xr) {
    await player.xrStill(await startXr(player, fail));
    return;
  }
  if (hooks.frame !== null || hooks.paused) {
    await player.stillFrame();
    return;
  }
  attachControls(player);
  await startXr(player, fail);
  await player.run();
}

start().catch((e) => fail(e && e.message ? e.message : String(e)));
