/// @file
/// @brief The null-space solve of the RBF saddle-point system.
#include "effects/rbf_solve.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <optional>
#include <vector>

#include "effects/cholesky.h"
#include "effects/huge_matrix.h"
#include "effects/rbf_exact_residual.h"
#include "effects/solve_threads.h"

namespace vdfx::effects {

std::string_view to_string(RbfSolveMethod m) {
  switch (m) {
    case RbfSolveMethod::Empty: return "empty";
    case RbfSolveMethod::Polynomial: return "polynomial";
    case RbfSolveMethod::NullSpaceCholesky: return "null-space Cholesky";
    case RbfSolveMethod::NullSpaceLu: return "null-space LU";
    case RbfSolveMethod::LeastSquares: return "least squares";
  }
  return "?";
}

void kernel_row(const RbfPoints& points, const RbfKernel& kernel, const Eigen::Vector3d& n,
                double t, Eigen::Ref<Eigen::ArrayXd> out) {
  const double tf = kernel.time_factor;
  if (kernel.distance == AngularDistance::Chordal) {
    out = (points.x - n.x()).square() + (points.y - n.y()).square() + (points.z - n.z()).square() +
          ((points.t - t) * tf).square();
  } else {
    for (Eigen::Index i = 0; i < out.size(); ++i) {
      const double dt = (points.t[i] - t) * tf;
      out[i] = kernel.angular_d2(points.unit(static_cast<int>(i)), n) + dt * dt;
    }
  }
  kernel.apply_phi(out);
}

namespace {

/// The strict upper triangle of the square `a` from its lower one, in 64 x 64 tiles (a tile's
/// transpose stays in cache where a column of the upper triangle read from a row of the lower
/// one takes a cache line per entry), tile columns split between the solve's threads in equal
/// shares of the triangle. Copies only: any split gives the same matrix.
void mirror_lower_into_upper(Eigen::Ref<Eigen::MatrixXd> a) {
  constexpr Eigen::Index kTile = 64;
  const Eigen::Index m = a.rows(), tiles = (m + kTile - 1) / kTile;
  // Tile column t holds about t tiles: part k ends where k / parts of the t^2 / 2 work is done.
  const auto cut = [tiles](int k, int parts) {
    return tiles - triangle_cut(tiles, parts - k, parts);
  };
  parallel_parts(tiles, kParallelSolveMin / kTile, cut, [&](std::ptrdiff_t lo, std::ptrdiff_t hi) {
    for (Eigen::Index t = lo; t < hi; ++t) {
      const Eigen::Index j = t * kTile, w = std::min(kTile, m - j);
      for (Eigen::Index i = 0; i < j; i += kTile)
        a.block(i, j, kTile, w) = a.block(j, i, w, kTile).transpose();
      auto diagonal = a.block(j, j, w, w);
      diagonal.triangularView<Eigen::StrictlyUpper>() = diagonal.transpose();
    }
  });
}

}  // namespace

Eigen::MatrixXd kernel_matrix(const RbfPoints& points, const RbfKernel& kernel) {
  Eigen::MatrixXd a(points.size(), points.size());
  kernel_matrix_into(points, kernel, a);
  return a;
}

void kernel_matrix_into(const RbfPoints& points, const RbfKernel& kernel,
                        Eigen::Ref<Eigen::MatrixXd> a) {
  const int m = points.size();
  if (kernel.distance == AngularDistance::Chordal) {
    // The lower triangle only (half the square roots / powers), mirrored afterwards: exactly
    // symmetric by construction. Columns are independent: split between the solve's threads.
    const double tf = kernel.time_factor;
    parallel_parts(
        m, kParallelSolveMin, [m](int k, int parts) { return triangle_cut(m, k, parts); },
        [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
          for (auto j = static_cast<int>(begin); j < static_cast<int>(end); ++j) {
            const int len = m - j;
            auto col = a.col(j).tail(len).array();
            col = (points.x.tail(len) - points.x[j]).square() +
                  (points.y.tail(len) - points.y[j]).square() +
                  (points.z.tail(len) - points.z[j]).square() +
                  ((points.t.tail(len) - points.t[j]) * tf).square();
            kernel.apply_phi(col);
          }
        });
  } else {
    Eigen::ArrayXd row(m);
    for (int j = 0; j < m; ++j) {
      kernel_row(points, kernel, points.unit(j), points.t[j], row);
      a.col(j).tail(m - j) = row.tail(m - j).matrix();
    }
  }
  mirror_lower_into_upper(a);
}

Eigen::MatrixXd polynomial_matrix(const RbfPoints& points, const PolynomialBasis& basis) {
  const int m = points.size();
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> p(m, basis.size());
  for (int i = 0; i < m; ++i) basis.row(points.unit(i), points.t[i], p.row(i).data());
  return p;
}

namespace {

using ConstMatrixRef = Eigen::Ref<const Eigen::MatrixXd>;

/// A V for a symmetric m x m A and a thin V (m x r, r <= 5): row j of A V is column j of A
/// against V, so the product is one contiguous sweep over A, split between the solve's threads.
/// A general product packs all of A into blocks first: another 8 MB touched at m = 1000, and a
/// quarter of `vdfx eval`'s page faults.
Eigen::MatrixXd symmetric_times_thin(ConstMatrixRef a, const Eigen::MatrixXd& v) {
  const Eigen::Index m = a.rows();
  // r x m, row-major: r contiguous dot products with each column of A (column-major, Eigen sweeps
  // the m columns of V^T four entries at a time).
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> vt = v.transpose();
  Eigen::MatrixXd out(m, v.cols());
  parallel_parts(
      m, kParallelSolveMin, [m](int part, int parts) { return m * part / parts; },
      [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
        for (Eigen::Index j = begin; j < end; ++j)
          out.row(j).noalias() = (vt * a.col(j)).transpose();
      });
  return out;
}

/// The Householder sequence of a QR of P in compact WY form, Q = H_0 ... H_{r-1} = I - V T V^T
/// (Schreiber & Van Loan 1989; LAPACK's dlarft recurrence), so Q^T A Q costs one product A V
/// and one symmetric rank-2r update instead of r rank-one sweeps per side.
struct CompactWy {
  Eigen::MatrixXd v;  // m x r, unit lower trapezoidal
  Eigen::MatrixXd t;  // r x r, upper triangular

