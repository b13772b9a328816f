/// @file
/// @brief Keyframe merging and polynomial term selection.
#include "effects/rbf_points.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vdfx::effects {

int RbfPoints::merged() const {
  return static_cast<int>(point_of_keyframe.size()) - size();
}

void RbfPoints::append(const Eigen::Vector3d& n, std::int64_t f, const Eigen::RowVectorXd& v) {
  const Eigen::Index m = x.size();
  x.conservativeResize(m + 1);
  y.conservativeResize(m + 1);
  z.conservativeResize(m + 1);
  t.conservativeResize(m + 1);
  x[m] = n.x();
  y[m] = n.y();
  z[m] = n.z();
  t[m] = static_cast<double>(f - frame_origin);
  frame.push_back(f);
  values.conservativeResize(m + 1, Eigen::NoChange);
  values.row(m) = v;
  counts.push_back(1);
}

void RbfPoints::swap_remove(int i) {
  const int last = size() - 1;
  x[i] = x[last];
  y[i] = y[last];
  z[i] = z[last];
  t[i] = t[last];
  frame[static_cast<size_t>(i)] = frame.back();
  counts[static_cast<size_t>(i)] = counts.back();
  values.row(i) = values.row(last);
  x.conservativeResize(last);
  y.conservativeResize(last);
  z.conservativeResize(last);
  t.conservativeResize(last);
  frame.pop_back();
  counts.pop_back();
  values.conservativeResize(last, Eigen::NoChange);
}

namespace {

/// Each keyframe's unit direction, after checking its parameters' count and that every number is
/// finite (std::invalid_argument naming the keyframe otherwise).
std::vector<Eigen::Vector3d> checked_units(std::span<const Keyframe> keyframes, int dimension) {
  const int n = static_cast<int>(keyframes.size());
  std::vector<Eigen::Vector3d> units(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Keyframe& kf = keyframes[static_cast<size_t>(k)];
    // The message is only composed for a bad keyframe (a stream per keyframe cost more than
    // the rest of this loop).
    const auto fail = [&](const std::string& what) {
      std::ostringstream where;
      where << "RBF keyframe " << k << " (az " << kf.direction.azimuth_deg << ", alt "
            << kf.direction.altitude_deg << ", frame " << kf.frame << "): " << what;
      throw std::invalid_argument(where.str());
    };
    if (static_cast<int>(kf.params.size()) != dimension)
      fail(std::to_string(kf.params.size()) + " parameters, expected " + std::to_string(dimension));
    for (double v : kf.params)
      if (!std::isfinite(v)) fail("non-finite parameter");
    if (!std::isfinite(kf.direction.azimuth_deg) || !std::isfinite(kf.direction.altitude_deg))
      fail("non-finite direction");
    units[static_cast<size_t>(k)] = to_unit(kf.direction);
  }
  return units;
}

}  // namespace

RbfPoints merge_keyframes(std::span<const Keyframe> keyframes, int dimension) {
  const int n = static_cast<int>(keyframes.size());
  const std::vector<Eigen::Vector3d> units = checked_units(keyframes, dimension);

  // Sort by (frame, x) so coincident keyframes are found by a sweep, O(N log N) typically.
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto& ka = keyframes[static_cast<size_t>(a)];
    const auto& kb = keyframes[static_cast<size_t>(b)];
    if (ka.frame != kb.frame) return ka.frame < kb.frame;
    return units[static_cast<size_t>(a)].x() < units[static_cast<size_t>(b)].x();
  });
  std::vector<int> group(static_cast<size_t>(n), -1);
  int groups = 0;
  for (int i = 0; i < n; ++i) {
    const int a = order[static_cast<size_t>(i)];
    if (group[static_cast<size_t>(a)] >= 0) continue;
    group[static_cast<size_t>(a)] = groups;
    for (int j = i + 1; j < n; ++j) {
      const int b = order[static_cast<size_t>(j)];
      if (keyframes[static_cast<size_t>(b)].frame != keyframes[static_cast<size_t>(a)].frame) break;
      const Eigen::Vector3d& ua = units[static_cast<size_t>(a)];
      const Eigen::Vector3d& ub = units[static_cast<size_t>(b)];
      if (ub.x() - ua.x() > kMergeChordTolerance) break;
      if (group[static_cast<size_t>(b)] < 0 && (ua - ub).norm() <= kMergeChordTolerance)
        group[static_cast<size_t>(b)] = groups;
    }
    ++groups;
  }

  RbfPoints p;
  p.x.setZero(groups);
  p.y.setZero(groups);
  p.z.setZero(groups);
  p.t.setZero(groups);
  p.frame.assign(static_cast<size_t>(groups), 0);
  p.values.setZero(groups, dimension);
  p.counts.assign(static_cast<size_t>(groups), 0);
  p.point_of_keyframe = group;
  if (n > 0) {
    p.frame_origin = std::min_element(keyframes.begin(), keyframes.end(), [](auto& a, auto& b) {
                       return a.frame < b.frame;
                     })->frame;
  }
  for (int k = 0; k < n; ++k) {
    const int g = group[static_cast<size_t>(k)];
    const Keyframe& kf = keyframes[static_cast<size_t>(k)];
    if (p.counts[static_cast<size_t>(g)] == 0) {
      // The first keyframe of a group gives the centre's direction (the others are within 1e-12).
      const Eigen::Vector3d& u = units[static_cast<size_t>(k)];
      p.x[g] = u.x();
      p.y[g] = u.y();
      p.z[g] = u.z();
      p.frame[static_cast<size_t>(g)] = kf.frame;
      p.t[g] = static_cast<double>(kf.frame - p.frame_origin);
    }
    p.values.row(g) += Eigen::Map<const Eigen::RowVectorXd>(kf.params.data(), dimension);
    ++p.counts[static_cast<size_t>(g)];
  }
  for (int g = 0; g < groups; ++g) p.values.row(g) /= p.counts[static_cast<size_t>(g)];
  return p;
}

