/// @file
/// @brief RBF knobs of `vdfx bench` at film scale (docs/interpolation.md, "Local interpolation"):
/// one effect with N keyframes over 20 minutes at 30 fps, its cold solve, one evaluation, an
/// editor's add and move and the memory they take, each beside today's global scheme at
/// N = 1000; and the reach, local interpolation's knob: its solve time against its deviation
/// from the global solve (max and RMS), for the contract's time scale and the author's.
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bench/inputs.h"
#include "app/bench/registry.h"
#include "app/bench/timing.h"
#include "effects/coords.h"
#include "effects/keyframe_set.h"
#include "effects/rbf_interpolator.h"
#include "effects/rbf_solve.h"

namespace vdfx::app::bench {
namespace {

using effects::Keyframe;
using effects::RbfInterpolator;

constexpr double kFps = 30.0;
constexpr std::int64_t kFilmFrames = 20 * 60 * 30;  // 20 minutes at 30 fps
volatile double g_sink = 0.0;

/// N keyframes (one parameter in [0, 4]) over the film, from a cache (one set per N).
const std::vector<Keyframe>& film(int n) {
  static std::map<int, std::vector<Keyframe>> cache;
  auto& k = cache[n];
  if (k.empty()) k = random_keyframes(n, 1, 31, kFilmFrames - 1);
  return k;
}

/// A process's resident-set line of /proc/self/status ("VmRSS:", "VmHWM:"), kilobytes.
long status_kb(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key, 0) == 0) return std::stol(line.substr(std::string(key).size()));
  return -1;
}

/// The memory `fn` takes at its peak, MB: run in a forked child that first returns its free heap
/// memory to the system and resets its peak resident set (/proc/self/clear_refs), so nothing
/// this process held before counts. NaN when it cannot be measured.
double peak_memory_mb(const std::function<void()>& fn) {
  int fd[2];
  if (pipe(fd) != 0) return kNaN;
  const pid_t pid = fork();
  if (pid < 0) return kNaN;
  if (pid == 0) {
    close(fd[0]);
    malloc_trim(0);  // free heap memory the parent left resident would hide new allocations
    { std::ofstream("/proc/self/clear_refs") << "5"; }
    const long before = status_kb("VmRSS:");
    fn();
    const double mb = static_cast<double>(status_kb("VmHWM:") - before) / 1024.0;
    const bool ok = write(fd[1], &mb, sizeof mb) == static_cast<ssize_t>(sizeof mb);
    _exit(ok ? 0 : 1);
  }
  close(fd[1]);
  double mb = kNaN;
  if (read(fd[0], &mb, sizeof mb) != static_cast<ssize_t>(sizeof mb)) mb = kNaN;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return mb;
}

/// Max and RMS of |a - b| over `count` random views inside the frame span.
ErrorStats deviation(const RbfInterpolator& a, const RbfInterpolator& b,
                     const std::vector<Keyframe>& k, int count) {
  std::int64_t lo = k.front().frame, hi = lo;
  for (const Keyframe& kf : k) lo = std::min(lo, kf.frame), hi = std::max(hi, kf.frame);
  ErrorStats s{0.0, 0.0};
  for (const Keyframe& v : random_keyframes(count, 1, 77, hi - lo)) {
    const Eigen::Vector3d u = effects::to_unit(v.direction);
    const double d = a.evaluate(u, v.frame + lo)[0] - b.evaluate(u, v.frame + lo)[0];
    s.max = std::max(s.max, std::abs(d));
    s.rms += d * d;
  }
  s.rms = std::sqrt(s.rms / count);
  return s;
}

/// Largest |value - keyframe value| over up to 2000 of the keyframes (a stride through them).
ErrorStats reproduction(const RbfInterpolator& rbf, const std::vector<Keyframe>& k) {
  ErrorStats s{0.0, 0.0};
  const std::size_t stride = std::max<std::size_t>(1, k.size() / 2000);
  double n = 0.0;
  for (std::size_t i = 0; i < k.size(); i += stride) {
    const double d = rbf.evaluate(k[i].direction, k[i].frame)[0] - k[i].params[0];
    s.max = std::max(s.max, std::abs(d));
    s.rms += d * d;
    n += 1.0;
  }
  s.rms = std::sqrt(s.rms / n);
  return s;
}

