/// @file
/// @brief Reading the runtime's knobs from the environment.
#include "tests/openxr_runtime/config.h"

#include <epoxy/gl.h>

#include <charconv>
#include <cstdlib>
#include <stdexcept>

namespace vdfx::test_runtime {
namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto at = s.find(sep, start);
    out.push_back(trim(s.substr(start, at == std::string::npos ? std::string::npos : at - start)));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

/// A whole non-negative integer, or nothing.
std::optional<std::int64_t> to_int(const std::string& s) {
  std::int64_t v = 0;
  const auto* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, v);
  if (s.empty() || ec != std::errc() || ptr != end || v < 0) return std::nullopt;
  return v;
}

std::int64_t int_variable(const char* name, const std::string& value) {
  const auto v = to_int(value);
  if (!v) {
    throw std::runtime_error(std::string(name) + "=" + value +
                             ": expected a whole number of at least 0");
  }
  return *v;
}

}  // namespace

bool CaptureSpec::wants(std::int64_t frame) const {
  switch (mode) {
    case Mode::None: return false;
    case Mode::Last: return true;  // every frame is read, the last one kept
    case Mode::All: return true;
    case Mode::List:
      for (const auto& [a, b] : ranges) {
        if (frame >= a && frame <= b) return true;
      }
      return false;
  }
  return false;
}

const std::vector<SwapchainFormat>& known_swapchain_formats() {
  // Default order: what a PC runtime such as Monado offers for GL, sRGB first (the runtime
  // displays every other colour format as linear light).
  static const std::vector<SwapchainFormat> formats{
      {GL_SRGB8_ALPHA8, "GL_SRGB8_ALPHA8", true, false},
      {GL_RGBA8, "GL_RGBA8", false, false},
      {GL_RGBA16F, "GL_RGBA16F", false, false},
      {GL_RGB10_A2, "GL_RGB10_A2", false, false},
      {GL_DEPTH_COMPONENT16, "GL_DEPTH_COMPONENT16", false, true},
      {GL_DEPTH_COMPONENT24, "GL_DEPTH_COMPONENT24", false, true},
      {GL_DEPTH_COMPONENT32F, "GL_DEPTH_COMPONENT32F", false, true},
      {GL_DEPTH24_STENCIL8, "GL_DEPTH24_STENCIL8", false, true},
      // Offered only when asked for: a colour format few apps render to, and a depth format
      // Monado lists (tests of `vdfx hmd openxr`'s names).
      {GL_R11F_G11F_B10F, "GL_R11F_G11F_B10F", false, false},
      {GL_DEPTH32F_STENCIL8, "GL_DEPTH32F_STENCIL8", false, true},
  };
  return formats;
}

CaptureSpec parse_capture_spec(const std::string& text) {
  CaptureSpec spec;
  const std::string t = trim(text);
  if (t.empty() || t == "last") return spec;
  if (t == "none") {
    spec.mode = CaptureSpec::Mode::None;
    return spec;
  }
  if (t == "all") {
    spec.mode = CaptureSpec::Mode::All;
    return spec;
  }
  spec.mode = CaptureSpec::Mode::List;
  for (const std::string& item : split(t, ',')) {
    const auto dash = item.find('-');
    const auto a = to_int(item.substr(0, dash));
    const auto b = dash == std::string::npos ? a : to_int(item.substr(dash + 1));
    if (!a || !b || *b < *a) {
      throw std::runtime_error("VDFX_TEST_RUNTIME_CAPTURE=" + text + ": '" + item +
                               "' is not a frame number or a range FIRST-LAST; the value is "
                               "last, all, none or a list such as 0,10,20-25");
    }
    spec.ranges.emplace_back(*a, *b);
  }
  return spec;
}

std::vector<SwapchainFormat> parse_swapchain_formats(const std::string& text) {
  std::vector<SwapchainFormat> out;
  if (trim(text) == "none") return out;  // a runtime offering nothing at all
  for (const std::string& name : split(text, ',')) {
    const SwapchainFormat* found = nullptr;
    for (const auto& f : known_swapchain_formats()) {
      if (f.name == name) found = &f;
    }
    if (!found) {
      std::string known;
      for (const auto& f : known_swapchain_formats()) known += " " + f.name;
      throw std::runtime_error("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS=" + text +
                               ": unknown format '" + name + "' (known:" + known + ", or none)");
    }
    out.push_back(*found);
  }
  return out;
}