  explicit CompactWy(const Eigen::HouseholderQR<Eigen::MatrixXd>& qr) {
    const Eigen::MatrixXd& h = qr.matrixQR();
    const Eigen::Index m = h.rows(), r = h.cols();
    v.setZero(m, r);
    t.setZero(r, r);
    for (Eigen::Index k = 0; k < r; ++k) {
      v(k, k) = 1.0;
      v.col(k).tail(m - k - 1) = h.col(k).tail(m - k - 1);
      const double tau = qr.hCoeffs()[k];
      if (k > 0) {
        const Eigen::VectorXd vtv = v.leftCols(k).transpose() * v.col(k);
        const Eigen::VectorXd tv = t.topLeftCorner(k, k) * vtv;  // T is 0 below its diagonal
        t.col(k).head(k) = -tau * tv;
      }
      t(k, k) = tau;
    }
  }

  /// Y with Q^T A Q = A - Y V^T - V Y^T for a symmetric A.
  Eigen::MatrixXd update_factor(ConstMatrixRef a) const {
    const Eigen::MatrixXd w = symmetric_times_thin(a, v) * t;
    const Eigen::MatrixXd mm = t.transpose() * (v.transpose() * w);
    return w - 0.5 * v * mm;
  }
};

/// The lower triangle of K = sign (A22 - Y2 V2^T - V2 Y2^T), the null-space block of Q^T A Q
/// (22: rows and columns r..m-1), in one pass over A's lower triangle: 2r multiply-adds per
/// entry, where two general rank-r triangular products would each sweep the matrix again.
/// The strict upper triangle of `k` (n2 x n2) is left as it was (only the lower one is factorised).
void projected_lower(ConstMatrixRef a, const Eigen::MatrixXd& y, const Eigen::MatrixXd& v,
                     double sign, Eigen::Ref<Eigen::MatrixXd> k) {
  const Eigen::Index m = a.rows(), r = y.cols(), n2 = m - r;
  // Column j of K is updated with the contiguous columns of Y2 and V2 (vectorises); columns are
  // independent: split between the solve's threads.
  parallel_parts(
      n2, kParallelSolveMin, [n2](int part, int parts) { return triangle_cut(n2, part, parts); },
      [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
        for (Eigen::Index j = begin; j < end; ++j) {
          const Eigen::Index len = n2 - j;
          auto kc = k.col(j).tail(len);
          kc = a.col(r + j).tail(len);
          for (Eigen::Index q = 0; q < r; ++q) {
            kc -= v(r + j, q) * y.col(q).tail(len) + y(r + j, q) * v.col(q).tail(len);
          }
          if (sign < 0.0) kc = -kc;
        }
      });
}

/// The lower triangle of the projected block in a new matrix (the fallbacks and tests).
Eigen::MatrixXd projected_lower(ConstMatrixRef a, const Eigen::MatrixXd& y,
                                const Eigen::MatrixXd& v, double sign) {
  Eigen::MatrixXd k(a.rows() - y.cols(), a.rows() - y.cols());
  projected_lower(a, y, v, sign, k);
  return k;
}

/// The whole symmetric matrix from its lower triangle.
Eigen::MatrixXd mirror_lower(Eigen::MatrixXd k) {
  k.triangularView<Eigen::StrictlyUpper>() = k.transpose();
  return k;
}

/// The factorised saddle-point system: solves [A P; P^T 0][w; c] = [f; g].
///
/// Only what the solve needs of B = Q^T A Q is formed: its first r rows, and the lower triangle
/// of the null-space block K = +-B22, factorised in place (in huge pages, no copy of the m x m
/// matrix; on the solve's threads, effects/cholesky.h). The LU and least-squares fallbacks rebuild
/// the full block when the Cholesky factorisation fails or its condition estimate is too large. The
/// estimate (Hager and Higham's, as Eigen's LLT::rcond(): about six solves with the factor, a tenth
/// of `vdfx eval` at m = 1000) runs on a second thread where the solve has two, while the caller
/// solves and refines with the factor; confirm() waits for it and, where it rejects the factor,
/// falls back: solve again.
class SaddleSolver {
 public:
  SaddleSolver(ConstMatrixRef a, const Eigen::MatrixXd& p, bool positive)
      : m_(a.rows()), r_(p.cols()), qr_(p) {
    const Eigen::Index n2 = m_ - r_;
    if (r_ > 0) {
      const CompactWy wy(qr_);
      y_ = wy.update_factor(a);
      v_ = wy.v;
      b_top_ = a.topRows(r_) - y_.topRows(r_) * v_.transpose() - v_.topRows(r_) * y_.transpose();
    }
    if (n2 == 0) {
      method_ = RbfSolveMethod::Polynomial;
      return;
    }
    sign_ = positive ? 1.0 : -1.0;
    k_.emplace(n2, n2);
    projected_lower(a, y_, v_, sign_, k_->map());
    const double norm1 = symmetric_norm1_lower(k_->map());
    if (cholesky_in_place(k_->map())) {
      factor_.emplace(k_->map(), norm1);
      method_ = RbfSolveMethod::NullSpaceCholesky;
#if !defined(__EMSCRIPTEN__)  // the web module is built without threads
      if (solve_threads() > 1) {
        rcond_ = async_beside([this] { return factor_->rcond(); });
        return;
      }
#endif
      if (accept(factor_->rcond())) return;
    }
    fall_back(a);
  }