/// The global solve of keyframes above the automatic threshold (the reach knob's reference),
/// from the solver directly.
std::shared_ptr<const RbfInterpolator> global_solve(const std::vector<Keyframe>& k,
                                                    const effects::InterpolationSettings& s) {
  effects::RbfPoints p = effects::merge_keyframes(k, 1);
  effects::PolynomialBasis basis = effects::select_polynomial_basis(p);
  const effects::RbfKernel kernel = effects::RbfKernel::from(s, kFps);
  const effects::RbfSolution sol = effects::solve_rbf(p, kernel, basis);
  return std::make_shared<const RbfInterpolator>(std::move(p), kernel, std::move(basis), sol,
                                                 Eigen::VectorXd::Zero(1));
}

/// A smooth field over the sphere and time (frames): what the knob's field columns interpolate.
double smooth_field(const Eigen::Vector3d& n, std::int64_t frame) {
  const double f = static_cast<double>(frame);
  return std::sin(f / 600.0) * n.x() + 0.5 * std::cos(f / 210.0) * n.y() + 0.3 * n.z();
}

/// The keyframes with the smooth field's values at their places.
std::vector<Keyframe> on_field(std::vector<Keyframe> k) {
  for (Keyframe& kf : k) kf.params[0] = smooth_field(effects::to_unit(kf.direction), kf.frame);
  return k;
}

/// RMS of an interpolant of on_field() keyframes against the field itself, at random views.
double field_rms(const RbfInterpolator& rbf, const std::vector<Keyframe>& k, int count) {
  std::int64_t lo = k.front().frame, hi = lo;
  for (const Keyframe& kf : k) lo = std::min(lo, kf.frame), hi = std::max(hi, kf.frame);
  double sum = 0.0;
  for (const Keyframe& v : random_keyframes(count, 1, 81, hi - lo)) {
    const Eigen::Vector3d u = effects::to_unit(v.direction);
    const double d = rbf.evaluate(u, v.frame + lo)[0] - smooth_field(u, v.frame + lo);
    sum += d * d;
  }
  return std::sqrt(sum / count);
}

void describe(Row& row, const RbfInterpolator& rbf) {
  row.add("windows", rbf.local() ? rbf.layout().count : 1);
  row.add("reach_s", rbf.local() ? rbf.layout().width / kFps : kNaN);
  row.note =
      rbf.local() ? "local (reach " + std::to_string(rbf.layout().width / kFps) + " s)" : "global";
}

/// The subject's CPU time per unit beside the wall time of the same `runs` runs (columns cpu_s
/// and cpu_wall_s): on the shared machine a wall time includes waits for a core.
void add_cpu(Row& row, const Timed& subject, int runs) {
  const CpuWall c = measure_cpu(subject, runs);
  row.add("cpu_s", c.cpu_s);
  row.add("cpu_wall_s", c.wall_s);
}

void add_film_solve(Registry& r, const std::vector<int>& ns) {
  r.knob({"rbf.film_solve",
          "one effect's cold solve against N keyframes over 20 minutes at 30 fps (time_scale 1; "
          "global up to 4096, local above)",
          "solve", "parameter units (values 0..4)",
          "the keyframe values (reproduction at up to 2000 keyframes)",
          "the global solve of N = 1000 (the scheme before local interpolation)", PlotError::Max,
          false, false});
  for (const int n : ns) {
    r.add("rbf.film_solve", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      const auto& k = film(n);
      const auto& base = film(1000);
      const Timed subject{
          [&] { g_sink = RbfInterpolator(k, 1, {}, kFps).diagnostics().max_residual; }};
      const auto times = measure_pair(
          subject,
          {[&] { g_sink = RbfInterpolator(base, 1, {}, kFps).diagnostics().max_residual; }},
          ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      add_cpu(row, subject, 2);
      const RbfInterpolator rbf(k, 1, {}, kFps);
      row.error = reproduction(rbf, k);
      describe(row, rbf);
      row.add("memory_mb",
              peak_memory_mb([&] { g_sink = RbfInterpolator(k, 1, {}, kFps).centres(); }));
    });
  }
}

