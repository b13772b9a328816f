// The page's WebGL2 renderer: the passes of vdfx's GL compositor for one view, compiled from the
// same GLSL (shaders/, written by `vdfx publish` from effects/' sources with the GLSL ES 3.00
// prelude). Per frame:
//   1. video layer: each pixel's footprint filtered from the eye's equirect image
//      (shaders/video.frag, effects/pixel_footprint.h: taps along the footprint's major axis from
//      the area-average mip chain, which shaders/mip_level.frag builds level by level after each
//      upload, as xr/render/mip_chain_gl.cpp does), into a float target larger than the view by
//      the blur's margin, so the blur sees real image beyond the border
//      (effects/view_renderer.h). A stereo frame is uploaded as two images, one per eye with its
//      own mip chain, as xr/render/video_layer.cpp does, so no sample, mip level or blur tap
//      reads the other eye's half; VR180 is black outside its coverage;
//   2. with a blur: the horizontal Gaussian (shaders/blur_1d.frag);
//   3. the stack (shaders/stack*.frag): the vertical Gaussian fused in, tint, exposure,
//      saturation, contrast, vignette, into the canvas;
//   4. with a flare or grain in view: the stack into a float target instead, the flares and the
//      grain drawn there (layers.js), then copied to the canvas.

const DEG = Math.PI / 180;

// Eye -> world rotation of a view at (azimuth, altitude, roll) in degrees, row-major: yaw
// -azimuth about y, then altitude about x, then roll about z (effects/view_camera.cpp,
// pose_rotation).
export function viewRotation(azDeg, altDeg, rollDeg = 0) {
  const rot = (axis, a) => {
    const c = Math.cos(a), s = Math.sin(a);
    if (axis === 'x') return [1, 0, 0, 0, c, -s, 0, s, c];
    if (axis === 'y') return [c, 0, s, 0, 1, 0, -s, 0, c];
    return [c, -s, 0, s, c, 0, 0, 0, 1];
  };
  const mul = (a, b) => {
    const m = new Array(9).fill(0);
    for (let i = 0; i < 3; ++i)
      for (let j = 0; j < 3; ++j)
        for (let k = 0; k < 3; ++k) m[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return m;
  };
  return mul(mul(rot('y', -azDeg * DEG), rot('x', altDeg * DEG)), rot('z', rollDeg * DEG));
}

// A symmetric view: its tangent rectangle (left, right, down, up) for a horizontal FOV.
export function viewTangents(hfovDeg, width, height) {
  const tx = Math.tan(0.5 * hfovDeg * DEG), ty = (tx * height) / width;
  return [-tx, tx, -ty, ty];
}

// Column-major for uniformMatrix3fv.
function columnMajor(m) {
  return new Float32Array([m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]]);
}

// The Gaussian's tap table as xr/render/blur_pyramid_gl.cpp builds it: the contract's weights
// exp(-i^2 / (2 sigma^2)) normalised over -radius..radius, texel k the pair (2k+1, 2k+2) read
// with one bilinear fetch at its weighted mean offset.
export function gaussianTaps(sigma, radius) {
  const w = [];
  let sum = 0;
  for (let i = 0; i <= radius; ++i) {
    w.push(Math.exp((-i * i) / (2 * sigma * sigma)));
    sum += (i === 0 ? 1 : 2) * w[i];
  }
  for (let i = 0; i <= radius; ++i) w[i] /= sum;
  const taps = [];
  for (let i = 1; i <= radius; i += 2) {
    const a = w[i], b = i + 1 <= radius ? w[i + 1] : 0;
    taps.push(i + b / (a + b), a + b);
  }
  return { centre: w[0], taps: new Float32Array(taps) };
}

// Blur sigma in pixels and the kernel radii of a centred view (xr/render/effect_stack_gl.cpp,
// blur_pixels, with the optical centre at the image centre).
export function blurPixels(sigmaDeg, tan, width, height) {
  const s = sigmaDeg * DEG;
  const sx = (s * width) / (tan[1] - tan[0]), sy = (s * height) / (tan[3] - tan[2]);
  return { sx, sy, rx: Math.ceil(3 * sx), ry: Math.ceil(3 * sy) };
}

function compile(gl, type, source, name) {
  const s = gl.createShader(type);
  gl.shaderSource(s, source);
  gl.compileShader(s);
  if (!gl.getShaderParameter(s, gl.COMPILE_STATUS))
    throw new Error(`shader ${name} does not compile: ${gl.getShaderInfoLog(s)}`);
  return s;
}

