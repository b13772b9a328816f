/// @file
/// @brief `vdfx suggest`'s library entry point (docs/suggest.md): proposes keyframes from the video
/// itself as ordinary keyframes in a sidecar. The command parses its options into a
/// SuggestRequest and calls run_suggest; tests call it directly.
#pragma once

#include <atomic>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/suggest/comfort.h"
#include "app/suggest/greedy_fit.h"
#include "app/suggest/guide.h"
#include "app/suggest/metering.h"
#include "app/suggest/motion.h"
#include "effects/effect_types.h"
#include "io/sidecar.h"
#include "io/video_layout.h"

namespace vdfx::app::suggest {

enum class Kind { Exposure, Guide, Comfort };
enum class GuideEffect { Saturation, Exposure, Both };

/// Defaults of the tolerance, in each effect's own units.
inline constexpr double kExposureToleranceStops = 0.25;
inline constexpr double kSaturationTolerance = 0.05;

struct SuggestRequest {
  Kind kind = Kind::Exposure;
  std::filesystem::path video;
  std::optional<std::filesystem::path> sidecar_in;
  std::filesystem::path sidecar_out;
  bool force = false;      //!< an existing --sidecar-out may be replaced (io/sidecar_target.h)
  double strength = 1.0;   //!< 0..1
  std::int64_t every = 0;  //!< frames between sampled frames; 0: about 1 s (comfort: 1/6 s)
  std::optional<double> tolerance;      //!< none: the effect's default above
  std::size_t max_keyframes = 256;      //!< per effect
  bool merge = false;                   //!< add to keyframes the sidecar already has
  int directions = 400;                 //!< sampled view directions (a Fibonacci lattice)
  MeteringOptions metering;             //!< exposure
  std::vector<PointOfInterest> points;  //!< guide
  GuideEffect guide_effect = GuideEffect::Saturation;
  MotionOptions motion;  //!< comfort
  /// --layout / --coverage (docs/stereo.md): stereo video is analysed in its left eye's image;
  /// VR180 in its half turn only, where the keyframes go too (docs/suggest.md, "VR180").
  io::LayoutOverride layout;
};

struct SuggestedEffect {
  effects::EffectType type = effects::EffectType::Exposure;
  double tolerance = 0.0;
  FitResult fit;
};

struct SuggestReport {
  std::vector<SuggestedEffect> effects;
  std::size_t samples = 0;              //!< directions x sampled frames
  std::vector<std::int64_t> frames;     //!< the sampled frames
  std::string transfer;                 //!< exposure: the transfer the video was linearised with
  double reference_level = 0.0;         //!< exposure: log2 luminance
  std::vector<double> speed_deg_per_s;  //!< comfort: the camera's angular speed at every frame
  double seconds = 0.0;                 //!< wall time of the whole suggestion
  std::string sidecar_note;  //!< run_suggest: what became of an existing --sidecar-out, or ""
};

/// A suggestion running on another thread (the editor's, app/editor/suggest_worker.h): how far it
/// is, and a request to stop.
struct Progress {
  std::atomic<double> fraction{0.0};  //!< 0..1: frames decoded, then keyframes placed
  std::atomic<bool> cancel{false};    //!< set by the caller; the suggestion then throws Cancelled
};

/// Thrown by suggest_into when Progress::cancel was set: nothing was changed.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("the suggestion was cancelled") {}
};

/// Runs one suggestion on `sidecar` in memory (its keyframes of the effect are added to, as with
/// request.merge; request.sidecar_in/out are not used). Reports progress and stops when asked
/// (Cancelled); on any exception `sidecar` is left as it was.
SuggestReport suggest_into(const SuggestRequest& request, io::Sidecar& sidecar,
                           Progress* progress = nullptr);

/// Runs one suggestion and writes the sidecar (atomically, never onto an input). An existing
/// --sidecar-out is added to, or replaced only with `force` (io::resolve_sidecar_target). Throws
/// io::InputError for input that cannot be used (unreadable video, a video that cannot be
/// metered, keyframes already there without merge, an --sidecar-out that would be replaced) and
/// UsageError for options out of range.
SuggestReport run_suggest(const SuggestRequest& request);

/// The frames sampled: 0, every, 2 every, ... and the last frame, plus `extra` (clamped).
std::vector<std::int64_t> sampled_frames(std::int64_t frames, std::int64_t every,
                                         const std::vector<std::int64_t>& extra = {});

}  // namespace vdfx::app::suggest