  SaddleSolver(const SaddleSolver&) = delete;
  SaddleSolver& operator=(const SaddleSolver&) = delete;

  /// Waits for a condition estimate still running. True where the factorisation stands; false
  /// where it fell back to another method: solutions computed before are to be computed again.
  bool confirm(ConstMatrixRef a) {
    if (!rcond_.valid()) return true;
    if (accept(rcond_.get())) return true;
    fall_back(a);
    return false;
  }

  RbfSolveMethod method() const {
    return method_;
  }
  double condition() const {
    return condition_;
  }

  /// f: m x D, g: r x D; writes w (m x D) and c (r x D).
  void solve(const Eigen::MatrixXd& f, const Eigen::MatrixXd& g, Eigen::MatrixXd& w,
             Eigen::MatrixXd& c) const {
    const Eigen::Index n2 = m_ - r_, d = f.cols();
    const auto r = qr_.matrixQR().topLeftCorner(r_, r_).triangularView<Eigen::Upper>();
    Eigen::MatrixXd qf = f;
    qf.applyOnTheLeft(qr_.householderQ().adjoint());
    // P^T w = g fixes the range part of w: (Q^T w)_top = R^{-T} g.
    Eigen::MatrixXd y(m_, d);
    y.topRows(r_) = r.transpose().solve(g);
    if (n2 > 0) {
      Eigen::MatrixXd rhs = qf.bottomRows(n2);
      if (r_ > 0) rhs.noalias() -= b_top_.rightCols(n2).transpose() * y.topRows(r_);
      switch (method_) {
        case RbfSolveMethod::NullSpaceCholesky:
          y.bottomRows(n2) = sign_ * factor_->solve(rhs);
          break;
        case RbfSolveMethod::NullSpaceLu: y.bottomRows(n2) = lu_->solve(rhs); break;
        default: y.bottomRows(n2) = cod_->solve(rhs); break;
      }
    }
    if (r_ > 0)
      c = r.solve(qf.topRows(r_) - b_top_ * y);
    else
      c.resize(0, d);
    w = y;
    w.applyOnTheLeft(qr_.householderQ());
  }

