/// @file
/// @brief KeyframeSet: replace-on-top editing, bordered inverse updates, asynchronous re-solves.
#include "effects/keyframe_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

/// The state the O(N^2) updates work on. Slots are ordered [polynomial (r); centres (m)];
/// centres are removed by moving the last into place. The saddle matrix M = [0 P^T; P A] and
/// its inverse are both symmetric: only their lower triangles are kept, in the top-left n x n
/// (n = r + m) of square buffers with spare capacity, so edits neither allocate nor copy them.
struct KeyframeSet::State {
  std::uint64_t version = 0;
  RbfPoints points;
  PolynomialBasis basis;
  Eigen::MatrixXd saddle;   //!< capacity^2; lower triangle of M (its diagonal is 0: phi(0) = 0)
  Eigen::MatrixXd inverse;  //!< capacity^2; lower triangle of M^-1
  Eigen::MatrixXd z;        //!< capacity x D; top n rows: [c; w]
  std::vector<int> centre_of_keyframe;
  std::vector<int> keyframe_of_centre;
  RbfDiagnostics diagnostics;
  std::shared_ptr<const RbfInterpolator> interpolator;
  bool exact = false;  //!< one centre per keyframe and M^-1 known: incremental updates possible
  //! An add's rank-one term of the inverse, u u^T / s on the top-left u.size() block, not yet
  //! applied: finish_incremental fuses it with the refinement product (one sweep, not two).
  Eigen::VectorXd pending_u;
  double pending_alpha = 0.0;

  int r() const { return basis.size(); }
  int m() const { return points.size(); }
  int n() const { return r() + m(); }
  int capacity() const { return static_cast<int>(inverse.rows()); }
  Eigen::Block<Eigen::MatrixXd> weights() { return z.block(r(), 0, m(), z.cols()); }
  Eigen::Block<Eigen::MatrixXd> coefficients() { return z.block(0, 0, r(), z.cols()); }

  /// Makes room for `slots` slots (keeping the lower triangles), growing by half at a time;
  /// true when it had to reallocate.
  bool reserve(int slots) {
    if (slots <= capacity()) return false;
    const int cap = std::max({slots, capacity() + capacity() / 2, 16});
    const int used = n();
    auto grow = [&](Eigen::MatrixXd& a, Eigen::Index cols) {
      Eigen::MatrixXd b = Eigen::MatrixXd::Zero(cap, cols);
      b.topLeftCorner(used, std::min<Eigen::Index>(used, cols)) =
          a.topLeftCorner(used, std::min<Eigen::Index>(used, cols));
      a.swap(b);
    };
    grow(saddle, cap);
    grow(inverse, cap);
    grow(z, z.cols());
    return true;
  }
};

namespace {

/// Spare slots kept after a full solve: edits add this many centres before a reallocation.
int spare_slots(int n) {
  return std::max(32, n / 8);
}

/// Exchanges slots j and l = n - 1 of the symmetric matrix whose lower triangle is stored in
/// s.topLeftCorner(n, n) (a symmetric permutation: rows and columns together), O(n).
void symmetric_swap_with_last(Eigen::MatrixXd& s, int j, int n) {
  const int l = n - 1;
  if (j == l) return;
  std::swap(s(j, j), s(l, l));
  for (int k = 0; k < j; ++k) std::swap(s(j, k), s(l, k));
  for (int k = j + 1; k < l; ++k) std::swap(s(k, j), s(l, k));
}

/// Applies the pending rank-one term of the inverse to the lower triangle of s (whose used
/// block is n x n, n >= u.size()) and, with x and y given (n rows), adds S x to y with the
/// updated S in the same sweep: each column is read from memory once.
void lower_update_and_product(Eigen::MatrixXd& s, const Eigen::VectorXd& u, double alpha, int n,
                              const Eigen::MatrixXd* x, Eigen::MatrixXd* y) {
  const Eigen::Index nu = u.size();
  for (Eigen::Index k = 0; k < n; ++k) {
    if (k < nu) s.col(k).segment(k, nu - k) += (alpha * u[k]) * u.tail(nu - k);
    if (!x) continue;
    const Eigen::Index len = n - k;
    const auto col = s.col(k).segment(k, len);
    for (Eigen::Index d = 0; d < x->cols(); ++d) {
      const double xk = (*x)(k, d);
      double acc = 0.0;
      if (len > 1) acc = col.tail(len - 1).dot(x->col(d).segment(k + 1, len - 1));
      y->col(d).segment(k, len) += xk * col;
      (*y)(k, d) += acc;
    }
  }
}

/// y = S x for each column, S symmetric with its lower triangle in s.topLeftCorner(n, n):
/// matrix-vector products (Eigen's selfadjoint matrix-matrix path packs for a few columns).
template <typename X, typename Y>
void lower_symmetric_product(const Eigen::MatrixXd& s, const X& x, Y&& y, bool subtract) {
  const Eigen::Index n = x.rows();
  const auto sym = s.topLeftCorner(n, n).template selfadjointView<Eigen::Lower>();
  for (Eigen::Index d = 0; d < x.cols(); ++d) {
    if (subtract) {
      y.col(d).noalias() -= sym * x.col(d);
    } else {
      y.col(d).noalias() += sym * x.col(d);
    }
  }
}

/// Column j of the symmetric matrix stored as in symmetric_swap_with_last.
void symmetric_column(const Eigen::MatrixXd& s, int j, int n, Eigen::VectorXd& out) {
  out.resize(n);
  out.head(j) = s.row(j).head(j).transpose();
  out.tail(n - j) = s.col(j).segment(j, n - j);
}

}  // namespace

