/// @file
/// @brief The OpenXR knob of `vdfx bench` (docs/openxr.md, "Measured"): the app's CPU time per
/// frame from xrWaitFrame's return to xrEndFrame's on the simulated OpenXR runtime, both eyes at
/// generic90's resolution, against the sim backend's frame (both eyes with mesh pre-distortion)
/// of the same player and picture in the same run. The simulated runtime is test code
/// (tests/openxr_runtime, never installed): the row is skipped, saying so, where its manifest is
/// not beside the executable.

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>

#include "app/bench/inputs.h"
#include "app/bench/registry.h"
#include "app/window/frame_loop.h"
#include "app/window/player.h"
#include "io/image_write.h"
#include "io/sidecar.h"
#include "io/temp_folder.h"
#include "io/video_source.h"
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime.h"

namespace vdfx::app::bench {
namespace {

namespace fs = std::filesystem;

constexpr const char* kKnob = "openxr.frame";

/// The simulated runtime's manifest in the build tree beside this executable; nullopt when the
/// tests were not built.
std::optional<fs::path> test_runtime_manifest() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  const fs::path m = exe.parent_path() / "tests" / "openxr_runtime" / "vdfx_test_runtime.json";
  return fs::is_regular_file(m, ec) ? std::optional<fs::path>(m) : std::nullopt;
}

/// The play frame as a still: the synthetic 4K frame in a folder of its own, removed after.
struct StillFile {
  io::TempFolder dir{"vdfx-bench-openxr"};
  fs::path path = dir.path() / "frame.png";
  StillFile() { io::write_png(path, synthetic_frame()); }
};

/// `vdfx play`'s exposure +0.5 (one keyframe: the same everywhere).
io::Sidecar play_sidecar(const fs::path& still) {
  io::Sidecar s = io::new_sidecar({still.string(), 30.0, 1, 3840, 1920});
  effects::EffectTrack exposure;
  exposure.type = effects::EffectType::Exposure;
  exposure.keyframes.push_back({{20.0, 10.0}, 0, {0.5}});
  s.effects.push_back(exposure);
  return s;
}

/// Runs the player for `frames` frames with the sim backend (runtime null) or the OpenXR one;
/// the median of the loop's "frame" CPU time, seconds.
double median_frame_s(const fs::path& still, double scale, int frames,
                      std::shared_ptr<xr::OpenXrRuntime> runtime) {
  auto video = io::VideoSource::open(still, {});
  Player player(play_sidecar(still), video->properties(), {});
  FrameLoopOptions o;
  o.profile = xr::load_hmd_profile("generic90");
  o.eye_scale = scale;
  o.visible = false;
  o.vsync = false;
  o.max_frames = frames;
  o.stats = true;  // the CPU parts' medians (GPU timers too, on both sides alike)
  std::ostringstream quiet;
  o.stats_out = &quiet;
  o.mirror = xr::MirrorMode::PreDistorted;  // the sim renders and pre-distorts both eyes
  o.openxr = runtime;
  std::unique_ptr<xr::InputBackend> input =
      runtime ? runtime->create_input_backend() : xr::create_sim_backend({});
  FrameLoopResult r;
  {
    FrameLoop loop(o, *input, *video, player);
    r = loop.run();
  }
  for (const StageMedian& m : r.medians)
    if (m.stage == "cpu frame") return m.ms / 1000.0;
  throw std::runtime_error("the frame loop reported no frame time");
}

/// Sets an environment variable for a scope, then puts the old value back.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

void run_case(Row& row, const Context& ctx) {
  const auto manifest = test_runtime_manifest();
  if (!manifest) {
    row.status = RowStatus::Skipped;
    row.reason =
        "needs the simulated OpenXR runtime (tests/openxr_runtime, built with the tests: its "
        "manifest tests/openxr_runtime/vdfx_test_runtime.json beside vdfx)";
    return;
  }
  const ScopedEnv runtime_json("XR_RUNTIME_JSON", manifest->string());
  const ScopedEnv no_readback("VDFX_TEST_RUNTIME_CAPTURE", "none");
  const StillFile still;
  const double scale = ctx.quick ? 0.5 : 1.0;
  const int frames = ctx.quick ? 16 : 24;
  // Alternately, so a drifting load weighs on both alike.
  std::vector<double> xr_s, sim_s;
  for (int round = 0; round < 2; ++round) {
    sim_s.push_back(median_frame_s(still.path, scale, frames, nullptr));
    xr_s.push_back(median_frame_s(still.path, scale, frames, xr::OpenXrRuntime::create()));
  }
  row.time = {median_of(xr_s), p90_of(xr_s), static_cast<int>(xr_s.size())};
  row.peer_time = {median_of(sim_s), p90_of(sim_s), static_cast<int>(sim_s.size())};
  const int w = static_cast<int>(1440 * scale), h = static_cast<int>(1600 * scale);
  row.note = "both eyes " + std::to_string(w) + "x" + std::to_string(h) + ", " +
             std::to_string(frames) + " frames per run, 2 runs each (a sample is a run's median)";
}

}  // namespace

void add_openxr_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "the app's CPU time per frame from xrWaitFrame to xrEndFrame on the simulated OpenXR "
          "runtime (vdfx play, exposure, the 4K synthetic frame)",
          "frame", "8-bit steps", "none (the pixels are tested: OpenXrFrames in vdfx_test_app)",
          "the sim backend's frame of the same player (both eyes, mesh 65 pre-distortion)",
          PlotError::Max, true, false});
  r.add(kKnob, quick ? "generic90 at half size" : "generic90 1440x1600", run_case);
}

}  // namespace vdfx::app::bench
