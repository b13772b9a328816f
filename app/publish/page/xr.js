// WebXR (immersive-vr) for the player page: "Enter VR" where the browser offers it (https or
// localhost). Each frame: the effects' parameters once, at the head's view direction (the
// contract: the same for both eyes); then each XRView drawn with its own rotation and its own
// projection (tangents read from its projection matrix), the vignette centred on that eye's
// optical axis, and a stereo video's image of that eye (XRView.eye; 'none', a mono display,
// shows the left), as vdfx's compositor draws each eye.
const DEG = 180 / Math.PI;

// Row-major rotation of a unit quaternion {x, y, z, w} (WebXR's DOMPointReadOnly).
export function quaternionRotation(q) {
  const { x, y, z, w } = q;
  return [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
          2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
          2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)];
}

// The direction a rotation looks along (its -z), as the contract's azimuth and altitude.
export function lookDirection(rot) {
  const f = [-rot[2], -rot[5], -rot[8]];
  return { az: Math.atan2(f[0], -f[2]) * DEG,
           alt: Math.asin(Math.max(-1, Math.min(1, f[1]))) * DEG };
}

// The tangent rectangle (left, right, down, up) of a perspective projection matrix
// (column-major 16 values, as XRView.projectionMatrix): for the frustum at near plane n,
// P[0] = 2n / (r - l), P[8] = (r + l) / (r - l), likewise P[5] and P[9] vertically.
export function projectionTangents(P) {
  return [(P[8] - 1) / P[0], (P[8] + 1) / P[0], (P[9] - 1) / P[5], (P[9] + 1) / P[5]];
}

// An XRRigidTransform's position as [x, y, z] (metres).
const position = (t) => (t.position ? [t.position.x, t.position.y, t.position.z] : [0, 0, 0]);

// One XR frame: the parameters from the head, every view with its own rotation and projection.
function drawXrFrame(player, layer, pose) {
  // stabilize=1: each pose as the video frame sees it (Player.turn).
  const headRot = player.turn(quaternionRotation(pose.transform.orientation));
  const head = lookDirection(headRot);
  const t0 = performance.now();
  const p = player.module.eval(head.az, head.alt, player.frame);
  // Flares and grain laid out once from the head's pose; each eye draws them from its own.
  player.renderer.layers?.update(headRot, position(pose.transform), player.frame);
  player.stats.xr = { head, params: p ? Array.from(p) : null, views: [] };
  if (!p) return;
  for (const view of pose.views) {
    const vp = layer.getViewport(view);
    const eye = { rot: player.turn(quaternionRotation(view.transform.orientation)),
                  tan: projectionTangents(view.projectionMatrix), pos: position(view.transform),
                  eye: view.eye === 'right' ? 'right' : 'left' };
    player.renderer.draw(eye, vp.width, vp.height, p, { fb: layer.framebuffer, x: vp.x, y: vp.y });
    player.stats.xr.views.push({ eye: view.eye, viewport: [vp.x, vp.y, vp.width, vp.height],
                                 tan: eye.tan });
  }
  player.stats.evalMs.push(performance.now() - t0);
}

export async function enterVr(player, button) {
  const gl = player.renderer.gl;
  const session = await navigator.xr.requestSession('immersive-vr');
  await gl.makeXRCompatible();
  // No multisampling: each eye is copied in with blitFramebuffer, which cannot write into a
  // multisampled framebuffer.
  const layer = new XRWebGLLayer(session, gl, { antialias: false });
  session.updateRenderState({ baseLayer: layer });
  const space = await session.requestReferenceSpace('local');
  player.xrSession = session;
  button.textContent = 'Exit VR';
  session.addEventListener('end', () => {
    player.xrSession = null;
    player.dirty = true;
    button.textContent = 'Enter VR';
  });
  const onFrame = (time, frame) => {
    session.requestAnimationFrame(onFrame);
    const pose = frame.getViewerPose(space);
    if (!pose) return;
    drawXrFrame(player, session.renderState.baseLayer, pose);
    if (player.onXrFrame) player.onXrFrame();
  };
  session.requestAnimationFrame(onFrame);
}

// Shows "Enter VR" when the browser offers immersive-vr; a failure goes to the page's error.
export async function startXr(player, fail) {
  if (!navigator.xr) return null;
  const supported = await navigator.xr.isSessionSupported('immersive-vr').catch(() => false);
  if (!supported) return null;
  const button = document.getElementById('enter-vr');
  button.hidden = false;
  button.addEventListener('click', () => {
    if (player.xrSession) player.xrSession.end();
    else enterVr(player, button).catch((e) => fail(`WebXR: ${e.message}`));
  });
  return button;
}