namespace {

std::shared_ptr<const RbfInterpolator> make_interpolator(
    const RbfPoints& points, const RbfKernel& kernel, const PolynomialBasis& basis,
    const Eigen::MatrixXd& z, const RbfDiagnostics& diagnostics, const Eigen::VectorXd& neutral) {
  RbfSolution s;
  s.coefficients = z.topRows(basis.size());
  s.weights = z.middleRows(basis.size(), points.size());
  s.diagnostics = diagnostics;
  return std::make_shared<const RbfInterpolator>(points, kernel, basis, s, neutral);
}

}  // namespace

/// Full solve; the returned state is not `exact` when keyframes had to be merged (the
/// incremental path keeps one centre per keyframe).
std::unique_ptr<KeyframeSet::State> KeyframeSet::solve_full(const std::vector<Keyframe>& keyframes,
                                                            int dimension, const RbfKernel& kernel,
                                                            const Eigen::VectorXd& neutral,
                                                            std::uint64_t version) {
  auto st = std::make_unique<KeyframeSet::State>();
  st->version = version;
  st->points = merge_keyframes(keyframes, dimension);
  st->basis = select_polynomial_basis(st->points);
  st->exact = st->points.merged() == 0;
  Eigen::MatrixXd inv, a;
  const RbfSolution s = solve_rbf(st->points, kernel, st->basis, st->exact ? &inv : nullptr,
                                  st->exact ? &a : nullptr);
  const int r = st->r(), m = st->m(), n = r + m;
  const int cap = st->exact ? n + spare_slots(n) : n;
  st->z.setZero(cap, dimension);
  st->z.topRows(r) = s.coefficients;
  st->z.middleRows(r, m) = s.weights;
  if (st->exact) {
    st->inverse.setZero(cap, cap);
    st->inverse.topLeftCorner(n, n).triangularView<Eigen::Lower>() = inv;
    st->saddle.setZero(cap, cap);
    st->saddle.block(r, r, m, m).triangularView<Eigen::Lower>() = a;
    st->saddle.block(r, 0, m, r) = polynomial_matrix(st->points, st->basis);
  }
  st->diagnostics = s.diagnostics;
  st->centre_of_keyframe = st->points.point_of_keyframe;
  st->keyframe_of_centre.assign(static_cast<size_t>(st->m()), -1);
  for (size_t k = 0; k < st->centre_of_keyframe.size(); ++k)
    st->keyframe_of_centre[static_cast<size_t>(st->centre_of_keyframe[k])] = static_cast<int>(k);
  st->interpolator =
      make_interpolator(st->points, kernel, st->basis, st->z, st->diagnostics, neutral);
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
  if (wants_local()) {
    local_ = std::make_unique<KeyframeWindows>(keyframes_, dimension_, settings_, fps_, neutral_);
    publish(local_->interpolator(), 0);
  } else {
    auto st = solve_full(keyframes_, dimension_, kernel_, neutral_, 0);
    publish(st->interpolator, 0);
    if (!st->exact) st.reset();
    state_ = std::move(st);
  }
  if (options_.async) start_worker();
}

void KeyframeSet::start_worker() {
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
      // The exact state is handed over under the same lock as the publication: an edit made
      // as soon as wait_for_version() returns must find it (and stay incremental).
      auto interpolator = st->interpolator;
      if (!st->exact) st.reset();
      publish(std::move(interpolator), job.first, std::move(st));
    }
  });
}

