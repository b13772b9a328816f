/// @file
/// @brief Effect stack benchmarks: blur peers, colour stack vs a plain copy, view rendering.
///
/// All run on one thread (cv::setNumThreads(1) for the measured loop) so that the ratios compare
/// algorithms, not how many cores each one happened to get. Run with --benchmark_repetitions=N to
/// get medians.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "app/bench/inputs.h"
#include "effects/effect_stack.h"
#include "effects/equirect_sampler.h"
#include "effects/gaussian_blur.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"

namespace vdfx::effects {
namespace {

constexpr int kSize = 1024;
constexpr double kFov = 90.0;

/// Single-threaded OpenCV for the lifetime of one benchmark.
struct OneThread {
  int previous = cv::getNumThreads();
  OneThread() { cv::setNumThreads(1); }
  ~OneThread() { cv::setNumThreads(previous); }
};

const cv::Mat& test_view() {
  static const cv::Mat img = app::bench::noise_image(kSize);
  return img;
}

const ViewCamera& test_camera() {
  static const ViewCamera cam = ViewCamera::from_horizontal_fov({{30, 10}, 0}, kFov, kSize, kSize);
  return cam;
}

const cv::Mat& sunrise() {
  return app::bench::sunrise_rgb();
}

/// range(0) is sigma in hundredths of a degree; the counter reports it in pixels.
template <cv::Mat (*Blur)(const cv::Mat&, double, double)>
void BM_Blur(benchmark::State& state) {
  const OneThread one;
  const double sigma_px = sigma_px_from_deg(state.range(0) / 100.0, test_camera().fx());
  for (auto _ : state) benchmark::DoNotOptimize(Blur(test_view(), sigma_px, sigma_px));
  state.counters["sigma_px"] = sigma_px;
  state.counters["radius_px"] = gaussian_radius(sigma_px);
}
BENCHMARK_TEMPLATE(BM_Blur, blur_exact_2d)
    ->Name("Effects/BlurExact2D")
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_TEMPLATE(BM_Blur, blur_separable)
    ->Name("Effects/BlurSeparable")
    ->Arg(25)
    ->Arg(50)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Blur, blur_opencv)
    ->Name("Effects/BlurOpenCv")
    ->Arg(25)
    ->Arg(50)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond);

using app::bench::colour_params;

void BM_ColourStack(benchmark::State& state) {
  const OneThread one;
  const StackParams p = colour_params();
  const cv::Mat angles = vignette_angle_map(test_camera());
  for (auto _ : state) benchmark::DoNotOptimize(apply_colour_stack(test_view(), p, angles));
}
BENCHMARK(BM_ColourStack)->Name("Effects/ColourStack")->Unit(benchmark::kMillisecond);

/// The memory-bound peer: a plain copy of an image of the same size and type.
void BM_MatCopy(benchmark::State& state) {
  const OneThread one;
  cv::Mat dst;
  for (auto _ : state) {
    test_view().copyTo(dst);
    benchmark::DoNotOptimize(dst.data);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_MatCopy)->Name("Effects/MatCopy")->Unit(benchmark::kMillisecond);

/// range(0): 0 bilinear, 1 footprint; range(1): blur sigma in hundredths of a degree.
void BM_RenderView(benchmark::State& state) {
  const OneThread one;
  const EquirectSampler sampler(
      sunrise(),
      {state.range(0) ? SampleFilter::Footprint : SampleFilter::Bilinear, PoleRows::Clamp});
  StackParams p = colour_params();
  p.blur_sigma_deg = state.range(1) / 100.0;
  for (auto _ : state) benchmark::DoNotOptimize(render_view(sampler, test_camera(), p));
}
BENCHMARK(BM_RenderView)
    ->Name("Effects/RenderView")
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 50})
    ->Unit(benchmark::kMillisecond);

void BM_SampleView(benchmark::State& state) {
  const OneThread one;
  const EquirectSampler sampler(
      sunrise(),
      {state.range(0) ? SampleFilter::Footprint : SampleFilter::Bilinear, PoleRows::Clamp});
  for (auto _ : state) benchmark::DoNotOptimize(sample_view(sampler, test_camera()));
}
BENCHMARK(BM_SampleView)->Name("Effects/SampleView")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vdfx::effects
