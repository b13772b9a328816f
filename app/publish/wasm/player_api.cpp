/// @file
/// @brief The web player's WebAssembly module: vdfx's own sidecar validator (io/), stack
/// interpolation and flare and grain layouts (effects/) behind a small C API, so the page runs
/// one implementation of the RBF, the hold-in-time rule, the validation messages and the flare
/// and grain geometry. Built with Debian's emscripten by
/// app/publish/wasm/CMakeLists.txt; docs/publish.md describes the calls.
///
/// One sidecar at a time (a page plays one film). Strings returned stay valid until the next call.
#include <emscripten/emscripten.h>

#include <array>
#include <cstdint>
#include <exception>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "effects/grain_uniforms.h"
#include "effects/stack_interpolator.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"
#include "io/sidecar_validate.h"

namespace {

using vdfx::effects::StackInterpolator;

namespace fx = vdfx::effects;

struct Loaded {
  vdfx::io::Sidecar sidecar;
  StackInterpolator stack;
  fx::FlareSet flares;
  fx::GrainSet grains;
  // The last vdfx_layers call's flare elements (kFlareElementValues each) and shader grain layers.
  std::vector<double> elements;
  std::vector<fx::GrainFrame> grain_layers;
  std::array<int, 256> perm{};
};

// One flare element for the page: shape, centre (3, LOCAL, metres), axis u (3), axis v (3), the
// quad's half-size (metres), its support (in radii), colour (3), chroma.
constexpr int kFlareElementValues = 16;

std::unique_ptr<Loaded> g_loaded;
std::string g_text;  // the last message or JSON handed out

const char* hand_out(std::string s) {
  g_text = std::move(s);
  return g_text.c_str();
}

// A frame index inside the video, else nullopt with the message set (as evaluate()).
std::optional<std::int64_t> checked_frame(double frame) {
  if (!g_loaded) return std::nullopt;
  const auto f = static_cast<std::int64_t>(frame);
  if (f < 0 || f >= g_loaded->sidecar.video.frames) {
    g_text = "frame " + std::to_string(f) + " is beyond the video's " +
             std::to_string(g_loaded->sidecar.video.frames) + " frames (/video/frames)";
    return std::nullopt;
  }
  return f;
}

// A row-major rotation and a position (12 doubles) as a pose.
fx::HeadPose pose_of(const double* v) {
  fx::HeadPose p;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) p.orientation(r, c) = v[3 * r + c];
  p.position = Eigen::Vector3d(v[9], v[10], v[11]);
  return p;
}

void append_elements(const fx::FlareLayout& l, std::vector<double>& out) {
  for (const fx::FlareElement& e : l.elements) {
    const double support = fx::element_support(e);
    const double v[kFlareElementValues] = {static_cast<double>(e.shape),
                                           e.centre.x(),
                                           e.centre.y(),
                                           e.centre.z(),
                                           l.axis_u.x(),
                                           l.axis_u.y(),
                                           l.axis_u.z(),
                                           l.axis_v.x(),
                                           l.axis_v.y(),
                                           l.axis_v.z(),
                                           support * e.radius,
                                           support,
                                           e.colour.x(),
                                           e.colour.y(),
                                           e.colour.z(),
                                           e.chroma};
    out.insert(out.end(), v, v + kFlareElementValues);
  }
}

// lights.json (written by vdfx publish, docs/publish.md): every frame's auto light or null.
std::vector<std::optional<Eigen::Vector3d>> parse_lights(const char* text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  if (j.value("format", "") != "vdfx.lights") throw std::runtime_error("not a vdfx.lights file");
  std::vector<std::optional<Eigen::Vector3d>> lights;
  for (const nlohmann::json& l : j.at("lights")) {
    if (l.is_null())
      lights.emplace_back();
    else
      lights.emplace_back(fx::to_unit(
          fx::Direction{l.at("azimuth_deg").get<double>(), l.at("altitude_deg").get<double>()}));
  }
  return lights;
}