std::vector<float> parse_refresh_rates(const std::string& text) {
  std::vector<float> out;
  for (const std::string& item : split(text, ',')) {
    float hz = 0.0f;
    const auto* end = item.data() + item.size();
    const auto [ptr, ec] = std::from_chars(item.data(), end, hz);
    if (item.empty() || ec != std::errc() || ptr != end || !(hz >= 1.0f && hz <= 1000.0f)) {
      throw std::runtime_error("VDFX_TEST_RUNTIME_REFRESH_RATES=" + text + ": '" + item +
                               "' is not a rate in Hz (1 to 1000); the value is a list such as "
                               "72,90,120");
    }
    out.push_back(hz);
  }
  return out;
}

bool refresh_rate_offered_from_environment() {
  return !trim(env("VDFX_TEST_RUNTIME_REFRESH_RATES")).empty();
}

bool opengl_offered_from_environment() {
  return env("VDFX_TEST_RUNTIME_NO_OPENGL") != "1";
}

Config read_config_from_environment() {
  Config c;
  c.script_path = env("VDFX_TEST_RUNTIME_SCRIPT");
  c.hmd = env("VDFX_TEST_RUNTIME_HMD");
  c.controller = env("VDFX_TEST_RUNTIME_CONTROLLER");
  if (c.controller.empty()) c.controller = "oculus/touch_controller";
  if (const std::string v = env("VDFX_TEST_RUNTIME_NO_HMD"); !v.empty()) {
    if (v == "always") {
      c.hmd_always_absent = true;
    } else {
      const auto n = to_int(v);
      if (!n || *n > 1000000) {
        throw std::runtime_error("VDFX_TEST_RUNTIME_NO_HMD=" + v +
                                 ": expected 'always' or a number of xrGetSystem calls");
      }
      c.hmd_absent_calls = static_cast<int>(*n);
    }
  }
  if (const std::string v = env("VDFX_TEST_RUNTIME_NO_OPENGL"); !v.empty()) {
    if (v != "0" && v != "1") {
      throw std::runtime_error("VDFX_TEST_RUNTIME_NO_OPENGL=" + v + ": expected 0 or 1");
    }
    c.no_opengl = v == "1";
  }
  const std::string formats = env("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS");
  if (formats.empty()) {
    for (const auto& f : known_swapchain_formats()) {
      if (f.gl_format != GL_R11F_G11F_B10F && f.gl_format != GL_DEPTH32F_STENCIL8)
        c.formats.push_back(f);
    }
  } else {
    c.formats = parse_swapchain_formats(formats);
  }
  if (const std::string v = env("VDFX_TEST_RUNTIME_LOSS_PENDING_NS"); !v.empty()) {
    c.loss_pending_ns = int_variable("VDFX_TEST_RUNTIME_LOSS_PENDING_NS", v);
  }
  if (const std::string v = env("VDFX_TEST_RUNTIME_EXIT_AFTER_FRAMES"); !v.empty()) {
    c.exit_after_frames = int_variable("VDFX_TEST_RUNTIME_EXIT_AFTER_FRAMES", v);
  }
  c.output_dir = env("VDFX_TEST_RUNTIME_OUTPUT_DIR");
  c.capture = parse_capture_spec(env("VDFX_TEST_RUNTIME_CAPTURE"));
  if (const std::string v = env("VDFX_TEST_RUNTIME_SWITCH_CONTEXT"); !v.empty()) {
    if (v != "0" && v != "1") {
      throw std::runtime_error("VDFX_TEST_RUNTIME_SWITCH_CONTEXT=" + v + ": expected 0 or 1");
    }
    c.switch_gl_context = v == "1";
  }
  if (const std::string v = trim(env("VDFX_TEST_RUNTIME_REFRESH_RATES")); !v.empty()) {
    c.refresh_rates = parse_refresh_rates(v);
  }
  if (const std::string v = env("VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES"); !v.empty()) {
    c.placeholder_frames = int_variable("VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES", v);
  }
  return c;
}

}  // namespace vdfx::test_runtime