 private:
  /// Keeps the Cholesky factorisation where its reciprocal condition estimate is not tiny.
  bool accept(double rc) {
    if (!(rc > 1e3 * std::numeric_limits<double>::epsilon())) return false;
    condition_ = 1.0 / rc;
    return true;
  }

  /// The general solvers, on the whole block rebuilt (the factorisation overwrote it).
  void fall_back(ConstMatrixRef a) {
    factor_.reset();
    k_.reset();
    const Eigen::MatrixXd b22 = mirror_lower(projected_lower(a, y_, v_, 1.0));
    lu_.emplace(b22);
    if (lu_->isInvertible() && lu_->rcond() > 1e2 * std::numeric_limits<double>::epsilon()) {
      method_ = RbfSolveMethod::NullSpaceLu;
      condition_ = 1.0 / lu_->rcond();
      return;
    }
    lu_.reset();
    cod_.emplace(b22);
    method_ = RbfSolveMethod::LeastSquares;
    condition_ = std::numeric_limits<double>::infinity();
  }

  Eigen::Index m_, r_;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr_;
  Eigen::MatrixXd y_, v_;        // Q^T A Q = A - Y V^T - V Y^T (compact WY form of Q)
  Eigen::MatrixXd b_top_;        // the first r rows of Q^T A Q
  std::optional<HugeMatrix> k_;  // +-B22 (lower triangle), overwritten by its Cholesky factor
  double sign_ = 1.0;
  std::optional<CholeskyFactor> factor_;  // reads k_
  std::optional<Eigen::FullPivLU<Eigen::MatrixXd>> lu_;
  std::optional<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>> cod_;
  RbfSolveMethod method_ = RbfSolveMethod::Empty;
  double condition_ = 1.0;
  std::future<double> rcond_;  // last: destroyed (waited for) before the factor it reads
};

}  // namespace

Eigen::MatrixXd projected_kernel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p) {
  if (p.cols() == 0) return a;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(p);
  const CompactWy wy(qr);
  return mirror_lower(projected_lower(a, wy.update_factor(a), wy.v, 1.0));
}

