/// @file
/// @brief The video inputs `vdfx bench` and tests/bench/media_bench.cpp measure: a generated
/// H.264 clip (made once with FFmpeg's libraries and kept in the system's temporary folder),
/// FFmpeg's plain decode loop as the decoder's floor, a typical sidecar for the exports and the
/// export pipeline with and without its effects.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "app/export/pipeline.h"
#include "effects/stack_interpolator.h"
#include "effects/stereo_layout.h"
#include "io/sidecar.h"

namespace vdfx::app::bench {

/// Frame i of a moving, textured equirect clip (RGB 8-bit, w x h): gradients, a sine pattern
/// and fine noise, so the encoder spends bits as on camera footage.
cv::Mat media_frame(int i, int w, int h);

/// How media_clip encodes: the encoder (libx264, or libx265 for HEVC; veryfast, crf 20 either
/// way) and the stereo layout it tags (Spherical Video V2 equirect with that st3d mode; mono:
/// no tags, as the H.264 clips have).
struct ClipFormat {
  std::string codec = "libx264";
  effects::StereoLayout stereo;
};

/// `frames` frames (RGB 8-bit, w x h, frame(i) the i-th) encoded as media_clip encodes, at `path`;
/// made only when no file is there yet.
std::filesystem::path encode_clip(const std::filesystem::path& path, int w, int h, int frames,
                                  int fps, const std::function<cv::Mat(int)>& frame,
                                  const ClipFormat& format = {});

/// The clip of `frames` media_frame()s as w x h H.264 (libx264 veryfast, crf 20: B-frames and
/// CABAC, as delivered files have), or as `format` says, at `fps`, at temp/<name>; made on first
/// use.
std::filesystem::path media_clip(const std::string& name, int w, int h, int frames, int fps = 30,
                                 const ClipFormat& format = {});

/// The Y', Cb, Cr planes of one decoded frame (CV_8UC1, or CV_16UC1 above 8 bits), pointing
/// into the decoder's buffer: valid only during the call that hands them over.
using PlanesFn = std::function<void(const std::array<cv::Mat, 3>& planes)>;

/// FFmpeg's own loop over a whole file: av_read_frame, avcodec_send_packet,
/// avcodec_receive_frame (threads as many as the codec likes, frame and slice), nothing else.
/// The file and the decoder are opened once; each run() seeks to the start and decodes every
/// frame, as a player's decode thread does after opening.
class PlainDecodeLoop {
 public:
  /// Throws std::runtime_error when the file or its decoder cannot be opened.
  explicit PlainDecodeLoop(const std::filesystem::path& clip);
  ~PlainDecodeLoop();
  PlainDecodeLoop(const PlainDecodeLoop&) = delete;
  PlainDecodeLoop& operator=(const PlainDecodeLoop&) = delete;

  /// Decodes the whole file; `each` (when set) sees every frame in presentation order. Returns
  /// the frame count. Throws std::runtime_error (with `each`) for frames not planar Y'CbCr.
  int run(const PlanesFn& each = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A typical sidecar at 30 fps: tint, exposure, saturation (and, with `blur`, a blur of 0..3
/// degrees towards one side).
io::Sidecar media_sidecar(bool blur);

/// The encoder of export_clip: `vdfx export`'s defaults for libx264 (crf 18) or, with h265,
/// libx265 (crf 20), at `bit_depth` 8 or 10 (Main10; the renderer must hand 10-bit pictures).
struct ExportFormat {
  bool h265 = false;
  int bit_depth = 8;
};

/// Exports every frame of `clip` to `out` through the baked export's frame-parallel pipeline
/// (app/export/pipeline.h) with `render`, encoded with `vdfx export`'s defaults (libx264 medium,
/// crf 18, spherical metadata; or as `format` says). Returns the frames encoded.
std::int64_t export_clip(const std::filesystem::path& clip, const FrameRenderer& render,
                         const std::filesystem::path& out, const ExportFormat& format = {});

/// The baked export's renderer of `stack` (Y'CbCr -> RGB float -> render_baked -> Y'CbCr at
/// `bit_depth`), and the encoder's floor: every frame passed through unchanged.
/// `layout`: a stereo frame, each eye's half baked on its own (docs/stereo.md).
FrameRenderer baked_renderer(const effects::StackInterpolator& stack,
                             const effects::StereoLayout& layout = {}, int bit_depth = 8);
FrameRenderer unchanged_renderer();

}  // namespace vdfx::app::bench
