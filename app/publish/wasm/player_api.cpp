/// @file
/// @brief The web player's WebAssembly module: vdfx's own sidecar validator (io/) and stack
/// interpolation (effects/) behind a small C API, so the page runs one implementation of the
/// RBF, the hold-in-time rule and the validation messages. Built with Debian's emscripten by
/// app/publish/wasm/CMakeLists.txt; docs/publish.md describes the calls.
///
/// One sidecar at a time (a page plays one film). Strings returned stay valid until the next call.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "effects/stack_interpolator.h"
#include "io/sidecar.h"
#include "io/sidecar_validate.h"

namespace {

using vdfx::effects::StackInterpolator;

struct Loaded {
  vdfx::io::Sidecar sidecar;
  StackInterpolator stack;
};

std::unique_ptr<Loaded> g_loaded;
std::string g_text;  // the last message or JSON handed out

const char* hand_out(std::string s) {
  g_text = std::move(s);
  return g_text.c_str();
}

// The view as `vdfx eval --at` reads it; nullopt (and the message set) for a frame outside the
// video, which eval refuses the same way.
std::optional<vdfx::effects::StackParams> evaluate(double az, double alt, double frame) {
  if (!g_loaded) return std::nullopt;
  const auto f = static_cast<std::int64_t>(frame);
  if (f < 0 || f >= g_loaded->sidecar.video.frames) {
    g_text = "frame " + std::to_string(f) + " is beyond the video's " +
             std::to_string(g_loaded->sidecar.video.frames) + " frames (/video/frames)";
    return std::nullopt;
  }
  return g_loaded->stack.evaluate(vdfx::effects::Direction{az, alt}, f);
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
    StackInterpolator stack(sidecar.effects, sidecar.interpolation, sidecar.video.fps);
    g_loaded = std::make_unique<Loaded>(Loaded{std::move(sidecar), std::move(stack)});
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

}  // extern "C"
