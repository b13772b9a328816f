// The flare layer of the page: xr/render/flare_gl.cpp's draw in WebGL2, from the same GLSL
// (shaders/flare.vert and flare.frag, effects/flare_shaders.h with the ES prelude). The layout
// (effects::FlareSet::layouts: every element's centre, plane axes, extent, colour) comes from
// the module once per frame for the head's pose; each eye draws it from its own position, rotation
// and projection (flare-grain.md, stereo rules 1 and 2).
import { program } from './renderer.js';

// The near plane: the headset style's plane sits a few centimetres from the eyes. Infinite far
// plane; no depth test (xr/render/flare_gl.cpp, kNear).
const NEAR = 1e-3;
// Values per element in the module's list (app/publish/wasm/player_api.cpp, vdfx_flare_elements).
export const ELEMENT_VALUES = 16;

// Projection (tangents left, right, down, up; near NEAR, far infinite) times the world -> eye
// rotation (the transpose of `rot`, eye -> world row-major), as xr::RenderView::projection and
// FlareGl::draw build it: column-major for uniformMatrix4fv, computed in doubles.
export function flareViewProj(rot, tan) {
  const w = tan[1] - tan[0], h = tan[3] - tan[2];
  const P = [[2 / w, 0, (tan[1] + tan[0]) / w, 0], [0, 2 / h, (tan[3] + tan[2]) / h, 0],
             [0, 0, -1, -2 * NEAR], [0, 0, -1, 0]];
  const R = [[rot[0], rot[3], rot[6], 0], [rot[1], rot[4], rot[7], 0],
             [rot[2], rot[5], rot[8], 0], [0, 0, 0, 1]];
  const out = new Float32Array(16);
  for (let r = 0; r < 4; ++r)
    for (let c = 0; c < 4; ++c) {
      let s = 0;
      for (let k = 0; k < 4; ++k) s += P[r][k] * R[k][c];
      out[4 * c + r] = s;
    }
  return out;
}

export class FlareLayer {
  constructor(gl, shaders) {
    this.gl = gl;
    this.prog = program(gl, shaders.flareVert, shaders.flareFrag, 'flare.frag', 'flare.vert');
  }

  // Adds every element's light into the bound target (width x height): elements is the module's
  // Float64Array (ELEMENT_VALUES per element), eye { rot, tan, pos } the eye's pose.
  draw(elements, eye, width, height) {
    const gl = this.gl, u = this.prog.u;
    const n = elements.length / ELEMENT_VALUES;
    if (!n) return;
    gl.useProgram(this.prog.p);
    gl.uniformMatrix4fv(u('u_view_proj'), false, flareViewProj(eye.rot, eye.tan));
    const r = eye.rot; // row-major; column-major for the shader
    gl.uniformMatrix3fv(u('u_eye_rot'), false,
                        [r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]]);
    gl.uniform4f(u('u_tan'), eye.tan[0], eye.tan[1], eye.tan[2], eye.tan[3]);
    gl.uniform2f(u('u_size'), width, height);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE); // light adds to the image under it
    const pos = eye.pos ?? [0, 0, 0];
    for (let i = 0; i < n; ++i) {
      const e = elements.subarray(i * ELEMENT_VALUES, (i + 1) * ELEMENT_VALUES);
      // The centre relative to the eye (in doubles, then to float): floats keep their precision
      // at the directional style's 100 m.
      gl.uniform3f(u('u_centre'), e[1] - pos[0], e[2] - pos[1], e[3] - pos[2]);
      gl.uniform3f(u('u_axis_u'), e[4], e[5], e[6]);
      gl.uniform3f(u('u_axis_v'), e[7], e[8], e[9]);
      gl.uniform1f(u('u_extent'), e[10]);
      gl.uniform1f(u('u_support'), e[11]);
      gl.uniform3f(u('u_colour'), e[12], e[13], e[14]);
      gl.uniform1i(u('u_shape'), e[0]);
      gl.uniform1f(u('u_chroma'), e[15]);
      gl.drawArrays(gl.TRIANGLES, 0, 6);
    }
    gl.disable(gl.BLEND);
  }
}
