/// @file
/// @brief The command-line options every windowed command shares (`vdfx play`, `vdfx edit`) and
/// the setup they share: HMD profile, input backend (optionally recorded), video source, loop
/// options. Inputs are checked before any window opens, so bad input is exit 1 even without a
/// display.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/window/frame_loop.h"
#include "io/output_path.h"
#include "io/sidecar.h"
#include "io/video_layout.h"
#include "io/video_source.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {

struct LoopCli {
  std::string hmd = "generic90";
  std::string input = "sim";
  std::string record;
  bool stats = false;
  double scale = kDefaultEyeScale;
  std::int64_t frames = -1;
  std::string screenshot;
  std::string mirror = "auto";          //!< auto | desktop | pre | lens | eye
  double fov = kDefaultDesktopHfovDeg;  //!< the desktop view's horizontal FOV
  std::string window = "1280x720";
  bool hidden = false;
  bool no_vsync = false;
  double decode_timeout_ms = 0.0;
  std::string bake = "256x128";
  std::string blur = "pyramid";  //!< exact | pyramid (xr::BlurMethod)
  std::string runtime = "sim";   //!< sim | openxr (docs/openxr.md)
  std::string look = "drag";     //!< the sim's right-button drag: drag | mouselook
  io::LayoutOverride layout;     //!< --layout / --coverage (docs/stereo.md)
  /// The --scale option once added (whether the user gave it: with a headset the default is 1).
  const CLI::Option* scale_option = nullptr;
  /// Options of the simulated headset's window that do nothing with --runtime openxr (--hmd,
  /// --mirror, --fov, --no-vsync): given together with it, a usage error.
  std::vector<const CLI::Option*> sim_only;
};

/// Adds --runtime, --hmd, --input, --record, --stats, --scale, --frames (alias
/// --exit-after-frames), --screenshot, --mirror, --fov, --window, --hidden, --no-vsync,
/// --decode-timeout, --bake, --blur, --look, --layout, --coverage.
void add_loop_options(CLI::App& cli, LoopCli& o);

struct LoopSetup {
  /// The desktop view a replayed sim session was recorded in (its header), for the editor's
  /// panel layout; nullopt otherwise.
  std::optional<io::RecordedDesktopView> recorded_desktop;
  std::unique_ptr<xr::InputBackend> input;
  std::unique_ptr<io::VideoSource> video;
  FrameLoopOptions options;
};

/// Loads the profile, opens the video (a still is a one-frame video) and the input backend
/// (wrapped in the recording decorator with --record); with --runtime openxr, the runtime
/// (xr::OpenXrRuntime::create: no runtime, headset or OpenGL support is an input error before any
/// window opens) and its controllers as the input. Throws io::InputError naming what is wrong,
/// including a --record or --screenshot that is the same file as the video, the profile, the
/// replayed recording or one of `other_inputs` (the command's sidecar).
LoopSetup prepare_loop(const LoopCli& o, const std::filesystem::path& video_path, bool loop_video,
                       const std::vector<io::NamedInput>& other_inputs = {});

/// The video's stereo layout and coverage (io::resolve_video_layout: --layout/--coverage, the
/// stream's tags, `sidecar`'s record (may be null), mono 360) into s.options.video_layout; a hint
/// for a stereo-shaped untagged frame goes to stderr. Throws io::InputError.
void resolve_loop_layout(LoopSetup& s, const LoopCli& o, const io::VideoInfo* sidecar,
                         const std::filesystem::path& sidecar_path);

/// Prints the run's summary line (frames, late frames, frames per second) to stderr.
void report_loop(const char* command, const FrameLoopResult& r);

}  // namespace vdfx::app
