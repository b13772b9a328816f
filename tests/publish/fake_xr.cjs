// A fake XRSystem for the page tests (page_test.cjs, page_stereo_test.cjs): Debian's headless
// Chromium has navigator.xr but offers no immersive-vr session and no WebXR test API
// (docs/publish.md), so the tests inject this before the page's scripts
// (Page.addScriptToEvaluateOnNewDocument) and hand the page views with known poses.
'use strict';

// A fake XRSystem, injected before the page's scripts: immersive-vr offered, a session whose
// three animation frames hand the page a viewer pose and two views with known orientations and
// projections; the layer draws into the canvas, the left eye in its left half, the right eye in
// its right half.
function fakeXr(config) {
  return `(() => {
    const cfg = ${JSON.stringify(config)};
    const pose = { transform: { orientation: cfg.head }, views: cfg.views.map((v) => ({
      eye: v.eye, transform: { orientation: v.q }, projectionMatrix: new Float32Array(v.P) })) };
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

// A symmetric perspective (column-major) with this horizontal FOV for a w x h viewport.
function projection(fovDeg, w, h) {
  const tx = Math.tan((fovDeg * Math.PI) / 360), ty = (tx * h) / w;
  const P = new Array(16).fill(0);
  P[0] = 1 / tx;
  P[5] = 1 / ty;
  P[10] = -1.0002;
  P[11] = -1;
  P[14] = -0.020002;
  return P;
}

module.exports = { fakeXr, viewQuaternion, projection };
