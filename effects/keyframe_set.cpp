/// @file
/// @brief KeyframeSet: replace-on-top editing, bordered inverse updates, asynchronous re-solves.
#include "effects/keyframe_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

/// The state the O(N^2) updates work on. Centres are in "slot" order: the inverse and z are
/// ordered [polynomial (r); centres (m)], and centres are removed by moving the last into place.
struct KeyframeSet::State {
  std::uint64_t version = 0;
  RbfPoints points;
  PolynomialBasis basis;
  Eigen::MatrixXd inverse;  //!< (r + m)^2 inverse of [0 P^T; P A]
  Eigen::MatrixXd z;        //!< (r + m) x D: [c; w]
  std::vector<int> centre_of_keyframe;
  std::vector<int> keyframe_of_centre;
  RbfDiagnostics diagnostics;
  std::shared_ptr<const RbfInterpolator> interpolator;

  int r() const { return basis.size(); }
  int m() const { return points.size(); }
};

namespace {

std::shared_ptr<const RbfInterpolator> make_interpolator(const RbfPoints& points,
                                                         const RbfKernel& kernel,
                                                         const PolynomialBasis& basis,
                                                         const Eigen::MatrixXd& z,
                                                         const RbfDiagnostics& diagnostics,
                                                         const Eigen::VectorXd& neutral) {
  RbfSolution s;
  s.coefficients = z.topRows(basis.size());
  s.weights = z.bottomRows(points.size());
  s.diagnostics = diagnostics;
  return std::make_shared<const RbfInterpolator>(points, kernel, basis, s, neutral);
}

}  // namespace

/// Full solve; the returned state has an empty inverse when keyframes had to be merged (the
/// incremental path keeps one centre per keyframe).
std::unique_ptr<KeyframeSet::State> KeyframeSet::solve_full(const std::vector<Keyframe>& keyframes,
                                                            int dimension, const RbfKernel& kernel,
                                                            const Eigen::VectorXd& neutral,
                                                            std::uint64_t version) {
  auto st = std::make_unique<KeyframeSet::State>();
  st->version = version;
  st->points = merge_keyframes(keyframes, dimension);
  st->basis = select_polynomial_basis(st->points);
  const bool exact = st->points.merged() == 0;
  const RbfSolution s = solve_rbf(st->points, kernel, st->basis, exact ? &st->inverse : nullptr);
  st->z.resize(st->r() + st->m(), dimension);
  st->z.topRows(st->r()) = s.coefficients;
  st->z.bottomRows(st->m()) = s.weights;
  st->diagnostics = s.diagnostics;
  st->centre_of_keyframe = st->points.point_of_keyframe;
  st->keyframe_of_centre.assign(static_cast<size_t>(st->m()), -1);
  for (size_t k = 0; k < st->centre_of_keyframe.size(); ++k)
    st->keyframe_of_centre[static_cast<size_t>(st->centre_of_keyframe[k])] = static_cast<int>(k);
  st->interpolator = make_interpolator(st->points, kernel, st->basis, st->z,
                                       st->diagnostics, neutral);
  return st;
}

struct KeyframeSet::Worker {
  std::mutex mu;
  std::condition_variable cv;
  std::optional<std::pair<std::uint64_t, std::vector<Keyframe>>> job;  // latest only
  bool stop = false;
  std::thread thread;
};

KeyframeSet::KeyframeSet(int dimension, const InterpolationSettings& settings, double fps,
                         std::vector<Keyframe> keyframes, KeyframeSetOptions options,
                         std::vector<double> neutral)
    : dimension_(dimension),
      settings_(settings),
      fps_(fps),
      kernel_(RbfKernel::from(settings, fps)),
      options_(options),
      keyframes_(std::move(keyframes)) {
  // RbfInterpolator validates dimension and neutral the same way.
  neutral_ = RbfInterpolator({}, dimension, settings, fps, std::move(neutral)).neutral();
  auto st = solve_full(keyframes_, dimension_, kernel_, neutral_, 0);
  publish(st->interpolator, 0);
  if (!st->inverse.size() && st->m() > 0) st.reset();
  state_ = std::move(st);
  if (options_.async) {
    worker_ = std::make_unique<Worker>();
    worker_->thread = std::thread([this] {
      Worker& w = *worker_;
      for (;;) {
        std::pair<std::uint64_t, std::vector<Keyframe>> job;
        {
          std::unique_lock lock(w.mu);
          w.cv.wait(lock, [&] { return w.stop || w.job.has_value(); });
          if (w.stop) return;
          job = std::move(*w.job);
          w.job.reset();
        }
        auto st = solve_full(job.second, dimension_, kernel_, neutral_, job.first);
        publish(st->interpolator, job.first);
        std::lock_guard lock(pub_mu_);
        if (st->inverse.size() || st->m() == 0) ready_ = std::move(st);
      }
    });
  }
}