void add_film_eval(Registry& r, const std::vector<int>& ns) {
  r.knob({"rbf.film_eval", "one effect's evaluation at a view against N keyframes over 20 minutes",
          "view", "parameter units (values 0..4)",
          "the keyframe values (reproduction at up to 2000 keyframes)",
          "evaluation of the global solve of N = 1000", PlotError::Max, false, false});
  for (const int n : ns) {
    r.add("rbf.film_eval", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      const auto& k = film(n);
      const RbfInterpolator rbf(k, 1, {}, kFps);
      const RbfInterpolator base(film(1000), 1, {}, kFps);
      const auto views = random_keyframes(256, 1, 78, kFilmFrames - 1);
      std::vector<Eigen::Vector3d> units;
      for (const Keyframe& v : views) units.push_back(effects::to_unit(v.direction));
      const auto eval_all = [&](const RbfInterpolator& e) {
        double out = 0.0, s = 0.0;
        for (std::size_t i = 0; i < units.size(); ++i) {
          e.evaluate_into(units[i], views[i].frame, &out);
          s += out;
        }
        g_sink = s;
      };
      const double per = static_cast<double>(units.size());
      const Timed subject{[&] { eval_all(rbf); }, per};
      const auto times = measure_pair(subject, {[&] { eval_all(base); }, per}, ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      add_cpu(row, subject, 200);
      row.error = reproduction(rbf, k);
      describe(row, rbf);
    });
  }
}

/// An editor's edit of a set of N: `add` a keyframe (undone untimed) or move one by a few
/// frames and degrees (moved back untimed), beside the same edit of N = 1000 (global).
void add_film_edit(Registry& r, const std::vector<int>& ns, bool move) {
  const std::string id = move ? "rbf.film_move" : "rbf.film_add";
  r.knob({id,
          std::string(move ? "moving" : "adding") +
              " one keyframe of N over 20 minutes in the editor's KeyframeSet",
          move ? "move" : "add", "parameter units (values 0..4)",
          "a fresh solve of the same keyframes (256 random views)",
          std::string("the same edit of N = 1000 (global: the O(N^2) bordered update)"),
          PlotError::Max, false, false});
  for (const int n : ns) {
    r.add(id, "N=" + std::to_string(n), [n, move](Row& row, const Context& ctx) {
      effects::KeyframeSetOptions opt;
      opt.async = false;
      effects::KeyframeSet set(1, {}, kFps, film(n), opt), base(1, {}, kFps, film(1000), opt);
      const auto extra = random_keyframes(512, 1, 79, kFilmFrames - 1);
      std::size_t i = 0, j = 0;
      const auto edit = [&](effects::KeyframeSet& s, std::size_t& c) {
        const Keyframe& e = extra[c++ % extra.size()];
        if (!move) {
          s.add(e);
          return;
        }
        const std::size_t at = (c * 7919) % s.keyframes().size();
        const Keyframe& kf = s.keyframes()[at];
        s.move(at,
               {effects::wrap_azimuth_deg(kf.direction.azimuth_deg + 5.0),
                0.9 * kf.direction.altitude_deg},
               std::clamp<std::int64_t>(kf.frame + 3, 0, kFilmFrames - 1));
      };
      const auto undo = [&](effects::KeyframeSet& s, std::size_t size0,
                            const std::vector<Keyframe>& original, std::size_t c) {
        if (!move) {
          if (s.keyframes().size() > size0) s.remove(s.keyframes().size() - 1);
          return;
        }
        const std::size_t at = (c * 7919) % s.keyframes().size();
        s.move(at, original[at].direction, original[at].frame);
      };
      const Timed subject{[&] { edit(set, i); }, 1.0,
                          [&] { undo(set, film(n).size(), film(n), i); }};
      const auto times = measure_pair(
          subject, {[&] { edit(base, j); }, 1.0, [&] { undo(base, 1000, film(1000), j); }},
          ctx.budget);
      row.time = times.subject;
      row.peer_time = times.peer;
      add_cpu(row, subject, 20);
      edit(set, i);
      const RbfInterpolator fresh(set.keyframes(), 1, {}, kFps);
      row.error = deviation(*set.solution(), fresh, set.keyframes(), 256);
      describe(row, *set.solution());
      const auto st = set.stats();
      row.add("windows_solved_per_edit", st.local_edits ? static_cast<double>(st.windows_solved) /
                                                              static_cast<double>(st.local_edits)
                                                        : kNaN);
      row.add("memory_mb", peak_memory_mb([&] {
                effects::KeyframeSet s(1, {}, kFps, film(n), opt);
                g_sink = static_cast<double>(s.keyframes().size());
              }));
    });
  }
}

