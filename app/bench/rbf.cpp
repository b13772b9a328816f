/// @file
/// @brief RBF knobs of `vdfx bench`: full solve and evaluation against N (peer: a textbook dense
/// LU solve of the whole saddle system, evaluated term by term), the incremental add (peer: the
/// full solve it avoids), the per-pixel mode's baked grid against exact per-pixel evaluation, and
/// the exponent and time scale (conditioning and keyframe reproduction).
#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "app/bench/inputs.h"
#include "app/bench/output.h"
#include "app/bench/registry.h"
#include "effects/coords.h"
#include "effects/keyframe_set.h"
#include "effects/rbf_interpolator.h"
#include "effects/rbf_solve.h"
#include "effects/stack_interpolator.h"
#include "xr/headset/render_view.h"
#include "xr/render/param_grid.h"

namespace vdfx::app::bench {
namespace {

using effects::Keyframe;
using effects::RbfInterpolator;

constexpr double kFps = 30.0;
volatile double g_sink = 0.0;  // keeps timed results alive

/// The textbook peer: [A P; P^T 0] [w; c] = [F; 0] assembled whole and solved by partial-pivot
/// LU (what scipy's RBFInterpolator does with LAPACK), on the same centres and polynomial terms.
struct DenseSolution {
  effects::RbfPoints points;
  effects::PolynomialBasis basis;
  effects::RbfKernel kernel;
  Eigen::VectorXd w, c;
};

DenseSolution dense_solve(const std::vector<Keyframe>& k, const effects::InterpolationSettings& s) {
  DenseSolution d;
  d.kernel = effects::RbfKernel::from(s, kFps);
  d.points = effects::merge_keyframes(k, 1);
  d.basis = effects::select_polynomial_basis(d.points);
  const int m = d.points.size(), r = d.basis.size();
  Eigen::MatrixXd sys = Eigen::MatrixXd::Zero(m + r, m + r);
  sys.topLeftCorner(m, m) = effects::kernel_matrix(d.points, d.kernel);
  const Eigen::MatrixXd p = effects::polynomial_matrix(d.points, d.basis);
  sys.topRightCorner(m, r) = p;
  sys.bottomLeftCorner(r, m) = p.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + r);
  rhs.head(m) = d.points.values.col(0);
  const Eigen::VectorXd x = sys.partialPivLu().solve(rhs);
  d.w = x.head(m);
  d.c = x.tail(r);
  return d;
}

/// Term by term with the generic power function: the peer of the evaluation.
double dense_evaluate(const DenseSolution& d, const Eigen::Vector3d& n, std::int64_t frame) {
  const double t = static_cast<double>(frame - d.points.frame_origin);
  const double half_alpha = 0.5 * d.kernel.alpha;
  double sum = 0.0;
  for (int k = 0; k < d.points.size(); ++k) {
    const double dx = n.x() - d.points.x[k], dy = n.y() - d.points.y[k], dz = n.z() - d.points.z[k];
    const double dt = (t - d.points.t[k]) * d.kernel.time_factor;
    sum += d.w[k] * std::pow(dx * dx + dy * dy + dz * dz + dt * dt, half_alpha);
  }
  double row[5];
  d.basis.row(n, t, row);
  for (int j = 0; j < d.basis.size(); ++j) sum += d.c[j] * row[j];
  return sum;
}

/// Views inside the keyframes' frame span (so no evaluation is held at an end of it).
struct Views {
  std::vector<Eigen::Vector3d> unit;
  std::vector<std::int64_t> frame;
};
Views random_views(const std::vector<Keyframe>& k, int count) {
  std::int64_t lo = k.front().frame, hi = lo;
  for (const Keyframe& kf : k) {
    lo = std::min(lo, kf.frame);
    hi = std::max(hi, kf.frame);
  }
  Views v;
  for (const Keyframe& kf : random_keyframes(count, 0, 99, hi - lo)) {
    v.unit.push_back(effects::to_unit(kf.direction));
    v.frame.push_back(kf.frame + lo);
  }
  return v;
}

/// Max and RMS of a list of absolute errors.
ErrorStats stats_of(const std::vector<double>& e) {
  ErrorStats s{0.0, 0.0};
  for (double x : e) {
    s.max = std::max(s.max, std::abs(x));
    s.rms += x * x;
  }
  s.rms = e.empty() ? kNaN : std::sqrt(s.rms / static_cast<double>(e.size()));
  if (e.empty()) s.max = kNaN;
  return s;
}

/// How far an interpolant is from the keyframe values it must reproduce.
template <class Eval>
ErrorStats reproduction(const std::vector<Keyframe>& k, const Eval& eval) {
  std::vector<double> e;
  for (const Keyframe& kf : k)
    e.push_back(eval(effects::to_unit(kf.direction), kf.frame) - kf.params[0]);
  return stats_of(e);
}

std::shared_ptr<const DenseSolution> dense_for(int n) {
  static std::map<int, std::shared_ptr<const DenseSolution>> cache;
  auto& d = cache[n];
  if (!d) d = std::make_shared<DenseSolution>(dense_solve(random_keyframes(n, 1, 4), {}));
  return d;
}

void add_solve(Registry& r, bool quick) {
  r.knob({"rbf.solve",
          "full RBF solve against the keyframe count N (one parameter, frames 0..3000)", "solve",
          "parameter units (values 0..4)", "the keyframe values (reproduction at every keyframe)",
          "dense partial-pivot LU of the whole saddle system (textbook)", PlotError::Max, false,
          false});
  const std::vector<int> ns =
      quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 300, 1000, 3000, 4096};
  for (const int n : ns) {
    r.add("rbf.solve", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      const auto k = random_keyframes(n, 1, 4);
      const auto times = measure_pair(
          {[&] { g_sink = RbfInterpolator(k, 1, {}, kFps).diagnostics().max_residual; }},
          {[&] { g_sink = dense_solve(k, {}).w[0]; }}, ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      const RbfInterpolator rbf(k, 1, {}, kFps);
      row.error = reproduction(
          k, [&](const Eigen::Vector3d& u, std::int64_t f) { return rbf.evaluate(u, f)[0]; });
      const auto dense = dense_for(n);
      row.add("condition", rbf.diagnostics().condition_estimate);
      row.add("peer_max_error", reproduction(k, [&](const Eigen::Vector3d& u, std::int64_t f) {
                                  return dense_evaluate(*dense, u, f);
                                }).max);
      row.note =
          std::string("solver: ") + std::string(effects::to_string(rbf.diagnostics().method));
    });
  }
}