// Levels of a full mip chain (GL's count, down to 1 x 1; effects/mip_chain.h).
export function mipLevels(width, height) {
  let levels = 1;
  while (width > 1 || height > 1) {
    width = Math.max(1, width >> 1);
    height = Math.max(1, height >> 1);
    ++levels;
  }
  return levels;
}

export function program(gl, vertex, fragment, name, vertexName = 'fullscreen.vert') {
  const p = gl.createProgram();
  gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, vertex, vertexName));
  gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, fragment, name));
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS))
    throw new Error(`program ${name} does not link: ${gl.getProgramInfoLog(p)}`);
  const uniforms = new Map();
  const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < n; ++i) {
    const info = gl.getActiveUniform(p, i);
    const key = info.name.replace(/\[0\]$/, '');
    uniforms.set(key, gl.getUniformLocation(p, info.name));
  }
  return { p, u: (key) => uniforms.get(key) ?? null };
}

// A float colour target (RGBA16F: filterable in WebGL2, renderable with EXT_color_buffer_float).
export function target(gl, width, height) {
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA16F, width, height);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
    throw new Error('this browser cannot render into a half-float target');
  return { tex, fb, width, height };
}

export class Renderer {
  // shaders: { vert, video, mip, blur, stack, stackBlur } source texts.
  constructor(gl, shaders) {
    if (!gl.getExtension('EXT_color_buffer_float'))
      throw new Error('this browser\'s WebGL2 has no EXT_color_buffer_float (float targets)');
    this.gl = gl;
    this.video = program(gl, shaders.vert, shaders.video, 'video.frag');
    this.mip = program(gl, shaders.vert, shaders.mip, 'mip_level.frag');
    this.mipFb = gl.createFramebuffer();
    this.storage = new Map(); // texture -> "WxH format" of its immutable storage (#storage)
    this.blur = program(gl, shaders.vert, shaders.blur, 'blur_1d.frag');
    this.stack = program(gl, shaders.vert, shaders.stack, 'stack.frag');
    this.stackBlur = program(gl, shaders.vert, shaders.stackBlur, 'stack_blur.frag');
    this.vao = gl.createVertexArray();
    this.frameTex = this.#videoTexture(); // the browser-converted frame (mono: the eye's image)
    // What each eye samples (mono: eyes[0] only): its image as an RGB texture, or three planes
    // converted per sample (ycbcr set by uploadPlanes).
    this.eyes = [0, 1].map(() => ({
      rgb: this.#videoTexture(), ycbcr: null,
      planes: [this.#videoTexture(), this.#videoTexture(), this.#videoTexture()] }));
    this.setLayout({});
    this.taps = [this.#tapTexture(), this.#tapTexture()];
    this.targets = null;
    this.layers = null; // layers.js's EffectLayers: the flares and grain after the stack
  }

  #videoTexture() {
    const gl = this.gl;
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    // Columns wrap at the seam, rows clamp at the poles (effects/equirect_sampler.h); the mip
    // chain (#buildMips) for the levels the video layer's footprint taps read.
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    return tex;
  }

  // player.json's video: layout, coverage, coverage_edge_deg, each eye's rectangle of the frame
  // (written by publish from effects/stereo_layout.h) and the frame's height. Absent: mono 360.
  setLayout(video) {
    const stereo = (video.layout ?? 'mono') !== 'mono';
    this.layout = { stereo, coverage: video.coverage ?? 360, edge: video.coverage_edge_deg ?? 2,
                    rects: stereo ? [video.eyes.left, video.eyes.right] : null,
                    height: video.height, maxAniso: video.max_anisotropy ?? 16 };
  }

  // Columns wrap at a 360 image's seam and clamp at a VR180 image's edges (as the GL path).
  #setWrap(tex) {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S,
                     this.layout.coverage === 360 ? gl.REPEAT : gl.CLAMP_TO_EDGE);
  }

  // `tex`, or a new texture in its place (the caller keeps the one returned), with immutable
  // storage for the full mip chain of a width x height image in `internal`, bound; level 0 is
  // then written with texSubImage2D. Immutable as in xr/render/video_layer.cpp: a mutable
  // texture's level outside [TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL] is an incomplete framebuffer
  // attachment (OpenGL ES 3.0, 4.4.4.1), so #buildMips could draw none of its levels.
  #storage(tex, width, height, internal) {
    const gl = this.gl;
    const key = `${width}x${height} ${internal}`;
    if (this.storage.get(tex) !== key) {
      this.storage.delete(tex);
      gl.deleteTexture(tex);
      tex = this.#videoTexture();
      gl.texStorage2D(gl.TEXTURE_2D, mipLevels(width, height), internal, width, height);
      this.storage.set(tex, key);
    }
    this.#setWrap(tex);
    return tex;
  }

  // Levels 1.. of `tex` (#storage; level 0 just uploaded, width x height) as the area-average
  // chain of effects/mip_chain.h, one draw of shaders/mip_level.frag per level with only the
  // level above readable, as xr/render/mip_chain_gl.cpp draws them (not generateMipmap, whose
  // filter for odd sizes is the browser's choice).
  #buildMips(tex, width, height) {
    const gl = this.gl;
    const levels = mipLevels(width, height);
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.useProgram(this.mip.p);
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(this.mip.u('u_src'), 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.mipFb);
    gl.bindVertexArray(this.vao);
    gl.disable(gl.BLEND);
    for (let l = 1, w = width, h = height; l < levels; ++l) {
      w = Math.max(1, w >> 1);
      h = Math.max(1, h >> 1);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_BASE_LEVEL, l - 1);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAX_LEVEL, l - 1);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, l);
      // Loud rather than a chain of blank levels (what the footprint taps would then read).
      if (l === 1 && gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
        throw new Error(`the mip chain's level 1 (${w} x ${h}) cannot be drawn`);
      gl.viewport(0, 0, w, h);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, null, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_BASE_LEVEL, 0);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAX_LEVEL, levels - 1);
  }

  #tapTexture() {
    const gl = this.gl;
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return tex;
  }

  // The current frame of a <video> (or any image source), as the video layer samples it: the
  // bottom row first (t = 1 - v, effects/glsl_common.h), values as encoded (no colour space
  // conversion by the browser beyond Y'CbCr -> R'G'B').
  upload(source) {
    const gl = this.gl;
    const w = source.videoWidth ?? source.width, h = source.videoHeight ?? source.height;
    this.frameTex = this.#storage(this.frameTex, w, h, gl.RGBA8);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, true);
    gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, source);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
    for (const e of this.eyes) e.ycbcr = null;
    if (!this.layout.stereo) {
      this.#buildMips(this.frameTex, w, h);
      return;
    }
    // Each eye's half copied into its own texture (rows bottom first, as uploaded).
    this.readFb ??= gl.createFramebuffer();
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.readFb);
    gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D,
                            this.frameTex, 0);
    for (const [i, r] of this.layout.rects.entries()) {
      const e = this.eyes[i];
      e.rgb = this.#storage(e.rgb, r.width, r.height, gl.RGBA8);
      gl.copyTexSubImage2D(gl.TEXTURE_2D, 0, 0, 0, r.x, this.layout.height - r.y - r.height,
                           r.width, r.height);
    }
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    for (const [i, r] of this.layout.rects.entries())
      this.#buildMips(this.eyes[i].rgb, r.width, r.height);
  }

  // A decoded 8-bit frame as its three planes (each { data, stride }, rows top first),
  // converted per sample by the video layer as the GL path converts (u_ycbcr = 1; `info` is
  // player.json's video.ycbcr, written by publish from io/ycbcr.h). A stereo frame's planes are
  // cut at each eye's rectangle, the chroma planes at the subsampled rectangle
  // (io/eye_picture.h, cut_picture). False, uploading nothing, when a half does not fall
  // on the chroma grid (an odd half height in 4:2:0): the caller lets the browser convert.
  uploadPlanes(planes, width, height, info) {
    const [sx, sy] = info.log2_chroma;
    const rects = this.layout.rects ?? [{ x: 0, y: 0, width, height }];
    const mx = (1 << sx) - 1, my = (1 << sy) - 1;
    const off = (r) => ((r.x | r.width) & mx) !== 0 || ((r.y | r.height) & my) !== 0;
    if (this.layout.stereo && rects.some(off)) return false;
    for (const [i, r] of rects.entries()) this.#uploadEyePlanes(this.eyes[i], planes, r, info);
    return true;
  }

  #uploadEyePlanes(eye, planes, r, info) {
    const gl = this.gl;
    const [sx, sy] = info.log2_chroma;
    const cw = Math.ceil(r.width / 2 ** sx), ch = Math.ceil(r.height / 2 ** sy);
    const sizes = [[r.width, r.height], [cw, ch], [cw, ch]];
    const corners = [[r.x, r.y], [r.x >> sx, r.y >> sy], [r.x >> sx, r.y >> sy]];
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    for (let i = 0; i < 3; ++i) {
      eye.planes[i] = this.#storage(eye.planes[i], sizes[i][0], sizes[i][1], gl.R8);
      gl.pixelStorei(gl.UNPACK_ROW_LENGTH, planes[i].stride);
      gl.pixelStorei(gl.UNPACK_SKIP_PIXELS, corners[i][0]);
      gl.pixelStorei(gl.UNPACK_SKIP_ROWS, corners[i][1]);
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, sizes[i][0], sizes[i][1], gl.RED,
                       gl.UNSIGNED_BYTE, planes[i].data);
    }
    gl.pixelStorei(gl.UNPACK_SKIP_PIXELS, 0);
    gl.pixelStorei(gl.UNPACK_SKIP_ROWS, 0);
    gl.pixelStorei(gl.UNPACK_ROW_LENGTH, 0);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
    for (let i = 0; i < 3; ++i)
      this.#buildMips(eye.planes[i], sizes[i][0], sizes[i][1]);
    // Luma (u, v) -> chroma (u, v) of this eye's planes, as xr/render/video_layer.cpp maps it.
    const scale = [], offset = [];
    for (let a = 0; a < 2; ++a) {
      const step = 2 ** info.log2_chroma[a], chroma = sizes[1][a];
      scale.push(sizes[0][a] / (step * chroma));
      offset.push((0.5 - (0.5 + info.chroma_siting[a]) / step) / chroma);
    }
    // A chroma texel spans 2^log2_chroma luma texels: the footprint's level is that much finer
    // there (xr/render/video_layer.cpp).
    const chromaLod = -0.5 * (info.log2_chroma[0] + info.log2_chroma[1]);
    eye.ycbcr = { m: info.m, offset: info.offset, scale, chromaOffset: offset, chromaLod };
  }

  #targetsFor(width, height, margin) {
    const w = width + 2 * margin, h = height + 2 * margin;
    const t = this.targets;
    if (t && t.a.width === w && t.a.height === h) return t;
    const gl = this.gl;
    if (t) for (const x of [t.a, t.b]) { gl.deleteTexture(x.tex); gl.deleteFramebuffer(x.fb); }
    this.targets = { a: target(gl, w, h), b: target(gl, w, h) };
    return this.targets;
  }

  #setTaps(prog, unit, index, sigma, radius) {
    const gl = this.gl;
    const { centre, taps } = gaussianTaps(sigma, radius);
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, this.taps[index]);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RG32F, Math.max(1, taps.length / 2), 1, 0, gl.RG, gl.FLOAT,
                  taps.length ? taps : new Float32Array(2));
    gl.uniform1i(prog.u('u_taps'), unit);
    gl.uniform1i(prog.u('u_tap_count'), taps.length / 2);
    gl.uniform1f(prog.u('u_centre_weight'), centre);
    gl.activeTexture(gl.TEXTURE0);
  }

  // The video layer into `dst` (the view widened by `margin` pixels on every side), sampling
  // `eye`'s image ('left' or 'right'; mono: the one image).
  #videoPass(dst, rot, tan, width, height, margin, eye) {
    const gl = this.gl, v = this.video;
    const dx = (margin * (tan[1] - tan[0])) / width, dy = (margin * (tan[3] - tan[2])) / height;
    gl.bindFramebuffer(gl.FRAMEBUFFER, dst.fb);
    gl.viewport(0, 0, dst.width, dst.height);
    gl.useProgram(v.p);
    const e = this.eyes[this.layout.stereo && eye === 'right' ? 1 : 0];
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.layout.stereo ? e.rgb : this.frameTex);
    gl.uniform1i(v.u('u_equirect'), 0);
    gl.uniformMatrix3fv(v.u('u_rot'), false, columnMajor(rot));
    gl.uniform1i(v.u('u_lod_mode'), 3); // the footprint filter (effects/pixel_footprint.h)
    gl.uniform1f(v.u('u_max_aniso'), this.layout.maxAniso);
    gl.uniform1f(v.u('u_coverage'), this.layout.coverage);
    gl.uniform1f(v.u('u_edge'), this.layout.edge);
    gl.uniform1i(v.u('u_ycbcr'), e.ycbcr ? 1 : 0);
    if (e.ycbcr) this.#setYcbcr(v, e);
    gl.uniform4f(v.u('u_tan'), tan[0] - dx, tan[1] + dx, tan[2] - dy, tan[3] + dy);
    gl.uniform2f(v.u('u_size'), dst.width, dst.height);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  #setYcbcr(v, eye) {
    const gl = this.gl, y = eye.ycbcr;
    for (let i = 0; i < 3; ++i) {
      gl.activeTexture(gl.TEXTURE1 + i);
      gl.bindTexture(gl.TEXTURE_2D, eye.planes[i]);
      gl.uniform1i(v.u(`u_plane${i}`), 1 + i);
    }
    gl.activeTexture(gl.TEXTURE0);
    gl.uniformMatrix3fv(v.u('u_m'), true, new Float32Array(y.m)); // row-major
    gl.uniform3fv(v.u('u_offset'), new Float32Array(y.offset));
    gl.uniform1f(v.u('u_code_scale'), 255);
    gl.uniform2f(v.u('u_chroma_scale'), y.scale[0], y.scale[1]);
    gl.uniform2f(v.u('u_chroma_offset'), y.chromaOffset[0], y.chromaOffset[1]);
    gl.uniform1f(v.u('u_chroma_lod'), y.chromaLod);
  }

  #blurPass(src, dst, blur) {
    const gl = this.gl, b = this.blur;
    gl.bindFramebuffer(gl.FRAMEBUFFER, dst.fb);
    gl.viewport(0, 0, dst.width, dst.height);
    gl.useProgram(b.p);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, src.tex);
    gl.uniform1i(b.u('u_src'), 0);
    gl.uniform2f(b.u('u_dir'), 1, 0);
    this.#setTaps(b, 1, 0, blur.sx, blur.rx);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // p: the 9 stack parameters of vdfx_eval (blur sigma_deg, tint r g b, stops, saturation,
  // contrast, vignette radius_deg, falloff_deg).
  #stackPass(src, prog, p, tan, width, height, margin, blur, dst) {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, dst ? dst.fb : null);
    gl.viewport(0, 0, width, height);
    gl.useProgram(prog.p);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, src.tex);
    gl.uniform1i(prog.u('u_src'), 0);
    gl.uniform1i(prog.u('u_margin'), margin);
    gl.uniform4f(prog.u('u_tan'), tan[0], tan[1], tan[2], tan[3]);
    gl.uniform2f(prog.u('u_size'), width, height);
    gl.uniform2f(prog.u('u_centre_tan'), 0, 0);
    if (blur) this.#setTaps(prog, 1, 1, blur.sy, blur.ry);
    gl.uniform3f(prog.u('u_tint'), p[1], p[2], p[3]);
    gl.uniform1f(prog.u('u_exposure_gain'), Math.pow(2, p[4]));
    gl.uniform1f(prog.u('u_saturation'), p[5]);
    gl.uniform1f(prog.u('u_contrast'), p[6]);
    gl.uniform2f(prog.u('u_vignette'), p[7] * DEG, p[8] * DEG);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // An 8-bit target of one eye's size: the stack pass draws an XR eye here, then it is copied
  // into the eye's viewport (the shaders' pinhole reads gl_FragCoord from the target's corner).
  #outputFor(width, height) {
    const o = this.output;
    if (o && o.width === width && o.height === height) return o;
    const gl = this.gl;
    if (o) { gl.deleteTexture(o.tex); gl.deleteFramebuffer(o.fb); }
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
    const fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    this.output = { tex, fb, width, height };
    return this.output;
  }

  // One view (width x height device pixels) with the parameters p: into the canvas, or with
  // `out` ({ fb, x, y }: an XR layer's framebuffer and the eye's viewport corner) into that.
  // view: { az, alt, fov } for the desktop, or { rot, tan, pos } (an XR eye's own rotation,
  // projection tangents and position); its `eye` ('left' or 'right', default left) picks a
  // stereo frame's image.
  draw(view, width, height, p, out = null) {
    const gl = this.gl;
    gl.bindVertexArray(this.vao);
    gl.disable(gl.BLEND);
    const tan = view.tan ?? viewTangents(view.fov, width, height);
    const rot = view.rot ?? viewRotation(view.az, view.alt);
    const blur = p[0] > 0 ? blurPixels(p[0], tan, width, height) : null;
    const margin = blur ? Math.max(blur.rx, blur.ry) : 0;
    const t = this.#targetsFor(width, height, margin);
    this.#videoPass(t.a, rot, tan, width, height, margin, view.eye);
    if (blur) this.#blurPass(t.a, t.b, blur);
    const dst = out ? this.#outputFor(width, height) : null;
    const layered = this.layers ? this.layers.begin(width, height) : null;
    this.#stackPass(blur ? t.b : t.a, blur ? this.stackBlur : this.stack, p, tan, width, height,
                    margin, blur, layered ?? dst);
    if (layered) this.layers.finish({ rot, tan, pos: view.pos ?? [0, 0, 0] }, width, height,
                                    dst ? dst.fb : null);
    if (!out) return;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, dst.fb);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, out.fb);
    gl.blitFramebuffer(0, 0, width, height, out.x, out.y, out.x + width, out.y + height,
                       gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }
}
