// The shader grain styles (headset, surface) on the page: xr/render/grain_gl.cpp's shader pass in
// WebGL2, from the same GLSL (shaders/grain.frag, effects/grain_shaders.h with the ES prelude).
// The layers are laid out by the module once per frame from the head's pose
// (effects::GrainSet::layout at the frame's display time); each eye's uniforms come from the
// module too (effects::shader_grain_uniforms of that eye's rotation, position and tangents), so
// the page computes nothing of the grain itself. GLSL ES has no dual-source blending: the shader
// writes (s floor, 1 + s) and the blend (ONE, SRC_ALPHA) into the float target gives
// s floor + C (1 + s), as the GL path's (docs/publish.md).
import { program } from './renderer.js';

// Floats per eye in the module's uniforms (app/publish/wasm/player_api.cpp, vdfx_grain_uniforms).
export const UNIFORM_VALUES = 28;

export class GrainLayer {
  constructor(gl, shaders) {
    this.gl = gl;
    this.prog = program(gl, shaders.vert, shaders.grainFrag, 'grain.frag');
  }

  // One layer into the bound float target (width x height): `u` the module's 28 floats for this
  // eye, `perm` its permutation (Int32Array(256)).
  draw(u, perm, width, height) {
    const gl = this.gl, loc = this.prog.u;
    gl.useProgram(this.prog.p);
    gl.uniform4iv(loc('u_perm'), perm);
    gl.uniform1i(loc('u_style'), u[0]);
    gl.uniformMatrix3fv(loc('u_eye_to_grain'), false, u.subarray(1, 10));
    gl.uniform3fv(loc('u_eye'), u.subarray(10, 13));
    gl.uniform1f(loc('u_distance'), u[13]);
    gl.uniform1f(loc('u_inv_cell'), u[14]);
    gl.uniform3fv(loc('u_offset1'), u.subarray(15, 18));
    gl.uniform3fv(loc('u_offset2'), u.subarray(18, 21));
    gl.uniform1f(loc('u_octave2'), u[21]);
    gl.uniform1f(loc('u_gain'), u[22]);
    gl.uniform1f(loc('u_floor'), u[23]);
    gl.uniform4fv(loc('u_tan'), u.subarray(24, 28));
    gl.uniform2f(loc('u_size'), width, height);
    gl.enable(gl.BLEND);
    // Colour: src + dst * src.alpha = s floor + C (1 + s); the target's alpha is kept.
    gl.blendFuncSeparate(gl.ONE, gl.SRC_ALPHA, gl.ZERO, gl.ONE);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.disable(gl.BLEND);
  }
}
