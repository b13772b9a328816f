/// @file
/// @brief Per-frame timings of the loop (`--stats`): GPU stages summed over both eyes, CPU parts;
/// medians over a window (periodic lines) and over the whole run (at exit).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "app/window/frame_loop.h"
#include "xr/render/gpu_timer.h"

namespace vdfx::app {

class FrameLoopStats {
 public:
  /// GPU stage times of one frame as the compositor names them ("left video", "right effects"):
  /// the eye prefix is dropped and both eyes are summed, so a stage is per frame.
  void add_gpu(const std::vector<xr::StageTime>& times);
  /// A CPU part of the frame ("frame", "upload", "bake"), milliseconds.
  void add_cpu(const std::string& part, double ms);
  /// Medians since the last take_window() (then starts a new window).
  std::vector<StageMedian> take_window();
  /// Medians over every frame added.
  std::vector<StageMedian> total() const;
  /// "video 12.1 ms, effects 3.0 ms, ..." in a stable order (GPU stages first).
  static std::string format(const std::vector<StageMedian>& m);

 private:
  using Series = std::map<std::string, std::vector<double>>;
  static std::vector<StageMedian> medians(const Series& s);
  Series window_, all_;
};

}  // namespace vdfx::app