KeyframeSet::~KeyframeSet() {
  if (worker_) {
    {
      std::lock_guard lock(worker_->mu);
      worker_->stop = true;
    }
    worker_->cv.notify_all();
    worker_->thread.join();
  }
}

void KeyframeSet::publish(std::shared_ptr<const RbfInterpolator> s, std::uint64_t version) const {
  {
    std::lock_guard lock(pub_mu_);
    if (published_ && version < published_version_) return;  // a stale worker result
    published_ = std::move(s);
    published_version_ = version;
  }
  pub_cv_.notify_all();
}

std::shared_ptr<const RbfInterpolator> KeyframeSet::solution() const {
  std::lock_guard lock(pub_mu_);
  return published_;
}

std::uint64_t KeyframeSet::solution_version() const {
  std::lock_guard lock(pub_mu_);
  return published_version_;
}

bool KeyframeSet::wait_for_version(std::uint64_t version,
                                   std::chrono::milliseconds timeout) const {
  std::unique_lock lock(pub_mu_);
  return pub_cv_.wait_for(lock, timeout, [&] { return published_version_ >= version; });
}

void KeyframeSet::adopt_worker_result() {
  std::lock_guard lock(pub_mu_);
  if (ready_ && ready_->version == version_) state_ = std::move(ready_);
  ready_.reset();
}

std::optional<std::size_t> KeyframeSet::find_coincident(const Direction& d, std::int64_t frame,
                                                        std::optional<std::size_t> skip) const {
  const Eigen::Vector3d n = to_unit(d);
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    if (skip && *skip == i) continue;
    if (keyframes_[i].frame != frame) continue;
    if (angle_between(n, to_unit(keyframes_[i].direction)) <= kReplaceAngleDeg * kDegToRad)
      return i;
  }
  return std::nullopt;
}

bool KeyframeSet::try_add_centre(std::size_t ki) {
  State& st = *state_;
  const Keyframe& kf = keyframes_[ki];
  const int r = st.r(), m = st.m(), n = r + m;
  const Eigen::Vector3d dir = to_unit(kf.direction);
  const double t = static_cast<double>(kf.frame - st.points.frame_origin);
  Eigen::VectorXd b(n);
  st.basis.row(dir, t, b.data());
  Eigen::ArrayXd krow(m);
  kernel_row(st.points, kernel_, dir, t, krow);
  b.tail(m) = krow.matrix();
  const Eigen::VectorXd u = st.inverse * b;
  const double s = -b.dot(u);  // Schur complement: phi(0) - b^T M^-1 b, phi(0) = 0
  if (!(std::abs(s) > 1e-13 * b.norm() * u.norm())) return false;
  const Eigen::RowVectorXd v = Eigen::Map<const Eigen::RowVectorXd>(kf.params.data(), dimension_);
  const Eigen::RowVectorXd bz = b.transpose() * st.z;
  Eigen::MatrixXd inv(n + 1, n + 1);
  inv.topLeftCorner(n, n) = st.inverse + u * (u.transpose() / s);
  inv.col(n).head(n) = -u / s;
  inv.row(n).head(n) = -u.transpose() / s;
  inv(n, n) = 1.0 / s;
  st.inverse.swap(inv);
  Eigen::MatrixXd z(n + 1, dimension_);
  z.topRows(n) = st.z + u * ((bz - v) / s);
  z.row(n) = (v - bz) / s;
  st.z.swap(z);
  st.points.append(dir, kf.frame, v);
  st.keyframe_of_centre.push_back(static_cast<int>(ki));
  st.centre_of_keyframe[ki] = m;
  return true;
}