void add_eval(Registry& r, bool quick) {
  r.knob({"rbf.eval", "evaluation of one effect at a view against N", "view",
          "parameter units (values 0..4)",
          "interpolant of a dense LU solve of the whole system, evaluated term by term",
          "that reference's term-by-term evaluation (std::pow per centre)", PlotError::Max, false,
          false});
  const std::vector<int> ns =
      quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 4096};
  for (const int n : ns) {
    r.add("rbf.eval", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      const auto k = random_keyframes(n, 1, 4);
      const RbfInterpolator rbf(k, 1, {}, kFps);
      const auto dense = dense_for(n);
      const Views v = random_views(k, 256);
      const double units = static_cast<double>(v.unit.size());
      const auto times = measure_pair({[&] {
                                         double out = 0.0;
                                         for (std::size_t i = 0; i < v.unit.size(); ++i)
                                           rbf.evaluate_into(v.unit[i], v.frame[i], &out);
                                         g_sink = out;
                                       },
                                       units},
                                      {[&] {
                                         double s = 0.0;
                                         for (std::size_t i = 0; i < v.unit.size(); ++i)
                                           s += dense_evaluate(*dense, v.unit[i], v.frame[i]);
                                         g_sink = s;
                                       },
                                       units},
                                      ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      std::vector<double> e;
      for (std::size_t i = 0; i < v.unit.size(); ++i)
        e.push_back(rbf.evaluate(v.unit[i], v.frame[i])[0] -
                    dense_evaluate(*dense, v.unit[i], v.frame[i]));
      row.error = stats_of(e);
      row.add("condition", rbf.diagnostics().condition_estimate);
      row.note = "256 random views inside the frame span";
    });
  }
}

void add_incremental(Registry& r, bool quick) {
  r.knob({"rbf.add", "adding one keyframe to N by the O(N^2) bordered update", "add",
          "parameter units (values 0..4)",
          "a full solve of the same N + 1 keyframes (256 random views and every keyframe)",
          "that full solve of N + 1 keyframes", PlotError::Max, false, false});
  const std::vector<int> ns =
      quick ? std::vector<int>{100, 1000} : std::vector<int>{100, 1000, 3000};
  for (const int n : ns) {
    r.add("rbf.add", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      effects::KeyframeSetOptions opt;
      opt.async = false;
      effects::KeyframeSet set(1, {}, kFps, random_keyframes(n, 1, 2), opt);
      const auto extra = random_keyframes(4096, 1, 3);
      std::size_t i = 0;
      int full = 0, adds = 0;
      std::vector<Keyframe> with_one = set.keyframes();
      with_one.push_back(extra.back());
      const auto times = measure_pair(
          {[&] {
             const auto e = set.add(extra[i++ % (extra.size() - 1)]);
             full += e.incremental ? 0 : 1;
             ++adds;
           },
           1.0,
           [&] {  // back to N (untimed); an add that replaced a keyframe changed nothing to undo
             if (set.keyframes().size() > static_cast<std::size_t>(n))
               set.remove(set.keyframes().size() - 1);
           }},
          {[&] { g_sink = RbfInterpolator(with_one, 1, {}, kFps).diagnostics().max_residual; }},
          ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      set.add(extra.back());
      const auto inc = set.solution();
      const RbfInterpolator ref(set.keyframes(), 1, {}, kFps);
      const Views v = random_views(set.keyframes(), 256);
      std::vector<double> e;
      for (std::size_t j = 0; j < v.unit.size(); ++j)
        e.push_back(inc->evaluate(v.unit[j], v.frame[j])[0] -
                    ref.evaluate(v.unit[j], v.frame[j])[0]);
      for (const Keyframe& kf : set.keyframes())
        e.push_back(inc->evaluate(kf.direction, kf.frame)[0] -
                    ref.evaluate(kf.direction, kf.frame)[0]);
      row.error = stats_of(e);
      const auto st = set.stats();
      row.add("full_solve_fallbacks", full);
      row.add("refined_share", st.incremental_edits ? static_cast<double>(st.refinements) /
                                                          static_cast<double>(st.incremental_edits)
                                                    : 0.0);
      row.note = std::to_string(adds) + " adds, each undone untimed";
    });
  }
}

