// The layers after the effect stack on the page, flares then grain (flare-grain.md, stereo
// rule 4), as the GL compositor draws them: the stack is drawn into a float target, the flares
// add to it and the grain modulates it there (unclamped, like the CPU reference), then it is
// copied to the screen. Laid out once per frame from the head's pose (update), drawn into each
// eye from that eye's own pose and projection (finish). With no flare or grain in view nothing
// changes: the stack draws straight to the screen.
import { target } from './renderer.js';
import { FlareLayer, ELEMENT_VALUES } from './flare.js';
import { GrainLayer, UNIFORM_VALUES } from './grain.js';

// The module's layer calls (app/publish/wasm/player_api.cpp).
function layerCalls(m) {
  const head = m._malloc(16 * 8), floats = m._malloc(UNIFORM_VALUES * 4);
  const layers = m.cwrap('vdfx_layers', 'number', ['number', 'number']);
  const elements = m.cwrap('vdfx_flare_elements', 'number', []);
  const grainCount = m.cwrap('vdfx_grain_layers', 'number', []);
  const uniforms = m.cwrap('vdfx_grain_uniforms', 'number', ['number', 'number', 'number']);
  const put = (values) => m.HEAPF64.set(values, head / 8);
  return {
    lights: m.cwrap('vdfx_lights', 'number', ['string']),
    // The head's pose (rot: head -> LOCAL row-major, pos: metres) at a frame: the flare elements
    // (a copy) and the number of shader grain layers; null for a frame outside the video.
    layout(rot, pos, frame) {
      put([...rot, ...pos]);
      const n = layers(head, frame);
      if (n < 0) return null;
      const at = elements() / 8;
      return { elements: m.HEAPF64.slice(at, at + n * ELEMENT_VALUES), grains: grainCount() };
    },
    // Grain layer k's uniforms for one eye: { u: Float32Array(28), perm: Int32Array(256) }.
    grain(k, eye) {
      put([...eye.rot, ...eye.pos, ...eye.tan]);
      const perm = uniforms(k, head, floats);
      return { u: m.HEAPF32.slice(floats / 4, floats / 4 + UNIFORM_VALUES),
               perm: m.HEAP32.slice(perm / 4, perm / 4 + 256) };
    },
  };
}

export class EffectLayers {
  // shaders: the page's shader texts (flareVert, flareFrag, grainFrag, vert); m: the module.
  constructor(gl, shaders, m) {
    this.gl = gl;
    this.calls = layerCalls(m);
    this.flare = new FlareLayer(gl, shaders);
    this.grain = new GrainLayer(gl, shaders);
    this.frame = { elements: new Float64Array(0), grains: 0 };
    this.target = null;
  }

  // lights.json's text (publish's tracked auto lights); throws with the module's message.
  setLights(text, message) {
    if (!this.calls.lights(text)) throw new Error(message());
  }

  // Once per drawn frame: the layout for the head's pose.
  update(rot, pos, frame) {
    this.frame = this.calls.layout(rot, pos, frame) ?? { elements: new Float64Array(0), grains: 0 };
  }

  // The float target the stack draws into when there is a layer to draw, else null.
  begin(width, height) {
    if (!this.frame.elements.length && !this.frame.grains) return null;
    const t = this.target;
    if (t && t.width === width && t.height === height) return t;
    if (t) { this.gl.deleteTexture(t.tex); this.gl.deleteFramebuffer(t.fb); }
    this.target = target(this.gl, width, height);
    return this.target;
  }

  // The layers into the target begin() gave, seen by `eye` ({ rot, tan, pos }), then the target
  // into `dst` (a framebuffer, or null: the canvas).
  finish(eye, width, height, dst) {
    const gl = this.gl, t = this.target;
    gl.bindFramebuffer(gl.FRAMEBUFFER, t.fb);
    gl.viewport(0, 0, width, height);
    this.flare.draw(this.frame.elements, eye, width, height);
    for (let k = 0; k < this.frame.grains; ++k) {
      const { u, perm } = this.calls.grain(k, eye);
      this.grain.draw(u, perm, width, height);
    }
    // Float to 8 bits as the stack's own output is written (clamped, rounded by GL).
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, t.fb);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, dst);
    gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }
}

// The page's layers for a film (player.json): the auto lights publish tracked (lights.json)
// handed to the module when a flare has "light": "auto".
export async function effectLayers(gl, shaders, module, config, fetchText) {
  const layers = new EffectLayers(gl, shaders, module.raw);
  if (config.lights) layers.setLights(await fetchText(config.lights), module.message);
  return layers;
}