namespace {

double max_abs(const Eigen::MatrixXd& m) {
  return m.size() ? m.cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace

double rbf_residual(const RbfPoints& points, const RbfKernel& kernel, const PolynomialBasis& basis,
                    const Eigen::MatrixXd& weights, const Eigen::MatrixXd& coefficients,
                    const std::vector<int>& rows) {
  const int m = points.size();
  double worst = 0.0;
  Eigen::ArrayXd krow(m);
  Eigen::RowVectorXd prow(basis.size());
  auto check = [&](int i) {
    kernel_row(points, kernel, points.unit(i), points.t[i], krow);
    basis.row(points.unit(i), points.t[i], prow.data());
    const Eigen::RowVectorXd v = krow.matrix().transpose() * weights + prow * coefficients;
    worst = std::max(worst, (v - points.values.row(i)).cwiseAbs().maxCoeff());
  };
  if (rows.empty()) {
    for (int i = 0; i < m; ++i) check(i);
  } else {
    for (int i : rows) check(i);
  }
  if (m > 0 && basis.size() > 0) {
    worst = std::max(worst, max_abs(polynomial_matrix(points, basis).transpose() * weights));
  }
  return worst;
}

namespace {

/// Solves for `f` (with P^T w = 0), then refines with residuals in twice double precision
/// (rbf_exact_residual.h) while that helps: up to three steps, keeping the better solution, and
/// none once the residual is below what rounding the weights to double leaves (at N = 1000 a
/// second step found nothing, and cost a twentieth of `vdfx eval`).
void solve_refined(const SaddleSolver& solver, ConstMatrixRef a, const Eigen::MatrixXd& p,
                   const Eigen::MatrixXd& f, RbfSolution& s) {
  const Eigen::MatrixXd g0 = Eigen::MatrixXd::Zero(p.cols(), f.cols());
  solver.solve(f, g0, s.weights, s.coefficients);
  s.diagnostics.refined = false;
  const double scale = max_abs(f);
  double floor = 0.0;  // what rounding the weights to double leaves (rbf_exact_residual.h)
  auto residuals = [&](Eigen::MatrixXd& rf, Eigen::MatrixXd& rg) {
    return saddle_residual_dot2(a, p, f, g0, s.weights, s.coefficients, rf, rg, &floor);
  };
  Eigen::MatrixXd rf, rg;
  // The double residual decides whether refinement is worth an exact-residual pass. From
  // kParallelSolveMin centres refinement runs nearly always (the first residual at N = 1000 is
  // about 1e-10 of the values) and the exact pass, on the solve's threads, decides alone: one
  // sweep of the m x m matrix fewer.
  const bool gate = a.rows() < kParallelSolveMin;
  double res = 0.0;
  if (gate) {
    rf = f - a * s.weights - p * s.coefficients;
    rg = -p.transpose() * s.weights;
    res = std::max(max_abs(rf), max_abs(rg));
  } else {
    res = residuals(rf, rg);
  }
  for (int step = 0; step < 3 && scale > 0.0 && res > kRefineTolerance * scale; ++step) {
    if (step == 0 && gate) res = residuals(rf, rg);
    if (res <= kRefineTolerance * scale || res <= floor) break;
    Eigen::MatrixXd dw, dc;
    solver.solve(rf, rg, dw, dc);
    const Eigen::MatrixXd w_old = s.weights, c_old = s.coefficients;
    s.weights += dw;
    s.coefficients += dc;
    const double next = residuals(rf, rg);
    if (!(next < res)) {  // no progress: keep the better solution
      s.weights = w_old;
      s.coefficients = c_old;
      break;
    }
    s.diagnostics.refined = true;
    res = next;
  }
  s.diagnostics.max_residual = res;
  s.diagnostics.relative_residual = scale > 0.0 ? res / scale : res;
}

}  // namespace

RbfSolution solve_rbf(const RbfPoints& points, const RbfKernel& kernel,
                      const PolynomialBasis& basis, Eigen::MatrixXd* inverse,
                      Eigen::MatrixXd* kernel_out) {
  RbfSolution s;
  const int m = points.size(), d = points.dimension(), r = basis.size();
  s.diagnostics.keyframes = static_cast<int>(points.point_of_keyframe.size());
  s.diagnostics.centres = m;
  s.diagnostics.merged = points.merged();
  s.diagnostics.active_terms = r;
  s.weights.setZero(m, d);
  s.coefficients.setZero(r, d);
  if (m == 0) {
    if (inverse) inverse->resize(0, 0);
    if (kernel_out) kernel_out->resize(0, 0);
    return s;
  }
  HugeMatrix a(m, m);
  kernel_matrix_into(points, kernel, a.map());
  const Eigen::MatrixXd p = polynomial_matrix(points, basis);
  SaddleSolver solver(a.map(), p, kernel.order_two());
  solve_refined(solver, a.map(), p, points.values, s);
  if (!solver.confirm(a.map())) solve_refined(solver, a.map(), p, points.values, s);
  s.diagnostics.method = solver.method();
  s.diagnostics.condition_estimate = solver.condition();

  if (inverse) {
    // Columns of the inverse: unit right-hand sides, ordered [polynomial; centres].
    Eigen::MatrixXd w1, c1, w2, c2;
    solver.solve(Eigen::MatrixXd::Identity(m, m), Eigen::MatrixXd::Zero(r, m), w1, c1);
    solver.solve(Eigen::MatrixXd::Zero(m, r), Eigen::MatrixXd::Identity(r, r), w2, c2);
    inverse->resize(r + m, r + m);
    inverse->topLeftCorner(r, r) = c2;
    inverse->bottomLeftCorner(m, r) = w2;
    inverse->topRightCorner(r, m) = c1;
    inverse->bottomRightCorner(m, m) = w1;
  }
  if (kernel_out) *kernel_out = a.map();
  return s;
}

}  // namespace vdfx::effects
