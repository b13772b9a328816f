// The page's stabilize=1 hook (docs/publish.md, "Stabilised"): the view shows the world frame.
// The sidecar's `camera` holds q_f, which takes a direction of the video frame at frame f into
// the world; the picture's direction w shows the video at q_f^-1 w q_f (the contract's "Frames
// of reference"). So every view's eye -> world rotation R becomes Q_f^T R before the video is
// sampled and the effects are evaluated at the video direction it looks along: the effects are
// exactly those of the unstabilised page, moved with the picture.
import { quaternionRotation } from './xr.js';

// Q^T R of two row-major 3x3 rotations.
function transposeTimes(q, r) {
  const m = new Array(9).fill(0);
  for (let i = 0; i < 3; ++i)
    for (let j = 0; j < 3; ++j)
      for (let k = 0; k < 3; ++k) m[3 * i + j] += q[3 * k + i] * r[3 * k + j];
  return m;
}

// The camera's rotation per frame from the sidecar's text; an error naming the sidecar when it
// records none.
export function cameraStabilizer(sidecarText, sidecarName) {
  const camera = JSON.parse(sidecarText).camera;
  if (!camera || !Array.isArray(camera.orientation) || camera.orientation.length === 0)
    throw new Error(`stabilize=1: ${sidecarName} has no camera motion: run vdfx track camera`);
  const turns = camera.orientation.map(([w, x, y, z]) => {
    const n = Math.hypot(w, x, y, z);
    return quaternionRotation({ w: w / n, x: x / n, y: y / n, z: z / n });
  });
  return {
    // A view's rotation (world frame) as the video frame at `frame` sees it.
    turn(rot, frame) {
      const f = Math.max(0, Math.min(turns.length - 1, frame));
      return transposeTimes(turns[f], rot);
    },
  };
}
