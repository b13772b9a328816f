/// @file
/// @brief The work of `vdfx export` as a library call: the command parses its options into an
/// ExportRequest and calls run_export (tests call it without the command line). docs/export.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "io/video_layout.h"

namespace vdfx::app {

/// Frames A-B of the source, inclusive (A <= B).
struct FrameRange {
  std::int64_t first = 0, last = 0;
};

struct ExportRequest {
  std::filesystem::path video;    //!< the equirect video (or a panorama image: one frame)
  std::filesystem::path sidecar;  //!< the effects (.vdfx.json)
  /// The baked per-pixel 360 video to write; empty for a viewer's-path export.
  std::filesystem::path baked_out;
  std::filesystem::path path_recording;  //!< a recorded session: export the viewer's view
  std::filesystem::path path_out;        //!< with path_recording: the flat video to write
  bool h265 = false;                     //!< libx265, else libx264
  /// A libavcodec encoder that replaces libx264/libx265 (`vdfx publish --transcode vp9`:
  /// libvpx-vp9), with its own options; empty: h265 decides.
  std::string encoder;
  std::map<std::string, std::string> encoder_options;
  /// ProRes 422 HQ (prores_ks profile 3, 10-bit 4:2:2, .mov only); overrides h265.
  bool prores = false;
  /// Bits per code value of the encoded video: 8, or 10 (--codec h265: Main10; --codec prores).
  /// At 10 bits nothing passes through 8 bits from decode to encode (baked export only). 0: the
  /// source's (10 for a deeper source when the codec and export can carry it, else 8).
  int depth = 0;
  int crf = -1;  //!< -1: 18 (h264) or 20 (h265)
  std::string preset = "medium";
  bool chroma_444 = false;  //!< else 4:2:0 (even sizes only)
  /// Only these frames; none: the whole video (a path export: up to the recording's end).
  std::optional<FrameRange> frames;
  int threads = 0;                 //!< render threads; 0: one per core
  int param_step = 0;              //!< baked: exact parameters every N pixels; 0: the default grid
  double hfov_deg = 90.0;          //!< path: horizontal field of view
  int width = 1280, height = 720;  //!< path: output size
  io::LayoutOverride layout;       //!< --layout / --coverage (docs/stereo.md)
  effects::EyeIndex eye = effects::EyeIndex::Left;  //!< path, stereo video: the eye shown
  /// Path, stereo video: both eyes side by side (left eye left, each width x height), tagged as
  /// a left-right stereo flat video (--stereo left-right).
  bool stereo_side_by_side = false;
  /// Baked: each frame turned back into the world frame with the sidecar's `camera` (contract:
  /// "Frames of reference"); a sidecar without one is an input error.
  bool stabilize = false;

  bool baked() const { return !baked_out.empty(); }
  /// The output as the user named it.
  const std::filesystem::path& output() const { return baked() ? baked_out : path_out; }
};

struct ExportResult {
  std::filesystem::path output;  //!< as named in the request
  std::int64_t frames = 0;       //!< frames encoded
  int width = 0, height = 0;
  bool cancelled =
      false;  //!< a stop signal (SIGINT, SIGTERM, SIGHUP): nothing written, the old file kept
  /// The video ended before the last frame asked for (cut short?); `end` is one past the last
  /// frame exported.
  bool ended_early = false;
  std::int64_t end = 0;
};

/// The request's own consistency (either baked_out or path_recording with path_out; an .mp4,
/// .mov or .mkv output; param_step and stabilize only baked). Throws app::UsageError naming the
/// option.
void check_export_request(const ExportRequest& request);

/// Reads and checks every input before anything is written (io::InputError: exit 1), then
/// renders and encodes the frames (docs/export.md: decode thread, render workers, ordered
/// encoder) into a temporary file renamed over the output when complete. Prints its plan, notes
/// and progress on stderr. A stop signal (app/cli/stop_signals.h: the caller's StopSignals) stops
/// it cleanly: result.cancelled, the temporary file removed, the output as it was.
ExportResult run_export(const ExportRequest& request);

}  // namespace vdfx::app
