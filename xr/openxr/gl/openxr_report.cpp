/// @file
/// @brief `vdfx hmd openxr`: what the active OpenXR runtime offers, the first thing to run on a
/// new headset and what a bug report quotes.
#include <cmath>
#include <sstream>
#include <thread>

#include "xr/openxr/gl/openxr_runtime_impl.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {
namespace {

using Clock = std::chrono::steady_clock;

/// Runs the session to READY and a few frames with no layers: the display period is the one
/// refresh-rate fact every runtime gives. Returns 0 when the session never became READY.
double measure_refresh_hz(OpenXrRuntime& rt) {
  const auto deadline = Clock::now() + std::chrono::seconds(2);
  while (!rt.lifecycle().running() && !rt.lifecycle().leaving() && Clock::now() < deadline) {
    rt.poll_events();
    if (!rt.lifecycle().running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!rt.lifecycle().running()) return 0.0;
  std::int64_t period = 0;
  for (int i = 0; i < 3 && rt.lifecycle().running(); ++i) {
    period = rt.begin_frame().period_ns;
    rt.end_frame();
    rt.poll_events();
  }
  rt.request_exit();
  const auto end = Clock::now() + std::chrono::seconds(2);
  while (!rt.lifecycle().leaving() && Clock::now() < end) {
    if (rt.lifecycle().running()) {
      rt.begin_frame();
      rt.end_frame();
    }
    rt.poll_events();
  }
  return period > 0 ? 1e9 / static_cast<double>(period) : 0.0;
}

void print_list(std::ostringstream& out, const char* label, const std::vector<std::string>& v) {
  out << label;
  if (v.empty()) out << " none";
  for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : " ") << v[i];
  out << "\n";
}

}  // namespace

std::string openxr_report(const OpenXrOptions& options) {
  auto rt = OpenXrRuntime::create(options);
  const OpenXrSystemInfo& info = rt->info();
  std::ostringstream out;
  out << "runtime        " << info.runtime_name << " " << info.runtime_version << "\n";
  out << "system         " << info.system_name << " (vendor 0x" << std::hex << info.vendor_id
      << std::dec << ")\n";
  out << "tracking       orientation " << (info.orientation_tracking ? "yes" : "no")
      << ", position " << (info.position_tracking ? "yes" : "no") << "\n";
  for (std::size_t i = 0; i < info.views.size(); ++i) {
    const OpenXrViewInfo& v = info.views[i];
    out << (i == 0 ? "left view      " : "right view     ") << v.recommended_width << "x"
        << v.recommended_height << " recommended, " << v.max_width << "x" << v.max_height
        << " max, " << v.recommended_samples << " sample(s)\n";
  }
  out << "layers         up to " << info.max_layers << "\n";
  print_list(out, "blend modes   ", info.blend_modes);
  print_list(out, "profiles       accepted:", info.profiles_accepted);
  if (!info.profiles_refused.empty())
    print_list(out, "               refused:", info.profiles_refused);

  // Swapchain formats belong to a session, and a session to a GL context: a hidden window.
  GlContextOptions go;
  go.visible = false;
  auto gl = GlContext::create(go);
  OpenXrRuntime::Impl& m = rt->impl();
  m.create_session(gl->window());
  out << "world space    " << m.world_space_name << "\n";
  const std::vector<std::int64_t> formats = m.enumerate_formats();
  std::vector<std::string> names;
  for (const std::int64_t f : formats) names.push_back(gl_format_name(f));
  print_list(out, "formats       ", names);
  const auto chosen = choose_swapchain_format(formats);
  out << "vdfx renders   "
      << (chosen ? gl_format_name(chosen->format) + (chosen->srgb
                                                         ? " (sRGB: encoded values as they are)"
                                                         : " (linear: values decoded from sRGB)")
                 : std::string("nothing: none of these formats suits vdfx"))
      << "\n";
  const double hz = measure_refresh_hz(*rt);
  if (hz > 0.0) {
    out << "refresh        " << std::round(hz * 100.0) / 100.0
        << " Hz (predicted display period)\n";
  } else {
    out << "refresh        unknown (the session did not become READY within 2 s)\n";
  }
  print_list(out, "extensions    ", info.extensions);
  rt.reset();  // the session goes before the GL context it was bound to
  return out.str();
}

}  // namespace vdfx::xr