bool KeyframeSet::try_remove_centre(std::size_t ki) {
  State& st = *state_;
  const int r = st.r(), m = st.m();
  const int c = st.centre_of_keyframe[ki];
  if (m <= 1 || c < 0) return false;
  const int j = r + c, last = r + m - 1;
  if (!(std::abs(st.inverse(j, j)) > 0.0)) return false;
  // Move the centre to the last slot, then take the Schur complement of that slot.
  st.inverse.row(j).swap(st.inverse.row(last));
  st.inverse.col(j).swap(st.inverse.col(last));
  st.z.row(j).swap(st.z.row(last));
  const double beta = st.inverse(last, last);
  const Eigen::VectorXd col = st.inverse.col(last).head(last);
  Eigen::MatrixXd inv = st.inverse.topLeftCorner(last, last) - col * (col.transpose() / beta);
  st.inverse.swap(inv);
  Eigen::MatrixXd z = st.z.topRows(last) - col * (st.z.row(last) / beta);
  st.z.swap(z);
  const int moved = st.keyframe_of_centre[static_cast<size_t>(m - 1)];
  st.points.swap_remove(c);
  st.keyframe_of_centre[static_cast<size_t>(c)] = moved;
  st.keyframe_of_centre.pop_back();
  st.centre_of_keyframe[static_cast<size_t>(moved)] = c;
  st.centre_of_keyframe[ki] = -1;
  return true;
}

bool KeyframeSet::finish_incremental(int checked_centre) {
  State& st = *state_;
  // The active polynomial terms must be those a full solve would choose.
  if (!select_polynomial_basis(st.points).same_columns(st.basis)) return false;
  const int m = st.m(), r = st.r();
  {
    // One refinement step with the full residual (O(N^2) kernel evaluations): the explicit
    // inverse carries ~cond * eps error after each update, and this keeps it from accumulating.
    const Eigen::MatrixXd p = polynomial_matrix(st.points, st.basis);
    Eigen::MatrixXd res(r + m, dimension_);
    res.topRows(r) = -(p.transpose() * st.z.bottomRows(m));
    Eigen::ArrayXd krow(m);
    for (int i = 0; i < m; ++i) {
      kernel_row(st.points, kernel_, st.points.unit(i), st.points.t[i], krow);
      res.row(r + i) = st.points.values.row(i) - krow.matrix().transpose() * st.z.bottomRows(m) -
                       p.row(i) * st.z.topRows(r);
    }
    st.z += st.inverse * res;
  }
  std::vector<int> rows;
  if (checked_centre >= 0) rows.push_back(checked_centre);
  const int samples = std::min(m, 32);
  for (int i = 0; i < samples; ++i) rows.push_back(static_cast<int>((static_cast<long>(i) * m) / samples));
  const Eigen::MatrixXd w = st.z.bottomRows(m), c = st.z.topRows(st.r());
  const double res = rbf_residual(st.points, kernel_, st.basis, w, c, rows);
  const double scale = st.points.values.cwiseAbs().maxCoeff();
  if (!(res <= options_.residual_tolerance * std::max(scale, 1e-300))) return false;
  st.version = version_;
  st.diagnostics.keyframes = st.diagnostics.centres = m;
  st.diagnostics.merged = 0;
  st.diagnostics.max_residual = res;
  st.diagnostics.relative_residual = scale > 0 ? res / scale : res;
  st.interpolator =
      make_interpolator(st.points, kernel_, st.basis, st.z, st.diagnostics, neutral_);
  publish(st.interpolator, version_);
  return true;
}

void KeyframeSet::full_solve() {
  state_.reset();
  if (!worker_ || static_cast<int>(keyframes_.size()) <= options_.inline_full_solve_max) {
    auto st = solve_full(keyframes_, dimension_, kernel_, neutral_, version_);
    publish(st->interpolator, version_);
    if (st->inverse.size() || st->m() == 0) state_ = std::move(st);
    return;
  }
  {
    std::lock_guard lock(worker_->mu);
    worker_->job.emplace(version_, keyframes_);
  }
  worker_->cv.notify_one();
}