KeyframeSet::KeyframeSet(CloneTag, const KeyframeSet& source, KeyframeSetOptions options)
    : dimension_(source.dimension_),
      settings_(source.settings_),
      fps_(source.fps_),
      kernel_(source.kernel_),
      options_(options),
      neutral_(source.neutral_),
      keyframes_(source.keyframes_),
      version_(source.version_) {}

std::unique_ptr<KeyframeSet> KeyframeSet::clone(KeyframeSetOptions options) const {
  std::unique_ptr<KeyframeSet> c(new KeyframeSet(CloneTag{}, *this, options));
  if (local_) {  // the windows' solves are immutable: shared, nothing solved
    c->local_ = std::make_unique<KeyframeWindows>(*local_);
    c->publish(c->local_->interpolator(), version_);
    c->stats_.cloned_exact = true;
    if (c->options_.async) c->start_worker();
    return c;
  }
  std::unique_ptr<State> st;
  {
    // The exact state of the latest edit: ours, or one the worker published with it and no edit
    // has adopted yet (ready_ is only read under the publication lock).
    std::lock_guard lock(pub_mu_);
    const State* exact = nullptr;
    if (state_ && state_->version == version_)
      exact = state_.get();
    else if (ready_ && ready_->version == version_)
      exact = ready_.get();
    if (exact && published_version_ == version_) st = std::make_unique<State>(*exact);
  }
  if (st) {
    if (st->pending_u.size()) {  // never left between edits; applied for safety
      lower_update_and_product(st->inverse, st->pending_u, st->pending_alpha, st->n(), nullptr,
                               nullptr);
      st->pending_u.resize(0);
    }
    c->stats_.cloned_exact = true;
  } else {
    st = solve_full(keyframes_, dimension_, kernel_, neutral_, version_);
  }
  c->publish(st->interpolator, version_);
  if (st->exact) c->state_ = std::move(st);
  if (c->options_.async) c->start_worker();
  return c;
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

void KeyframeSet::publish(std::shared_ptr<const RbfInterpolator> s, std::uint64_t version,
                          std::unique_ptr<State> exact_state) const {
  {
    std::lock_guard lock(pub_mu_);
    if (published_ && version < published_version_) return;  // a stale worker result
    published_ = std::move(s);
    published_version_ = version;
    if (exact_state) ready_ = std::move(exact_state);
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

bool KeyframeSet::wait_for_version(std::uint64_t version, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(pub_mu_);
  return pub_cv_.wait_for(lock, timeout, [&] { return published_version_ >= version; });
}

void KeyframeSet::adopt_worker_result() {
  std::lock_guard lock(pub_mu_);
  if (ready_ && ready_->version == version_) state_ = std::move(ready_);
  ready_.reset();
}

bool replaces(const Direction& direction, std::int64_t frame, const Keyframe& other) {
  return other.frame == frame && angle_between(to_unit(direction), to_unit(other.direction)) <=
                                     kReplaceAngleDeg * kDegToRad;
}

std::optional<std::size_t> KeyframeSet::find_coincident(const Direction& d, std::int64_t frame,
                                                        std::optional<std::size_t> skip) const {
  for (std::size_t i = 0; i < keyframes_.size(); ++i)
    if (!(skip && *skip == i) && replaces(d, frame, keyframes_[i])) return i;
  return std::nullopt;
}

void KeyframeSet::flush_pending() {
  State& st = *state_;
  if (!st.pending_u.size()) return;
  lower_update_and_product(st.inverse, st.pending_u, st.pending_alpha, st.n(), nullptr, nullptr);
  st.pending_u.resize(0);
}

bool KeyframeSet::try_add_centre(std::size_t ki) {
  State& st = *state_;
  flush_pending();
  const Keyframe& kf = keyframes_[ki];
  const int r = st.r(), m = st.m(), n = r + m;
  const Eigen::Vector3d dir = to_unit(kf.direction);
  const double t = static_cast<double>(kf.frame - st.points.frame_origin);
  // The new row of M: b = [P row; A row], and M_nn = phi(0) = 0.
  Eigen::VectorXd b(n);
  st.basis.row(dir, t, b.data());
  kernel_row(st.points, kernel_, dir, t, b.tail(m).array());
  const Eigen::VectorXd u = st.inverse.topLeftCorner(n, n).selfadjointView<Eigen::Lower>() * b;
  const double s = -b.dot(u);  // Schur complement: 0 - b^T M^-1 b
  if (!(std::abs(s) > 1e-13 * b.norm() * u.norm())) return false;
  if (st.reserve(n + 1)) ++stats_.storage_growths;
  const Eigen::RowVectorXd v = Eigen::Map<const Eigen::RowVectorXd>(kf.params.data(), dimension_);
  const Eigen::RowVectorXd bz = b.transpose() * st.z.topRows(n);
  // Bordered inverse: [M^-1 + u u^T / s, -u / s; -u^T / s, 1 / s], lower triangle in place.
  st.pending_u = u;  // the top-left rank-one term: applied by finish_incremental
  st.pending_alpha = 1.0 / s;
  st.inverse.row(n).head(n) = -u.transpose() / s;
  st.inverse(n, n) = 1.0 / s;
  st.saddle.row(n).head(n) = b.transpose();
  st.saddle(n, n) = 0.0;
  st.z.topRows(n) += u * ((bz - v) / s);
  st.z.row(n) = (v - bz) / s;
  st.points.append(dir, kf.frame, v);
  st.keyframe_of_centre.push_back(static_cast<int>(ki));
  st.centre_of_keyframe[ki] = m;
  return true;
}

bool KeyframeSet::try_remove_centre(std::size_t ki) {
  State& st = *state_;
  flush_pending();
  const int r = st.r(), m = st.m(), n = r + m;
  const int c = st.centre_of_keyframe[ki];
  if (m <= 1 || c < 0) return false;
  const int j = r + c, last = n - 1;
  if (!(std::abs(st.inverse(j, j)) > 0.0)) return false;
  // Move the centre to the last slot, then take the Schur complement of that slot.
  symmetric_swap_with_last(st.inverse, j, n);
  symmetric_swap_with_last(st.saddle, j, n);
  st.z.row(j).swap(st.z.row(last));
  const double beta = st.inverse(last, last);
  const Eigen::VectorXd col = st.inverse.row(last).head(last).transpose();
  lower_update_and_product(st.inverse, col, -1.0 / beta, last, nullptr, nullptr);
  st.z.topRows(last) -= col * (st.z.row(last) / beta);
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
  const int m = st.m(), r = st.r(), n = r + m;
  const double scale = st.points.values.cwiseAbs().maxCoeff();
  // The full residual [0; F] - M z from the cached M: one symmetric matrix product, no kernel
  // evaluations. The bordered updates carry ~cond * eps error; a refinement step with it keeps
  // the error from accumulating, and is skipped when the residual already meets the full solve's
  // own refinement threshold.
  Eigen::MatrixXd res(n, dimension_);
  res.topRows(r).setZero();
  res.bottomRows(m) = st.points.values;
  lower_symmetric_product(st.saddle, st.z.topRows(n), res, true);
  const double full_res = res.cwiseAbs().maxCoeff();
  bool refined = false;
  if (options_.always_refine || full_res > kRefineTolerance * scale) {
    Eigen::MatrixXd dz = Eigen::MatrixXd::Zero(n, dimension_);
    lower_update_and_product(st.inverse, st.pending_u, st.pending_alpha, n, &res, &dz);
    st.pending_u.resize(0);
    st.z.topRows(n) += dz;
    refined = true;
    ++stats_.refinements;
  } else {
    flush_pending();
  }
  double check = full_res;
  if (refined || options_.always_refine) {
    // Independent check, kernel rows computed afresh: the new centre and 32 sampled ones.
    std::vector<int> rows;
    if (checked_centre >= 0) rows.push_back(checked_centre);
    const int samples = std::min(m, 32);
    for (int i = 0; i < samples; ++i)
      rows.push_back(static_cast<int>((static_cast<long>(i) * m) / samples));
    const Eigen::MatrixXd w = st.weights(), c = st.coefficients();
    check = rbf_residual(st.points, kernel_, st.basis, w, c, rows);
  }
  if (!(check <= options_.residual_tolerance * std::max(scale, 1e-300))) return false;
  ++stats_.incremental_edits;
  st.version = version_;
  st.diagnostics.keyframes = st.diagnostics.centres = m;
  st.diagnostics.merged = 0;
  st.diagnostics.active_terms = r;
  st.diagnostics.refined = refined;
  st.diagnostics.max_residual = check;
  st.diagnostics.relative_residual = scale > 0 ? check / scale : check;
  st.interpolator = make_interpolator(st.points, kernel_, st.basis, st.z, st.diagnostics, neutral_);
  publish(st.interpolator, version_);
  return true;
}

KeyframeSetStats KeyframeSet::stats() const {
  KeyframeSetStats s = stats_;
  s.capacity = state_ ? state_->capacity() : 0;
  return s;
}

bool KeyframeSet::wants_local() const {
  return !keyframes_.empty() && (settings_.reach_s || keyframes_.size() > kGlobalSolveMaxKeyframes);
}

bool KeyframeSet::local_edit(const KeyframeChange& change) {
  if (local_ && local_->update(keyframes_, change)) {
    ++stats_.local_edits;
    stats_.windows_solved += static_cast<std::uint64_t>(local_->last_solved());
    publish(local_->interpolator(), version_);
    return true;
  }
  full_solve();
  return false;
}

void KeyframeSet::full_solve() {
  state_.reset();
  local_.reset();
  if (wants_local()) {  // inline: only a change of the windows' layout gets here
    local_ = std::make_unique<KeyframeWindows>(keyframes_, dimension_, settings_, fps_, neutral_);
    publish(local_->interpolator(), version_);
    return;
  }
  if (!worker_ || static_cast<int>(keyframes_.size()) <= options_.inline_full_solve_max) {
    auto st = solve_full(keyframes_, dimension_, kernel_, neutral_, version_);
    publish(st->interpolator, version_);
    if (st->exact) state_ = std::move(st);
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
  KeyframeChange change{KeyframeChange::Added, keyframes_.size(), keyframe.frame, keyframe.frame};
  if (hit) {
    e.index = *hit;
    e.replaced = *hit;
    change = {KeyframeChange::Moved, *hit, keyframes_[*hit].frame, keyframe.frame};
    keyframes_[*hit] = std::move(keyframe);
  } else {
    e.index = keyframes_.size();
    keyframes_.push_back(std::move(keyframe));
  }
  if (local_ || wants_local()) {
    e.incremental = local_edit(change);
    return e;
  }
  bool ok = state_ && state_->m() > 0;
  if (hit) {
    ok = ok && try_remove_centre(*hit) && try_add_centre(*hit);
  } else {
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
  if (local_) {
    const KeyframeChange change{KeyframeChange::Removed, index, keyframes_[index].frame,
                                keyframes_[index].frame};
    keyframes_.erase(keyframes_.begin() + static_cast<std::ptrdiff_t>(index));
    local_edit(change);
    return;
  }
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
  const KeyframeChange change{KeyframeChange::Moved, index, keyframes_[index].frame, frame};
  keyframes_[index].direction = direction;
  keyframes_[index].frame = frame;
  if (local_ || wants_local()) {
    e.incremental = local_edit(change);
    return e;
  }
  bool ok = state_ && try_remove_centre(index) && try_add_centre(index);
  ok = ok && finish_incremental(state_->centre_of_keyframe[index]);
  if (!ok) full_solve();
  e.incremental = ok;
  return e;
}

void KeyframeSet::assign(std::vector<Keyframe> keyframes) {
  for (const Keyframe& k : keyframes) check_params(k, dimension_);
  adopt_worker_result();
  std::swap(keyframes_, keyframes);  // `keyframes` now holds the old list
  std::unique_ptr<KeyframeWindows> windows;
  std::unique_ptr<State> st;
  try {
    if (wants_local())
      windows = local_ ? std::make_unique<KeyframeWindows>(keyframes_, dimension_, settings_, fps_,
                                                           neutral_, *local_, keyframes)
                       : std::make_unique<KeyframeWindows>(keyframes_, dimension_, settings_, fps_,
                                                           neutral_);
    else
      st = solve_full(keyframes_, dimension_, kernel_, neutral_, version_ + 1);
  } catch (...) {
    std::swap(keyframes_, keyframes);
    throw;
  }
  ++version_;
  local_ = std::move(windows);
  state_.reset();
  if (local_) {
    publish(local_->interpolator(), version_);
    return;
  }
  publish(st->interpolator, version_);
  if (st->exact) state_ = std::move(st);
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
  if (local_) {
    local_edit({KeyframeChange::Values, index, keyframes_[index].frame, keyframes_[index].frame});
    return;
  }
  bool ok = false;
  if (state_) {
    State& st = *state_;
    const int c = st.centre_of_keyframe[index];
    const Eigen::RowVectorXd v =
        Eigen::Map<const Eigen::RowVectorXd>(keyframes_[index].params.data(), dimension_);
    // Only the right-hand side changes: z += M^-1 e_c (v - v_old).
    flush_pending();
    Eigen::VectorXd col;
    symmetric_column(st.inverse, st.r() + c, st.n(), col);
    st.z.topRows(st.n()) += col * (v - st.points.values.row(c));
    st.points.values.row(c) = v;
    ok = finish_incremental(c);
  }
  if (!ok) full_solve();
}

}  // namespace vdfx::effects
