/// @file
/// @brief The cost of getting one decoded 4K frame (3840 x 1920) into the video layer, before
/// and after the move to Y'CbCr pictures, in the same run:
/// - before: the frame loop's old path: the decoder's RGB frame swapped to BGR on the CPU
///   (cv::cvtColor), uploaded as packed 8-bit BGR, mip chain rebuilt;
/// - after: the decoder's Y'CbCr 4:2:0 planes uploaded as they are (1.5 bytes per pixel instead
///   of 3), converted by the GPU into the RGBA8 level 0, mip chain rebuilt (counter "x_before").
/// And the other side of the move: the video layer now converts every sample it takes, so one
/// eye (1440 x 1600, the generic90 panel; analytic LOD) costs more to draw from Y'CbCr planes
/// than from the RGB texture (counter "x_rgb").
/// Every iteration ends with glFinish; real time. Needs a display (`xvfb-run -a`).
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "io/ycbcr.h"
#include "xr/headset/render_view.h"
#include "xr/render/gl_context.h"
#include "xr/render/video_layer.h"

namespace {

using namespace vdfx;

struct Upload {
  std::unique_ptr<xr::GlContext> ctx;
  std::unique_ptr<xr::VideoLayerGl> layer;
  cv::Mat rgb;
  io::Picture picture;
  std::string error;
  double before_ms = 0;
};

Upload& upload() {
  static Upload u = [] {
    Upload f;
    try {
      f.ctx = xr::GlContext::create();
    } catch (const xr::GlError& e) {
      f.error = e.what();
      return f;
    }
    f.layer = std::make_unique<xr::VideoLayerGl>();
    f.rgb.create(1920, 3840, CV_8UC3);
    f.rgb.forEach<cv::Vec3b>([](cv::Vec3b& p, const int* pos) {
      p = cv::Vec3b(static_cast<uchar>(pos[1] / 15), static_cast<uchar>(pos[0] / 8),
                    static_cast<uchar>((pos[0] + pos[1]) % 256));
    });
    f.picture = io::rgb_to_ycbcr(f.rgb, io::YcbcrInfo{});
    return f;
  }();
  return u;
}

void BM_VideoUploadBefore_RgbToBgr(benchmark::State& state) {
  Upload& u = upload();
  if (!u.ctx) return state.SkipWithError(u.error.c_str());
  double total = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    cv::Mat bgr;
    cv::cvtColor(u.rgb, bgr, cv::COLOR_RGB2BGR);
    u.layer->set_frame(bgr);
    glFinish();
    total +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  u.before_ms = total / state.iterations();
}

void BM_VideoUploadAfter_Ycbcr420(benchmark::State& state) {
  Upload& u = upload();
  if (!u.ctx) return state.SkipWithError(u.error.c_str());
  double total = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    u.layer->set_frame(u.picture);
    glFinish();
    total +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  if (u.before_ms > 0) state.counters["x_before"] = total / state.iterations() / u.before_ms;
}

double g_rgb_render_ms = 0;

/// One eye drawn from the layer's current source; arg 0: RGB texture, 1: Y'CbCr planes.
void BM_VideoLayerEye(benchmark::State& state) {
  Upload& u = upload();
  if (!u.ctx) return state.SkipWithError(u.error.c_str());
  const bool ycbcr = state.range(0) != 0;
  if (ycbcr) {
    u.layer->set_frame(u.picture);
  } else {
    cv::Mat bgr;
    cv::cvtColor(u.rgb, bgr, cv::COLOR_RGB2BGR);
    u.layer->set_frame(bgr);
  }
  xr::GlTarget eye(1440, 1600, xr::TexFormat::RGBA16F);
  const xr::RenderView view = xr::RenderView::look_at({30, 10}, 0, 100.0, 1440, 1600);
  double total = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    u.layer->render(eye, view);
    glFinish();
    total +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  const double ms = total / state.iterations();
  if (!ycbcr)
    g_rgb_render_ms = ms;
  else if (g_rgb_render_ms > 0)
    state.counters["x_rgb"] = ms / g_rgb_render_ms;
}

}  // namespace

BENCHMARK(BM_VideoUploadBefore_RgbToBgr)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_VideoUploadAfter_Ycbcr420)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_VideoLayerEye)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
