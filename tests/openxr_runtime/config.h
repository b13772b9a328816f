/// @file
/// @brief The simulated OpenXR runtime's knobs, read from the environment when an instance is
/// created (docs/openxr.md, "Testing without a headset", lists every variable).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vdfx::test_runtime {

/// Which submitted frames are read back into the output folder.
struct CaptureSpec {
  enum class Mode { None, Last, All, List } mode = Mode::Last;
  /// Mode::List: inclusive frame ranges [first, last], frame = index of the xrWaitFrame (0-based).
  std::vector<std::pair<std::int64_t, std::int64_t>> ranges;
  bool wants(std::int64_t frame) const;
};

/// One GL swapchain format the runtime can offer (name as in the GL headers).
struct SwapchainFormat {
  std::int64_t gl_format = 0;
  std::string name;
  bool srgb = false;   //!< stored values are sRGB-encoded (read back as they are)
  bool depth = false;  //!< a depth or depth-stencil format (never read back)
};

/// Every format the runtime can back with a texture, in its default order of preference.
const std::vector<SwapchainFormat>& known_swapchain_formats();

struct Config {
  std::string script_path;         //!< VDFX_TEST_RUNTIME_SCRIPT ("" = no script)
  std::string hmd;                 //!< VDFX_TEST_RUNTIME_HMD ("" = script header's, else generic90)
  std::string controller;          //!< VDFX_TEST_RUNTIME_CONTROLLER: profile tail or "none"
  bool hmd_always_absent = false;  //!< VDFX_TEST_RUNTIME_NO_HMD=always
  int hmd_absent_calls = 0;        //!< VDFX_TEST_RUNTIME_NO_HMD=N: the first N xrGetSystem fail
  bool no_opengl = false;          //!< VDFX_TEST_RUNTIME_NO_OPENGL=1
  std::vector<SwapchainFormat> formats;           //!< VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS
  std::optional<std::int64_t> loss_pending_ns;    //!< VDFX_TEST_RUNTIME_LOSS_PENDING_NS
  std::optional<std::int64_t> exit_after_frames;  //!< VDFX_TEST_RUNTIME_EXIT_AFTER_FRAMES
  std::string output_dir;          //!< VDFX_TEST_RUNTIME_OUTPUT_DIR ("" = nothing written)
  CaptureSpec capture;             //!< VDFX_TEST_RUNTIME_CAPTURE
  bool switch_gl_context = false;  //!< VDFX_TEST_RUNTIME_SWITCH_CONTEXT=1 (SteamVR's habit)
  /// VDFX_TEST_RUNTIME_REFRESH_RATES=72,90,120: XR_FB_display_refresh_rate is offered with these
  /// rates (Hz); empty: it is not offered.
  std::vector<float> refresh_rates;
  /// VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES=N: the first N frames of a session are predicted
  /// kPlaceholderPeriodNs apart, and say so as their period, as a runtime does before it has
  /// the display's timing (Monado: 16 ms, "62.5 Hz").
  std::int64_t placeholder_frames = 0;
};

/// The placeholder frame period (VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES).
inline constexpr std::int64_t kPlaceholderPeriodNs = 16'000'000;

/// Reads the variables; throws std::runtime_error naming the variable and what is wrong.
Config read_config_from_environment();

/// Whether XR_KHR_opengl_enable is offered (VDFX_TEST_RUNTIME_NO_OPENGL is not 1). The loader
/// lists the extensions before it creates an instance: that list must not fail on another
/// variable's bad value, which xrCreateInstance then reports.
bool opengl_offered_from_environment();
/// Whether XR_FB_display_refresh_rate is offered (VDFX_TEST_RUNTIME_REFRESH_RATES is set), for
/// the same list.
bool refresh_rate_offered_from_environment();

/// Parses one variable's value (exposed for tests).
CaptureSpec parse_capture_spec(const std::string& text);
std::vector<SwapchainFormat> parse_swapchain_formats(const std::string& text);
std::vector<float> parse_refresh_rates(const std::string& text);

}  // namespace vdfx::test_runtime