// The view as `vdfx eval --at` reads it; nullopt (and the message set) for a frame outside the
// video, which eval refuses the same way.
std::optional<vdfx::effects::StackParams> evaluate(double az, double alt, double frame) {
  const std::optional<std::int64_t> f = checked_frame(frame);
  if (!f) return std::nullopt;
  return g_loaded->stack.evaluate(vdfx::effects::Direction{az, alt}, *f);
}

}  // namespace

extern "C" {

/// Validates and loads sidecar `text`; `name` is the file name the messages carry. 1 when
/// valid, 0 otherwise: vdfx_message() is then every problem, one per line, as `vdfx validate`
/// prints them.
EMSCRIPTEN_KEEPALIVE int vdfx_load(const char* name, const char* text) {
  g_loaded.reset();
  try {
    vdfx::io::SidecarReport report = vdfx::io::validate_sidecar_text(text, name);
    if (!report.ok()) {
      hand_out(report.to_string());
      return 0;
    }
    vdfx::io::Sidecar sidecar = std::move(*report.sidecar);
    StackInterpolator stack = vdfx::io::stack_of(sidecar);
    fx::FlareSet flares = vdfx::io::flare_set_of(sidecar);
    fx::GrainSet grains = vdfx::io::grain_set_of(sidecar);
    g_loaded = std::make_unique<Loaded>(
        Loaded{std::move(sidecar), std::move(stack), std::move(flares), std::move(grains)});
    hand_out("");
    return 1;
  } catch (const std::exception& e) {
    hand_out(std::string(name) + ": " + e.what() + "\n");
    return 0;
  }
}

/// The message of the last call that failed (empty after a success).
EMSCRIPTEN_KEEPALIVE const char* vdfx_message() {
  return g_text.c_str();
}

/// The loaded sidecar's video: 0 fps, 1 frames, 2 width, 3 height (0 when none is loaded).
EMSCRIPTEN_KEEPALIVE double vdfx_video(int what) {
  if (!g_loaded) return 0;
  const vdfx::io::VideoInfo& v = g_loaded->sidecar.video;
  switch (what) {
    case 0: return v.fps;
    case 1: return static_cast<double>(v.frames);
    case 2: return v.width;
    case 3: return v.height;
    default: return 0;
  }
}

/// The stack's parameters at a view, the page's per-frame call: writes 9 doubles to `out`
/// (blur sigma_deg, tint gain r, g, b, exposure stops, saturation, contrast, vignette radius_deg,
/// falloff_deg; neutral for an effect without keyframes) and returns the bit mask of the effects
/// that have keyframes (bit i = effect i in the contract's order), or -1 (vdfx_message says why).
EMSCRIPTEN_KEEPALIVE int vdfx_eval(double az, double alt, double frame, double* out) {
  const std::optional<vdfx::effects::StackParams> p = evaluate(az, alt, frame);
  if (!p) return -1;
  const double values[9] = {p->blur_sigma_deg, p->tint_gain.x(),       p->tint_gain.y(),
                            p->tint_gain.z(),  p->exposure_stops,      p->saturation,
                            p->contrast,       p->vignette_radius_deg, p->vignette_falloff_deg};
  for (int i = 0; i < 9; ++i) out[i] = values[i];
  int mask = 0;
  for (int i = 0; i < vdfx::effects::kEffectCount; ++i)
    if (g_loaded->stack.active(static_cast<vdfx::effects::EffectType>(i))) mask |= 1 << i;
  return mask;
}

/// The same as JSON, the "effects" object `vdfx eval` prints (io::stack_params_to_json), or
/// null when vdfx_eval would return -1.
EMSCRIPTEN_KEEPALIVE const char* vdfx_eval_json(double az, double alt, double frame) {
  const std::optional<vdfx::effects::StackParams> p = evaluate(az, alt, frame);
  if (!p) return nullptr;
  return hand_out(vdfx::io::stack_params_to_json(g_loaded->stack, *p).dump());
}

/// The auto lights `vdfx publish` tracked over the video (lights.json's text): from now on a
/// flare with "light": "auto" takes frame f's light from it. 1 when read, else 0 (vdfx_message).
EMSCRIPTEN_KEEPALIVE int vdfx_lights(const char* text) {
  if (!g_loaded) return 0;
  try {
    g_loaded->flares.set_auto_lights(parse_lights(text));
    return 1;
  } catch (const std::exception& e) {
    hand_out(std::string("lights.json: ") + e.what());
    return 0;
  }
}

/// Lays out the flares and the shader grain layers once for a frame from the head (cyclopean)
/// pose: `head` is 12 doubles, its head -> LOCAL rotation row-major and its position (metres).
/// Flares: effects::FlareSet::layouts; grain: effects::GrainSet::layout at the frame's display
/// time (effects::frame_display_time_ns, as vdfx render and export pick a frame's grain), the
/// volumetric styles left out. Returns the number of flare elements (vdfx_flare_elements), or -1
/// for a frame outside the video (vdfx_message says why).
EMSCRIPTEN_KEEPALIVE int vdfx_layers(const double* head, double frame) {
  const std::optional<std::int64_t> f = checked_frame(frame);
  if (!f) return -1;
  Loaded& m = *g_loaded;
  const fx::HeadPose pose = pose_of(head);
  m.elements.clear();
  for (const fx::FlareLayout& l : m.flares.layouts(pose, *f)) append_elements(l, m.elements);
  m.grain_layers.clear();
  const std::int64_t t = fx::frame_display_time_ns(*f, m.sidecar.video.fps);
  for (fx::GrainFrame& g : m.grains.layout(pose, t, *f))
    if (!fx::is_volumetric(g.style)) m.grain_layers.push_back(std::move(g));
  return static_cast<int>(m.elements.size() / kFlareElementValues);
}

/// The flare elements of the last vdfx_layers, 16 doubles each (in the order the GL layer
/// draws them): shape (0 glow, 1 ring), centre x y z (LOCAL, metres), axis u x y z, axis v x y z,
/// the quad's half-size (metres) and the same in radii (u_extent, u_support), colour r g b,
/// chroma: effects/flare_shaders.h's uniforms less the eye's.
EMSCRIPTEN_KEEPALIVE const double* vdfx_flare_elements() {
  return g_loaded ? g_loaded->elements.data() : nullptr;
}

/// The number of shader grain layers of the last vdfx_layers.
EMSCRIPTEN_KEEPALIVE int vdfx_grain_layers() {
  return g_loaded ? static_cast<int>(g_loaded->grain_layers.size()) : 0;
}

/// Shader grain layer k's uniforms for one eye (effects::shader_grain_uniforms): `eye` is 16
/// doubles, the eye -> LOCAL rotation row-major, its position (metres) and its tangents (left,
/// right, down, up). Writes 28 floats to `out`: style, u_eye_to_grain (9, column-major), u_eye
/// (3), distance, inv_cell, offset1 (3), offset2 (3), octave2, gain, floor, tangents (4); returns
/// the layer's permutation (256 ints, u_perm), or null for no such layer.
EMSCRIPTEN_KEEPALIVE const int* vdfx_grain_uniforms(int k, const double* eye, float* out) {
  if (!g_loaded || k < 0 || k >= static_cast<int>(g_loaded->grain_layers.size())) return nullptr;
  const fx::HeadPose pose = pose_of(eye);
  fx::TanRect tan;
  tan.left = eye[12];
  tan.right = eye[13];
  tan.down = eye[14];
  tan.up = eye[15];
  const fx::ShaderGrainUniforms u = fx::shader_grain_uniforms(
      g_loaded->grain_layers[static_cast<std::size_t>(k)], pose.orientation, pose.position, tan);
  float* o = out;
  *o++ = static_cast<float>(u.style);
  for (int i = 0; i < 9; ++i) *o++ = u.eye_to_grain.data()[i];
  for (int i = 0; i < 3; ++i) *o++ = u.eye[i];
  *o++ = u.distance;
  *o++ = u.inv_cell;
  for (int i = 0; i < 3; ++i) *o++ = u.offset1[i];
  for (int i = 0; i < 3; ++i) *o++ = u.offset2[i];
  *o++ = u.octave2;
  *o++ = u.gain;
  *o++ = u.floor;
  for (int i = 0; i < 4; ++i) *o++ = u.tangents[static_cast<std::size_t>(i)];
  g_loaded->perm = u.perm;
  return g_loaded->perm.data();
}

}  // extern "C"