bool PolynomialBasis::has(Column c) const {
  return std::find(columns.begin(), columns.end(), static_cast<int>(c)) != columns.end();
}

void PolynomialBasis::row(const Eigen::Vector3d& n, double t, double* out) const {
  int j = 0;
  for (int c : columns) {
    switch (c) {
      case One: out[j] = 1.0; break;
      case X: out[j] = (n.x() - dir_shift.x()) / dir_scale; break;
      case Y: out[j] = (n.y() - dir_shift.y()) / dir_scale; break;
      case Z: out[j] = (n.z() - dir_shift.z()) / dir_scale; break;
      case T: out[j] = (t - t_shift) / t_scale; break;
      default: break;
    }
    ++j;
  }
}

PolynomialBasis select_polynomial_basis(const RbfPoints& points) {
  PolynomialBasis b;
  const int m = points.size();
  if (m == 0) return b;
  b.columns.push_back(PolynomialBasis::One);
  const std::array<const Eigen::ArrayXd*, 4> in = {&points.x, &points.y, &points.z, &points.t};
  std::array<double, 4> lo{}, hi{};
  for (int c = 0; c < 4; ++c) {
    lo[static_cast<size_t>(c)] = in[static_cast<size_t>(c)]->minCoeff();
    hi[static_cast<size_t>(c)] = in[static_cast<size_t>(c)]->maxCoeff();
  }
  double dir_half = 0.0;
  for (int c = 0; c < 3; ++c) {
    b.dir_shift[c] = 0.5 * (lo[static_cast<size_t>(c)] + hi[static_cast<size_t>(c)]);
    dir_half = std::max(dir_half, 0.5 * (hi[static_cast<size_t>(c)] - lo[static_cast<size_t>(c)]));
  }
  b.dir_scale = std::max(dir_half, kMinDirectionScale);
  b.t_shift = 0.5 * (lo[3] + hi[3]);
  b.t_scale = std::max(0.5 * (hi[3] - lo[3]), 1.0);  // frames are integers: 1 frame minimum
  const int max_linear = std::max(0, m - 2);
  if (max_linear == 0) return b;

  Eigen::MatrixXd c(m, 4);
  c.col(0) = ((points.x - b.dir_shift.x()) / b.dir_scale).matrix();
  c.col(1) = ((points.y - b.dir_shift.y()) / b.dir_scale).matrix();
  c.col(2) = ((points.z - b.dir_shift.z()) / b.dir_scale).matrix();
  c.col(3) = ((points.t - b.t_shift) / b.t_scale).matrix();
  // Project out the constant (which is always kept) so the QR measures what each column adds.
  c.rowwise() -= c.colwise().mean();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(c);
  const double tol = kPolynomialRankTolerance * std::sqrt(static_cast<double>(m));
  const Eigen::Index k = std::min<Eigen::Index>(4, m);
  for (Eigen::Index i = 0; i < k && static_cast<int>(b.columns.size()) - 1 < max_linear; ++i) {
    if (std::abs(qr.matrixQR()(i, i)) <= tol) break;
    b.columns.push_back(1 + qr.colsPermutation().indices()[i]);
  }
  std::sort(b.columns.begin(), b.columns.end());
  return b;
}

}  // namespace vdfx::effects
