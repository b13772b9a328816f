/// @file
/// @brief Lens pre-distortion: inverse per point (closed form, Newton, OpenCV undistortPoints as
/// the peer), mesh build per N, and the mesh error against the exact map per N (computed once).
///
/// All on the generic90 profile's left eye (1440 x 1600). Error counters are the largest
/// difference from the Newton root, in normalised radius and in eye-image pixels at the panel.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "app/bench/inputs.h"
#include "effects/distortion_mesh.h"

namespace {

using vdfx::effects::EyeLens;
using vdfx::effects::InverseMethod;

const EyeLens& eye() {
  return vdfx::app::bench::generic90_left_lens();
}
const std::vector<cv::Point2d>& points() {
  return vdfx::app::bench::lens_grid_points();
}
double px_per_unit() {
  return vdfx::app::bench::lens_px_per_unit();
}

cv::Point2d invert(const cv::Point2d& p, InverseMethod method) {
  return vdfx::app::bench::undistort_point(p, method);
}

double max_error(const std::vector<cv::Point2d>& got) {
  double worst = 0.0;
  for (size_t k = 0; k < got.size(); ++k) {
    const cv::Point2d want = invert(points()[k], InverseMethod::Newton);
    worst = std::max(worst, std::hypot(got[k].x - want.x, got[k].y - want.y));
  }
  return worst;
}

void report(benchmark::State& state, const std::vector<cv::Point2d>& out) {
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points().size()));
  const double err = max_error(out);
  state.counters["max_err"] = err;
  state.counters["max_err_px"] = err * px_per_unit();
}

void run_inverse(benchmark::State& state, InverseMethod method) {
  std::vector<cv::Point2d> out(points().size());
  for (auto _ : state) {
    for (size_t k = 0; k < out.size(); ++k) out[k] = invert(points()[k], method);
    benchmark::DoNotOptimize(out.data());
  }
  report(state, out);
}

void BM_InverseClosedForm(benchmark::State& state) {
  run_inverse(state, InverseMethod::ClosedForm);
}
void BM_InverseNewton(benchmark::State& state) {
  run_inverse(state, InverseMethod::Newton);
}

/// The peer (app/bench/inputs.h): arg 0 OpenCV's default 5 iterations, N > 0 up to N.
void BM_InverseOpenCvUndistortPoints(benchmark::State& state) {
  std::vector<cv::Point2d> out;
  for (auto _ : state) {
    vdfx::app::bench::opencv_undistort_grid(out, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(out.data());
  }
  report(state, out);
}

void BM_MeshBuild(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(vdfx::effects::build_distortion_mesh(eye(), n));
  state.counters["vertices"] = n * n;
}

/// Error of the mesh against the exact per-pixel map over every pixel of the eye: run once.
void BM_MeshErrorVsN(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto mesh = vdfx::effects::build_distortion_mesh(eye(), n);
  vdfx::effects::MeshError err;
  for (auto _ : state) err = vdfx::effects::measure_mesh_error(eye(), mesh, 1);
  state.counters["rms_px"] = err.rms_px;
  state.counters["max_px"] = err.max_px;
  state.counters["skipped"] = static_cast<double>(err.skipped);
}

}  // namespace

BENCHMARK(BM_InverseClosedForm);
BENCHMARK(BM_InverseNewton);
BENCHMARK(BM_InverseOpenCvUndistortPoints)->Arg(0)->Arg(20);
BENCHMARK(BM_MeshBuild)->Arg(5)->Arg(9)->Arg(17)->Arg(33)->Arg(65)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MeshErrorVsN)
    ->Arg(5)
    ->Arg(9)
    ->Arg(17)
    ->Arg(33)
    ->Arg(65)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
