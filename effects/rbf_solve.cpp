/// @file
/// @brief The null-space solve of the RBF saddle-point system.
#include "effects/rbf_solve.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <optional>

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
    out = (points.x - n.x()).square() + (points.y - n.y()).square() +
          (points.z - n.z()).square() + ((points.t - t) * tf).square();
  } else {
    for (Eigen::Index i = 0; i < out.size(); ++i) {
      const double dt = (points.t[i] - t) * tf;
      out[i] = kernel.angular_d2(points.unit(static_cast<int>(i)), n) + dt * dt;
    }
  }
  kernel.apply_phi(out);
}

Eigen::MatrixXd kernel_matrix(const RbfPoints& points, const RbfKernel& kernel) {
  const int m = points.size();
  Eigen::MatrixXd a(m, m);
  Eigen::ArrayXd row(m);
  for (int j = 0; j < m; ++j) {
    kernel_row(points, kernel, points.unit(j), points.t[j], row);
    a.col(j) = row.matrix();
  }
  // Exact symmetry (the rows are computed independently and could differ in the last bit).
  a = a.selfadjointView<Eigen::Lower>();
  return a;
}

Eigen::MatrixXd polynomial_matrix(const RbfPoints& points, const PolynomialBasis& basis) {
  const int m = points.size();
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> p(m, basis.size());
  for (int i = 0; i < m; ++i) basis.row(points.unit(i), points.t[i], p.row(i).data());
  return p;
}

Eigen::MatrixXd projected_kernel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p) {
  const Eigen::Index m = a.rows(), r = p.cols();
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(p);
  Eigen::MatrixXd b = a;
  b.applyOnTheLeft(qr.householderQ().adjoint());
  b.applyOnTheRight(qr.householderQ());
  return b.bottomRightCorner(m - r, m - r);
}

namespace {

/// The factorised saddle-point system: solves [A P; P^T 0][w; c] = [f; g].
class SaddleSolver {
 public:
  SaddleSolver(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, bool positive)
      : m_(a.rows()), r_(p.cols()), qr_(p) {
    b_ = a;
    b_.applyOnTheLeft(qr_.householderQ().adjoint());
    b_.applyOnTheRight(qr_.householderQ());
    const Eigen::Index n2 = m_ - r_;
    if (n2 == 0) {
      method_ = RbfSolveMethod::Polynomial;
      return;
    }
    sign_ = positive ? 1.0 : -1.0;
    llt_.compute(sign_ * b_.bottomRightCorner(n2, n2));
    if (llt_.info() == Eigen::Success) {
      const double rc = llt_.rcond();
      if (rc > 1e3 * std::numeric_limits<double>::epsilon()) {
        method_ = RbfSolveMethod::NullSpaceCholesky;
        condition_ = 1.0 / rc;
        return;
      }
    }
    lu_.emplace(b_.bottomRightCorner(n2, n2));
    if (lu_->isInvertible() && lu_->rcond() > 1e2 * std::numeric_limits<double>::epsilon()) {
      method_ = RbfSolveMethod::NullSpaceLu;
      condition_ = 1.0 / lu_->rcond();
      return;
    }
    lu_.reset();
    cod_.emplace(b_.bottomRightCorner(n2, n2));
    method_ = RbfSolveMethod::LeastSquares;
    condition_ = std::numeric_limits<double>::infinity();
  }

  RbfSolveMethod method() const { return method_; }
  double condition() const { return condition_; }

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
      const Eigen::MatrixXd rhs =
          qf.bottomRows(n2) - b_.bottomLeftCorner(n2, r_) * y.topRows(r_);
      switch (method_) {
        case RbfSolveMethod::NullSpaceCholesky: y.bottomRows(n2) = sign_ * llt_.solve(rhs); break;
        case RbfSolveMethod::NullSpaceLu: y.bottomRows(n2) = lu_->solve(rhs); break;
        default: y.bottomRows(n2) = cod_->solve(rhs); break;
      }
    }
    c = r.solve(qf.topRows(r_) - b_.topRows(r_) * y);
    w = y;
    w.applyOnTheLeft(qr_.householderQ());
  }

 private:
  Eigen::Index m_, r_;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr_;
  Eigen::MatrixXd b_;  // Q^T A Q
  double sign_ = 1.0;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  std::optional<Eigen::FullPivLU<Eigen::MatrixXd>> lu_;
  std::optional<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>> cod_;
  RbfSolveMethod method_ = RbfSolveMethod::Empty;
  double condition_ = 1.0;
};

double max_abs(const Eigen::MatrixXd& m) { return m.size() ? m.cwiseAbs().maxCoeff() : 0.0; }

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
  Eigen::MatrixXd a = kernel_matrix(points, kernel);
  const Eigen::MatrixXd p = polynomial_matrix(points, basis);
  const SaddleSolver solver(a, p, kernel.order_two());
  s.diagnostics.method = solver.method();
  s.diagnostics.condition_estimate = solver.condition();

  const Eigen::MatrixXd& f = points.values;
  const Eigen::MatrixXd g0 = Eigen::MatrixXd::Zero(r, d);
  solver.solve(f, g0, s.weights, s.coefficients);

  const double scale = max_abs(f);
  // Residuals accumulated in long double: near-coincident centres make the weights large and
  // their sums cancel, so a residual summed in double would be as wrong as the solution.
  auto residuals = [&](Eigen::MatrixXd& rf, Eigen::MatrixXd& rg) {
    using LMat = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
    const LMat wl = s.weights.cast<long double>();
    const LMat cl = s.coefficients.cast<long double>();
    rf = (f.cast<long double>() - a.cast<long double>() * wl - p.cast<long double>() * cl)
             .cast<double>();
    rg = (-(p.cast<long double>().transpose() * wl)).cast<double>();
    return std::max(max_abs(rf), max_abs(rg));
  };
  Eigen::MatrixXd rf, rg;
  // The double residual decides whether refinement is worth an O(m^2) long double pass.
  rf = f - a * s.weights - p * s.coefficients;
  rg = -p.transpose() * s.weights;
  double res = std::max(max_abs(rf), max_abs(rg));
  for (int step = 0; step < 3 && scale > 0.0 && res > kRefineTolerance * scale; ++step) {
    if (step == 0) res = residuals(rf, rg);
    if (res <= kRefineTolerance * scale) break;
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
  if (kernel_out) *kernel_out = std::move(a);
  return s;
}

}  // namespace vdfx::effects