/// The reach knob: N keyframes at the density of 100000 over 20 minutes (2.78 a frame).
void add_reach(Registry& r, bool quick) {
  const int n = quick ? 1000 : 4200;
  const std::int64_t frames = n * kFilmFrames / 100000;
  r.knob({"rbf.reach",
          "local interpolation's reach (window width) against the deviation from the global "
          "solve, N = " +
              std::to_string(n) + " over " + std::to_string(frames) +
              " frames (the density of 100000 keyframes over 20 minutes)",
          "solve", "parameter units (values 0..4)",
          "the global solve of the same keyframes (1000 random views)", "that global solve",
          PlotError::Rms, false, true});
  const std::vector<double> reaches =
      quick ? std::vector<double>{0.25, 1.0, 4.0}
            : std::vector<double>{0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0};
  for (const bool author : {false, true}) {
    effects::InterpolationSettings base;
    if (author) base.time_scale = effects::kAuthorTimeScale;
    const std::string series = author ? "D=2 (author)" : "c=1 (contract)";
    std::vector<std::pair<std::string, std::optional<double>>> settings;
    for (const double reach : reaches)
      settings.emplace_back("reach " + std::to_string(reach).substr(0, 5) + " s", reach);
    if (!quick) settings.emplace_back("auto", std::nullopt);
    for (const auto& [label, reach] : settings) {
      const std::optional<double> rs = reach;
      r.add("rbf.reach", series + ", " + label,
            [n, frames, base, rs, series](Row& row, const Context& ctx) {
              row.series = series;
              const auto k = random_keyframes(n, 1, 32, frames - 1);
              effects::InterpolationSettings s = base;
              s.reach_s = rs;
              if (!rs && k.size() <= effects::kGlobalSolveMaxKeyframes)
                throw std::runtime_error("the automatic reach needs more than 4096 keyframes");
              Budget b = ctx.budget;
              b.min_samples = std::min(b.min_samples, 3);
              const auto times = measure_pair(
                  {[&] { g_sink = RbfInterpolator(k, 1, s, kFps).diagnostics().max_residual; }},
                  {[&] { g_sink = global_solve(k, base)->diagnostics().max_residual; }}, b);
              row.time = times.subject;
              row.peer_time = times.peer;
              const RbfInterpolator local(k, 1, s, kFps);
              const auto global = global_solve(k, base);
              row.error = deviation(local, *global, k, 1000);
              describe(row, local);
              row.add("reproduction_max", reproduction(local, k).max);
              // Both schemes against a smooth field they interpolate (the global solve once a
              // series).
              static std::map<std::string, double> global_field;
              const auto field = on_field(k);
              if (!global_field.count(series))
                global_field[series] = field_rms(*global_solve(field, base), field, 1000);
              row.add("field_rms_local",
                      field_rms(RbfInterpolator(field, 1, s, kFps), field, 1000));
              row.add("field_rms_global", global_field[series]);
              const auto views = random_keyframes(256, 1, 80, frames - 1);
              const auto t =
                  measure({[&] {
                             double out = 0.0, sum = 0.0;
                             for (const Keyframe& v : views) {
                               local.evaluate_into(effects::to_unit(v.direction), v.frame, &out);
                               sum += out;
                             }
                             g_sink = sum;
                           },
                           256.0},
                          b);
              row.add("eval_us", t.median_s * 1e6);
            });
    }
  }
}

}  // namespace

void add_rbf_film_knobs(Registry& r, bool quick) {
  const std::vector<int> ns =
      quick ? std::vector<int>{1000, 10000} : std::vector<int>{1000, 10000, 100000};
  add_film_solve(r, ns);
  add_film_eval(r, ns);
  add_film_edit(r, ns, false);
  add_film_edit(r, ns, true);
  add_reach(r, quick);
}

}  // namespace vdfx::app::bench
