/// @file
/// @brief Pieces the GL knobs of `vdfx bench` share: timing that drains the GL pipeline, the eye
/// they render (generic90's left eye, half size in a quick run), the video layer's image of the
/// synthetic 4K frame as their input, the plain textured copy of an eye (the memory-bound floor),
/// and errors between read-back images in 8-bit steps. Every GL object lives in caches that
/// release_gl_caches() empties before the context goes.
#pragma once

#include <functional>
#include <opencv2/core.hpp>

#include "app/bench/error.h"
#include "app/bench/registry.h"
#include "app/bench/report.h"
#include "app/bench/timing.h"
#include "xr/headset/render_view.h"
#include "xr/render/eye_layer.h"
#include "xr/render/gl_texture.h"

namespace vdfx::app::bench {

/// `work` followed by glFinish, so a sample is the wall time of its GL work (on llvmpipe, CPU
/// threads) and the next sample starts on an idle pipeline.
Timed gl_timed(std::function<void()> work, double units = 1.0);

struct BenchEye {
  xr::RenderView view;  //!< generic90 left eye's FOV, looking at azimuth 20, altitude 10
  int width = 0, height = 0;
};
/// 1440 x 1600 (generic90), 720 x 800 in a quick run.
BenchEye bench_eye(bool quick);

/// The video layer's render of synthetic_frame() for bench_eye(quick), as an RGBA32F texture
/// and as the CV_32FC3 BGR image the CPU references take (the very same values).
const xr::GlTexture& eye_input(bool quick);
const cv::Mat& eye_input_bgr(bool quick);

/// The plain textured copy of eye_input into an RGBA16F eye buffer (the effect stack with no
/// effect: one texture read and one write per pixel).
Timed copy_floor(bool quick);
inline constexpr const char* kCopyFloor = "plain textured copy of the eye (memory-bound floor)";

/// One eye of the frame `vdfx play` renders (generic90 left eye looking at kFlareLook, half size
/// in a quick run; the synthetic 4K frame, exposure +0.5, mesh 65 pre-distortion) with `layer`
/// drawn into it, timed interleaved with the same eye without it.
PairTimes time_play_eye(const Context& ctx, xr::EyeLayer& layer);

/// Runs `release` when release_gl_caches() is called (before the GL context is destroyed).
void on_gl_release(std::function<void()> release);
void release_gl_caches();

}  // namespace vdfx::app::bench