/// Bilinear lookup of the grid's exposure along a direction, as the GPU reads the grid texture:
/// cell centres at ((i + 0.5) / W, (j + 0.5) / H), repeating in azimuth, clamped at the poles.
double grid_stops(const xr::ParamGrid& g, const Eigen::Vector3d& unit) {
  const effects::Direction d = effects::from_unit(unit);
  const double x = (0.5 + d.azimuth_deg / 360.0) * g.width - 0.5;
  const double y = std::clamp((0.5 - d.altitude_deg / 180.0) * g.height - 0.5, 0.0, g.height - 1.0);
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const int i0 = ((static_cast<int>(fx) % g.width) + g.width) % g.width, i1 = (i0 + 1) % g.width;
  const int j0 = static_cast<int>(fy), j1 = std::min(j0 + 1, g.height - 1);
  const auto s = [&](int i, int j) { return g.at(i, j).exposure_stops; };
  return (1 - ay) * ((1 - ax) * s(i0, j0) + ax * s(i1, j0)) +
         ay * ((1 - ax) * s(i0, j1) + ax * s(i1, j1));
}

/// An exposure field of 30 keyframes at frame 0 (stops in [-2, 2]) and the rays of an eye.
struct GridFixture {
  std::unique_ptr<effects::StackInterpolator> stack;
  std::vector<Eigen::Vector3d> rays;
  int w = 0, h = 0;
};
const GridFixture& grid_fixture(bool quick) {
  static std::map<bool, GridFixture> cache;
  GridFixture& f = cache[quick];
  if (f.stack) return f;
  effects::EffectTrack t;
  t.type = effects::EffectType::Exposure;
  t.keyframes = random_keyframes(30, 1, 11, 0);
  for (Keyframe& k : t.keyframes) k.params[0] -= 2.0;
  f.stack = std::make_unique<effects::StackInterpolator>(std::vector<effects::EffectTrack>{t},
                                                         effects::InterpolationSettings{}, kFps);
  f.w = quick ? 360 : 720;
  f.h = quick ? 400 : 800;
  const xr::RenderView eye = xr::RenderView::look_at({30.0, 10.0}, 0.0, 100.0, f.w, f.h);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x)
      f.rays.push_back(eye.world_ray(x + 0.5, y + 0.5, f.w, f.h).normalized());
  return f;
}

void add_grid(Registry& r, bool quick) {
  r.knob({"rbf.grid",
          "per-pixel mode: parameters baked on an equirect grid, read bilinearly per pixel", "view",
          "stops (exposure)", "exact RBF evaluation at every pixel's own ray",
          "that exact evaluation at every pixel (CPU)", PlotError::Max, false});
  const std::vector<std::pair<int, int>> sizes =
      quick ? std::vector<std::pair<int, int>>{{64, 32}, {256, 128}, {1024, 512}}
            : std::vector<std::pair<int, int>>{{16, 8},    {64, 32},   {128, 64},
                                               {256, 128}, {512, 256}, {1024, 512}};
  for (const auto& size : sizes) {
    const int gw = size.first, gh = size.second;  // clang 14 cannot capture structured bindings
    r.add(
        "rbf.grid", std::to_string(gw) + "x" + std::to_string(gh),
        [gw, gh](Row& row, const Context& ctx) {
          const GridFixture& f = grid_fixture(ctx.quick);
          const auto at = [&](const effects::Direction& d) { return f.stack->evaluate(d, 0); };
          const auto times = measure_pair({[&] {
                                            const xr::ParamGrid g = xr::bake_param_grid(at, gw, gh);
                                            double s = 0.0;
                                            for (const auto& ray : f.rays) s += grid_stops(g, ray);
                                            g_sink = s;
                                          }},
                                          {[&] {
                                            double s = 0.0;
                                            for (const auto& ray : f.rays)
                                              s += f.stack->evaluate(ray, 0).exposure_stops;
                                            g_sink = s;
                                          }},
                                          ctx.budget);
          row.time = times.subject;
          row.peer_time = times.peer;
          const xr::ParamGrid g = xr::bake_param_grid(at, gw, gh);
          std::vector<double> e;
          for (const auto& ray : f.rays)
            e.push_back(grid_stops(g, ray) - f.stack->evaluate(ray, 0).exposure_stops);
          row.error = stats_of(e);
          row.note = "CPU bake + lookups for a " + std::to_string(f.w) + "x" + std::to_string(f.h) +
                     " eye (100 deg); 30 exposure keyframes, stops in [-2, 2]";
        });
  }
}

