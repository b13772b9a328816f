/// @file
/// @brief Lens knob of `vdfx bench` on the CPU: the inverse of the radial model per point,
/// closed form (Mallon-Whelan) and bracketed Newton, with OpenCV's undistortPoints as the peer,
/// each against the root found by long-double bisection, in eye pixels over generic90's panel.
#include <cmath>
#include <vector>

#include "app/bench/inputs.h"
#include "app/bench/registry.h"

namespace vdfx::app::bench {
namespace {

using effects::InverseMethod;

/// r_u with f(r_u) = r_d by bisection in long double (64 halvings reach its precision).
long double exact_root(const effects::LensModel& lens, double r_d) {
  const long double c1 = lens.params().c1, c2 = lens.params().c2;
  const auto f = [&](long double r) { return r + c1 * r * r * r + c2 * r * r * r * r * r; };
  long double lo = 0.0L, hi = std::max(1e-3, r_d);
  const long double cap = lens.max_undistorted_radius();
  while (f(hi) < r_d && hi < cap) hi = std::min(2.0L * hi, cap);
  for (int i = 0; i < 100; ++i) {
    const long double mid = 0.5L * (lo + hi);
    (f(mid) < r_d ? lo : hi) = mid;
  }
  return 0.5L * (lo + hi);
}

/// Error of undistorted points against the exact roots, in eye pixels.
ErrorStats error_px(const std::vector<cv::Point2d>& got) {
  const auto& pts = lens_grid_points();
  double worst = 0.0, sum2 = 0.0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    const double r_d = std::hypot(pts[k].x, pts[k].y);
    const double s =
        r_d > 0.0 ? static_cast<double>(exact_root(generic90_left_lens().lens, r_d) / r_d) : 1.0;
    const double e =
        std::hypot(got[k].x - pts[k].x * s, got[k].y - pts[k].y * s) * lens_px_per_unit();
    worst = std::max(worst, e);
    sum2 += e * e;
  }
  return {worst, std::sqrt(sum2 / static_cast<double>(got.size()))};
}

constexpr const char* kKnob = "lens.inverse";

void inverse_case(Row& row, const Context& ctx,
                  std::function<void(std::vector<cv::Point2d>&)> method, bool is_peer) {
  std::vector<cv::Point2d> out(lens_grid_points().size()), peer_out;
  const double units = static_cast<double>(out.size());
  const Timed subject{[&] { method(out); }, units};
  if (is_peer) {
    row.time = row.peer_time = measure(subject, ctx.budget);
  } else {
    const auto t =
        measure_pair(subject, {[&] { opencv_undistort_grid(peer_out, 0); }, units}, ctx.budget);
    row.time = t.subject;
    row.peer_time = t.peer;
  }
  method(out);
  row.error = error_px(out);
}

}  // namespace

void add_lens_knobs(Registry& r, bool /*quick*/) {
  r.knob({kKnob,
          "inverse of the radial lens model per point, generic90 (c1 0.22, c2 0.24), 4096 points "
          "over the panel",
          "point", "px (eye image)", "root by long-double bisection",
          "OpenCV undistortPoints, default 5 iterations", PlotError::Max, false});
  const auto ours = [](InverseMethod m) {
    return [m](std::vector<cv::Point2d>& out) {
      const auto& pts = lens_grid_points();
      for (std::size_t k = 0; k < out.size(); ++k) out[k] = undistort_point(pts[k], m);
    };
  };
  r.add(kKnob, "closed form", [ours](Row& row, const Context& ctx) {
    inverse_case(row, ctx, ours(InverseMethod::ClosedForm), false);
  });
  r.add(kKnob, "Newton", [ours](Row& row, const Context& ctx) {
    inverse_case(row, ctx, ours(InverseMethod::Newton), false);
  });
  r.add(kKnob, "OpenCV 5 iterations", [](Row& row, const Context& ctx) {
    inverse_case(
        row, ctx, [](std::vector<cv::Point2d>& out) { opencv_undistort_grid(out, 0); }, true);
  });
  r.add(kKnob, "OpenCV 20 iterations", [](Row& row, const Context& ctx) {
    inverse_case(
        row, ctx, [](std::vector<cv::Point2d>& out) { opencv_undistort_grid(out, 20); }, false);
  });
}

}  // namespace vdfx::app::bench
