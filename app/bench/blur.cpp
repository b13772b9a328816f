/// @file
/// @brief Blur knob of `vdfx bench` on the CPU: the exact 2-D Gaussian, the separable one (the
/// CPU reference of the effect stack) and OpenCV's GaussianBlur (the peer), one thread each,
/// against a direct 2-D Gaussian sum in long double at sampled pixels, in 8-bit steps.
#include <cmath>
#include <random>
#include <vector>

#include "app/bench/inputs.h"
#include "app/bench/output.h"
#include "app/bench/registry.h"
#include "effects/gaussian_blur.h"

namespace vdfx::app::bench {
namespace {

using BlurFn = cv::Mat (*)(const cv::Mat&, double, double);

constexpr const char* kKnob = "blur.cpu";

/// Pixels where the reference is computed: 4096 seeded positions, borders included.
std::vector<cv::Point> sample_pixels(int size) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> u(0, size - 1);
  std::vector<cv::Point> p;
  for (int i = 0; i < 4096; ++i) p.emplace_back(u(rng), u(rng));
  for (int i = 0; i < 64; ++i) p.emplace_back(i * (size - 1) / 63, 0);  // the top border row
  return p;
}

/// The contract's Gaussian at one pixel summed directly in 2-D (border pixels repeated).
cv::Vec3d reference_at(const cv::Mat& src, cv::Point at, const std::vector<double>& w) {
  const int r = static_cast<int>(w.size() / 2);
  long double acc[3] = {0, 0, 0};
  for (int dy = -r; dy <= r; ++dy) {
    const int y = std::clamp(at.y + dy, 0, src.rows - 1);
    for (int dx = -r; dx <= r; ++dx) {
      const int x = std::clamp(at.x + dx, 0, src.cols - 1);
      const long double k = static_cast<long double>(w[static_cast<std::size_t>(dy + r)]) *
                            w[static_cast<std::size_t>(dx + r)];
      const cv::Vec3f& c = src.at<cv::Vec3f>(y, x);
      for (int ch = 0; ch < 3; ++ch) acc[ch] += k * c[ch];
    }
  }
  return {static_cast<double>(acc[0]), static_cast<double>(acc[1]), static_cast<double>(acc[2])};
}

ErrorStats steps_at_samples(const cv::Mat& src, const cv::Mat& got, double sigma_px, double* mean) {
  const std::vector<double> w = effects::gaussian_kernel(sigma_px);
  double worst = 0.0, sum = 0.0, sum2 = 0.0;
  long n = 0;
  for (const cv::Point& p : sample_pixels(src.rows)) {
    const cv::Vec3d ref = reference_at(src, p, w);
    const cv::Vec3f& g = got.at<cv::Vec3f>(p);
    for (int ch = 0; ch < 3; ++ch) {
      const double e = std::abs(g[ch] - ref[ch]) * 255.0;
      worst = std::max(worst, e);
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  *mean = sum / static_cast<double>(n);
  return {worst, std::sqrt(sum2 / static_cast<double>(n))};
}

void blur_case(Row& row, const Context& ctx, BlurFn fn, double sigma_deg, bool is_peer) {
  const int size = ctx.quick ? 512 : 1024;
  const cv::Mat src = noise_image(size);
  const double sigma = effects::sigma_px_from_deg(sigma_deg, size / 2.0);  // 90 degree FOV
  cv::Mat out;
  const Timed subject{[&] { out = fn(src, sigma, sigma); }};
  if (is_peer) {
    row.time = row.peer_time = measure(subject, ctx.budget);
  } else {
    cv::Mat peer_out;
    const auto t = measure_pair(
        subject, {[&] { peer_out = effects::blur_opencv(src, sigma, sigma); }}, ctx.budget);
    row.time = t.subject;
    row.peer_time = t.peer;
  }
  out = fn(src, sigma, sigma);
  double mean = 0.0;
  row.error = steps_at_samples(src, out, sigma, &mean);
  row.add("mean_error", mean);
  row.add("sigma_px", sigma);
  row.note = std::to_string(size) + "x" + std::to_string(size) + " noise, 90 deg FOV";
}

}  // namespace

void add_blur_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "Gaussian blur on the CPU, one thread: exact 2-D, separable (the reference path), OpenCV",
          "view", "8-bit steps", "direct 2-D Gaussian sum in long double at 4160 sampled pixels",
          "OpenCV GaussianBlur, same kernel", PlotError::Max, false});
  struct Method {
    const char* name;
    BlurFn fn;
    std::vector<double> sigmas;
    bool peer;
  };
  const std::vector<Method> methods =
      quick ? std::vector<Method>{{"exact 2-D", effects::blur_exact_2d, {0.5}, false},
                                  {"separable", effects::blur_separable, {0.5, 2}, false},
                                  {"OpenCV", effects::blur_opencv, {0.5, 2}, true}}
            : std::vector<Method>{{"exact 2-D", effects::blur_exact_2d, {0.25, 0.5}, false},
                                  {"separable", effects::blur_separable, {0.25, 0.5, 2}, false},
                                  {"OpenCV", effects::blur_opencv, {0.25, 0.5, 2}, true}};
  for (const Method& m : methods)
    for (const double s : m.sigmas)
      r.add(kKnob, std::string(m.name) + " " + setting_degrees(s),
            [fn = m.fn, s, peer = m.peer](Row& row, const Context& ctx) {
              blur_case(row, ctx, fn, s, peer);
              row.series = setting_degrees(s);
            });
}

}  // namespace vdfx::app::bench
