/// @file
/// @brief The export's frame-parallel pipeline: one thread decodes the source in order, workers
/// render frames in parallel (one frame each), and the calling thread hands the rendered frames
/// to the encoder strictly in order. Frames in flight are bounded, so memory stays flat however
/// long the video is.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "io/frame_decoder.h"
#include "io/picture.h"

namespace vdfx::app {

struct PipelineSettings {
  std::int64_t first = 0;  //!< first frame (inclusive)
  std::int64_t last = 0;   //!< last frame (inclusive)
  int workers = 0;         //!< render threads; 0: one per core
  /// Frames decoded but not yet encoded, at most (0: 2 per worker).
  int max_in_flight = 0;
  const std::atomic<bool>* cancel = nullptr;  //!< polled; set: stop soon, nothing more encoded
  /// After each encoded frame, on the calling thread: frames done so far.
  std::function<void(std::int64_t done)> on_progress;
};

struct PipelineResult {
  std::int64_t encoded = 0;
  bool cancelled = false;
  /// The source ended before `last` (a file cut short): frames after it do not exist.
  bool ended_early = false;
  std::int64_t end = 0;  //!< one past the last frame encoded
};

/// Source frame `frame` (as decoded) -> the picture to encode. Called on worker threads, several
/// at once: must be thread-safe.
using FrameRenderer = std::function<io::Picture(const io::Picture& source, std::int64_t frame)>;
/// Receives the rendered frames in order on the calling thread (the encoder).
using FrameSink = std::function<void(const io::Picture& rendered, std::int64_t frame)>;

/// Runs the pipeline over [first, last]. A frame that fails to decode is an io::InputError naming
/// the file and the frame (an export never skips frames silently); an exception in a renderer or
/// the sink stops everything and is rethrown here.
PipelineResult run_export_pipeline(io::FrameDecoder& decoder, const FrameRenderer& render,
                                   const FrameSink& sink, const PipelineSettings& settings);

}  // namespace vdfx::app