/// A solve with other interpolation settings, timed beside the default ones.
void conditioning_case(Row& row, const Context& ctx, const std::vector<Keyframe>& k,
                       const effects::InterpolationSettings& s,
                       const effects::InterpolationSettings& peer) {
  const auto times = measure_pair(
      {[&] { g_sink = RbfInterpolator(k, 1, s, kFps).diagnostics().max_residual; }},
      {[&] { g_sink = RbfInterpolator(k, 1, peer, kFps).diagnostics().max_residual; }}, ctx.budget);
  row.time = times.subject;
  row.peer_time = times.peer;
  const RbfInterpolator rbf(k, 1, s, kFps);
  row.error = reproduction(
      k, [&](const Eigen::Vector3d& u, std::int64_t f) { return rbf.evaluate(u, f)[0]; });
  row.add("condition", rbf.diagnostics().condition_estimate);
  row.note = std::string("solver: ") + std::string(effects::to_string(rbf.diagnostics().method));
}

/// A knob of solves under other interpolation settings, each timed beside `peer` settings:
/// conditioning and keyframe reproduction (exponent, time scale).
struct ConditioningKnob {
  std::string id, title, peer, label;  //!< label: the setting's name before its value
  std::string title_end;               //!< after the keyframe count in the title
  std::vector<double> values;
  std::int64_t max_frame;
  std::uint64_t seed;
  std::function<void(effects::InterpolationSettings&, double)> set;
  effects::InterpolationSettings peer_settings;
  bool report_time_scale = false;  //!< add the contract's c to each row
};

void add_conditioning(Registry& r, bool quick, const ConditioningKnob& k) {
  const int n = quick ? 100 : 300;
  r.knob({k.id,
          k.title + ", N = " + std::to_string(n) + " keyframes over frames 0.." +
              std::to_string(k.max_frame) + k.title_end,
          "solve", "parameter units (values 0..4)",
          "the keyframe values (reproduction at every keyframe)", k.peer, PlotError::Max, false});
  for (const double v : k.values) {
    r.add(k.id, k.label + "=" + setting_number(v), [k, v, n](Row& row, const Context& ctx) {
      effects::InterpolationSettings s;
      k.set(s, v);
      conditioning_case(row, ctx, random_keyframes(n, 1, k.seed, k.max_frame), s, k.peer_settings);
      if (k.report_time_scale) row.add("time_scale_c", s.time_scale);
    });
  }
}

void add_exponent(Registry& r, bool quick) {
  add_conditioning(r, quick,
                   {"rbf.exponent",
                    "kernel exponent alpha (phi = d^alpha; 2: thin plate)",
                    "the solve with alpha = 1 (the default)",
                    "alpha",
                    "",
                    quick ? std::vector<double>{0.5, 1, 1.99, 2, 3}
                          : std::vector<double>{0.25, 0.5, 1, 1.5, 1.99, 2, 3},
                    300,
                    7,
                    [](effects::InterpolationSettings& s, double a) { s.exponent = a; },
                    {}});
}

void add_time_scale(Registry& r, bool quick) {
  effects::InterpolationSettings peer;
  peer.time_scale = effects::kAuthorTimeScale;
  add_conditioning(
      r, quick,
      {"rbf.time_scale", "time scale D (1 s of video weighs like D degrees)",
       "the solve with the author's default D = 2", "D", " at 30 fps",
       quick ? std::vector<double>{0.1, 2, 1375} : std::vector<double>{0.1, 2, 20, 1375, 13751},
       3000, 8,
       [](effects::InterpolationSettings& s, double d) {
         s.time_scale = effects::time_scale_from_deg_per_s(d);
       },
       peer, true});
}

}  // namespace

void add_rbf_knobs(Registry& r, bool quick) {
  add_solve(r, quick);
  add_eval(r, quick);
  add_incremental(r, quick);
  add_grid(r, quick);
  add_exponent(r, quick);
  add_time_scale(r, quick);
}

}  // namespace vdfx::app::bench
