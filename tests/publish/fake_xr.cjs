// A fake WebXR system for the page tests (headless Chromium answers isSessionSupported
// ('immersive-vr') with false and has no WebXR test API; docs/publish.md, "WebXR"): a script
// injected before the page's scripts (DevTools' Page.addScriptToEvaluateOnNewDocument) that offers
// immersive-vr and hands the page, for three animation frames, a viewer pose and two views with
// known orientations, positions and projections. The layer draws into the canvas, the left eye
// in its left half, the right eye in its right half.
'use strict';

// config: { head: quaternion, headPos?: [x, y, z], views: [{ eye, q, pos?, P }] } (P column-major).
function fakeXr(config) {
  return `(() => {
    const cfg = ${JSON.stringify(config)};
    const at = (p) => (p ? { x: p[0], y: p[1], z: p[2], w: 1 } : undefined);
    const pose = { transform: { orientation: cfg.head, position: at(cfg.headPos) },
      views: cfg.views.map((v) => ({ eye: v.eye, projectionMatrix: new Float32Array(v.P),
        transform: { orientation: v.q, position: at(v.pos) } })) };
    const frame = { getViewerPose: () => pose };
    window.XRWebGLLayer = class {
      constructor(session, gl) { this.gl = gl; this.framebuffer = null; }
      getViewport(view) {
        const c = this.gl.canvas, w = c.width / 2;
        return { x: view.eye === 'left' ? 0 : w, y: 0, width: w, height: c.height };
      }
    };
    WebGL2RenderingContext.prototype.makeXRCompatible = () => Promise.resolve();
    let frames = 0;
    const session = {
      renderState: {},
      updateRenderState(s) { this.renderState = { ...this.renderState, ...s }; },
      requestReferenceSpace: async () => ({}),
      requestAnimationFrame(cb) {
        if (frames++ < 3) setTimeout(() => cb(performance.now(), frame), 16);
        return frames;
      },
      addEventListener() {},
      end() {},
    };
    Object.defineProperty(navigator, 'xr', { configurable: true, value: {
      isSessionSupported: async (mode) => mode === 'immersive-vr',
      requestSession: async () => session } });
  })();`;
}

// Quaternion {x, y, z, w} of a view at (azimuth, altitude): yaw -azimuth about y, then pitch.
function viewQuaternion(az, alt) {
  const a = (-az * Math.PI) / 360, b = (alt * Math.PI) / 360;
  // (0, sin a, 0, cos a) * (sin b, 0, 0, cos b)
  return { x: Math.cos(a) * Math.sin(b), y: Math.sin(a) * Math.cos(b),
           z: -Math.sin(a) * Math.sin(b), w: Math.cos(a) * Math.cos(b) };
}

// A perspective (column-major, near 0.01, far 100) with the tangent rectangle left, right, down,
// up: P[8] and P[9] carry an asymmetric frustum's offsets.
function projectionOf([l, r, d, u]) {
  const P = new Array(16).fill(0);
  P[0] = 2 / (r - l);
  P[5] = 2 / (u - d);
  P[8] = (r + l) / (r - l);
  P[9] = (u + d) / (u - d);
  P[10] = -1.0002;
  P[11] = -1;
  P[14] = -0.020002;
  return P;
}

// The left or right half of a decoded screenshot ({ width, height, rgb }).
function half(shot, i) {
  const w = shot.width / 2, H = shot.height;
  const out = { width: w, height: H, rgb: Buffer.alloc(w * H * 3) };
  for (let y = 0; y < H; ++y)
    shot.rgb.copy(out.rgb, y * w * 3, (y * shot.width + i * w) * 3, (y * shot.width + i * w + w) * 3);
  return out;
}

// A symmetric perspective (column-major) with this horizontal FOV for a w x h viewport.
function projection(fovDeg, w, h) {
  const tx = Math.tan((fovDeg * Math.PI) / 360), ty = (tx * h) / w;
  return projectionOf([-tx, tx, -ty, ty]);
}

module.exports = { fakeXr, viewQuaternion, projectionOf, projection, half };
