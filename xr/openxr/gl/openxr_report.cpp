/// @file
/// @brief `vdfx hmd openxr`: what the active OpenXR runtime offers, the first thing to run on a
/// new headset and what a bug report quotes.
#include <optional>
#include <sstream>
#include <thread>

#include "xr/openxr/display_refresh.h"
#include "xr/openxr/gl/openxr_runtime_impl.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {
namespace {

using Clock = std::chrono::steady_clock;

/// XR_FB_display_refresh_rate's rates and the current one (the session exists); nothing when the
/// runtime does not offer the extension or answers none.
std::optional<DisplayRefresh> extension_refresh(OpenXrRuntime::Impl& m) {
  if (!m.refresh_rate_ext) return std::nullopt;
  PFN_xrEnumerateDisplayRefreshRatesFB enumerate = nullptr;
  PFN_xrGetDisplayRefreshRateFB get = nullptr;
  if (XR_FAILED(xrGetInstanceProcAddr(m.instance, "xrEnumerateDisplayRefreshRatesFB",
                                      reinterpret_cast<PFN_xrVoidFunction*>(&enumerate))) ||
      XR_FAILED(xrGetInstanceProcAddr(m.instance, "xrGetDisplayRefreshRateFB",
                                      reinterpret_cast<PFN_xrVoidFunction*>(&get))))
    return std::nullopt;
  std::uint32_t n = 0;
  if (XR_FAILED(enumerate(m.session, 0, &n, nullptr))) return std::nullopt;
  std::vector<float> rates(n);
  if (n > 0 && XR_FAILED(enumerate(m.session, n, &n, rates.data()))) return std::nullopt;
  float current = 0.0f;
  if (XR_FAILED(get(m.session, &current)) || !(current > 0.0f)) return std::nullopt;
  DisplayRefresh r;
  r.hz = current;
  r.from_extension = true;
  for (std::uint32_t i = 0; i < n; ++i) r.offered_hz.push_back(rates[i]);
  return r;
}

/// Runs the session to READY and through frames with no layers, measuring the display times the
/// runtime predicts (xr/openxr/display_refresh.h), then leaves through the lifecycle. Unknown
/// when the session never became READY.
DisplayRefresh measured_refresh(OpenXrRuntime& rt) {
  const auto deadline = Clock::now() + std::chrono::seconds(2);
  while (!rt.lifecycle().running() && !rt.lifecycle().leaving() && Clock::now() < deadline) {
    rt.poll_events();
    if (!rt.lifecycle().running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  DisplayRefresh r;
  if (!rt.lifecycle().running()) return r;
  std::vector<std::int64_t> times;
  const std::size_t want = kRefreshWarmupFrames + kRefreshMeasuredFrames + 1;
  const auto frames_end = Clock::now() + std::chrono::seconds(3);
  while (rt.lifecycle().running() && times.size() < want && Clock::now() < frames_end) {
    times.push_back(rt.begin_frame().xr_time);
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
  // A runtime that ended the session early: what frames there are, warm-up included.
  const std::size_t skip = times.size() >= want ? kRefreshWarmupFrames : 0;
  if (const auto hz = refresh_from_display_times(times, skip)) {
    r.hz = *hz;
    r.measured_intervals = static_cast<int>(times.size() - skip - 1);
  }
  return r;
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
  const std::optional<DisplayRefresh> offered = extension_refresh(m);
  out << "refresh        " << describe_refresh(offered ? *offered : measured_refresh(*rt)) << "\n";
  print_list(out, "extensions    ", info.extensions);
  rt.reset();  // the session goes before the GL context it was bound to
  return out.str();
}

}  // namespace vdfx::xr