namespace {
void check_params(const Keyframe& k, int dimension) {
  if (static_cast<int>(k.params.size()) != dimension)
    throw std::invalid_argument("KeyframeSet: keyframe has " + std::to_string(k.params.size()) +
                                " parameters, expected " + std::to_string(dimension));
  for (double v : k.params)
    if (!std::isfinite(v)) throw std::invalid_argument("KeyframeSet: non-finite parameter");
}
}  // namespace

KeyframeSet::Edit KeyframeSet::add(Keyframe keyframe) {
  check_params(keyframe, dimension_);
  adopt_worker_result();
  ++version_;
  Edit e;
  const auto hit = find_coincident(keyframe.direction, keyframe.frame, std::nullopt);
  bool ok = state_ && state_->m() > 0;
  if (hit) {
    e.index = *hit;
    e.replaced = *hit;
    keyframes_[*hit] = std::move(keyframe);
    ok = ok && try_remove_centre(*hit) && try_add_centre(*hit);
  } else {
    e.index = keyframes_.size();
    keyframes_.push_back(std::move(keyframe));
    if (state_) state_->centre_of_keyframe.push_back(-1);
    ok = ok && try_add_centre(e.index);
  }
  ok = ok && finish_incremental(state_->centre_of_keyframe[e.index]);
  if (!ok) full_solve();
  e.incremental = ok;
  return e;
}

void KeyframeSet::remove(std::size_t index) {
  if (index >= keyframes_.size()) throw std::out_of_range("KeyframeSet::remove: no such keyframe");
  adopt_worker_result();
  ++version_;
  bool ok = state_ && try_remove_centre(index);
  keyframes_.erase(keyframes_.begin() + static_cast<std::ptrdiff_t>(index));
  if (state_) {
    auto& ck = state_->centre_of_keyframe;
    ck.erase(ck.begin() + static_cast<std::ptrdiff_t>(index));
    for (int& k : state_->keyframe_of_centre)
      if (k > static_cast<int>(index)) --k;
  }
  ok = ok && finish_incremental(-1);
  if (!ok) full_solve();
}

KeyframeSet::Edit KeyframeSet::move(std::size_t index, const Direction& direction,
                                    std::int64_t frame) {
  if (index >= keyframes_.size()) throw std::out_of_range("KeyframeSet::move: no such keyframe");
  Edit e;
  if (const auto hit = find_coincident(direction, frame, index)) {
    e.replaced = *hit;
    remove(*hit);
    if (*hit < index) --index;
  }
  adopt_worker_result();
  ++version_;
  e.index = index;
  keyframes_[index].direction = direction;
  keyframes_[index].frame = frame;
  bool ok = state_ && try_remove_centre(index) && try_add_centre(index);
  ok = ok && finish_incremental(state_->centre_of_keyframe[index]);
  if (!ok) full_solve();
  e.incremental = ok;
  return e;
}

void KeyframeSet::set_params(std::size_t index, std::vector<double> params) {
  if (index >= keyframes_.size())
    throw std::out_of_range("KeyframeSet::set_params: no such keyframe");
  Keyframe k = keyframes_[index];
  k.params = std::move(params);
  check_params(k, dimension_);
  adopt_worker_result();
  ++version_;
  keyframes_[index] = std::move(k);
  bool ok = false;
  if (state_) {
    State& st = *state_;
    const int c = st.centre_of_keyframe[index];
    const Eigen::RowVectorXd v =
        Eigen::Map<const Eigen::RowVectorXd>(keyframes_[index].params.data(), dimension_);
    // Only the right-hand side changes: z += M^-1 e_c (v - v_old).
    st.z += st.inverse.col(st.r() + c) * (v - st.points.values.row(c));
    st.points.values.row(c) = v;
    ok = finish_incremental(c);
  }
  if (!ok) full_solve();
}

}  // namespace vdfx::effects
