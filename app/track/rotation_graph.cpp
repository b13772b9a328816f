/// @file
/// @brief average_rotations: Gauss-Newton over key frame orientations (rotation_graph.h).
#include "app/track/rotation_graph.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace vdfx::app::track {
namespace {

Eigen::Vector3d log_of(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

Eigen::Matrix3d exp_of(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

/// One Gauss-Newton step; returns the largest residual before it.
double step(std::vector<Eigen::Matrix3d>& q, const std::vector<RotationLink>& links) {
  const int unknowns = 3 * (static_cast<int>(q.size()) - 1);
  std::vector<Eigen::Triplet<double>> h;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(unknowns);
  double worst = 0.0;
  const auto add_block = [&h](int r, int c, const Eigen::Matrix3d& m) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) h.emplace_back(r + i, c + j, m(i, j));
  };
  for (const RotationLink& l : links) {
    const Eigen::Vector3d r = log_of(l.rotation.transpose() * q[l.to].transpose() * q[l.from]);
    worst = std::max(worst, r.norm());
    // Residual r + J_from d_from + J_to d_to, J_from = I, J_to = -R^T; key frame 0 is fixed.
    const Eigen::Matrix3d jt = -l.rotation.transpose();
    const int a = 3 * (l.from - 1), b = 3 * (l.to - 1);
    if (l.from > 0) {
      add_block(a, a, l.weight * Eigen::Matrix3d::Identity());
      g.segment<3>(a) += l.weight * r;
    }
    if (l.to > 0) {
      add_block(b, b, l.weight * jt.transpose() * jt);
      g.segment<3>(b) += l.weight * jt.transpose() * r;
    }
    if (l.from > 0 && l.to > 0) {
      add_block(a, b, l.weight * jt);
      add_block(b, a, l.weight * jt.transpose());
    }
  }
  // A little damping keeps a key frame that no link reaches at its value instead of making the
  // system singular.
  for (int i = 0; i < unknowns; ++i) h.emplace_back(i, i, 1e-9);
  Eigen::SparseMatrix<double> m(unknowns, unknowns);
  m.setFromTriplets(h.begin(), h.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(m);
  if (solver.info() != Eigen::Success) return worst;
  const Eigen::VectorXd d = solver.solve(-g);
  for (std::size_t i = 1; i < q.size(); ++i)
    q[i] = q[i] * exp_of(d.segment<3>(3 * static_cast<Eigen::Index>(i - 1)));
  return worst;
}

}  // namespace

double rotation_angle(const Eigen::Matrix3d& r) {
  return std::acos(std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0));
}

double average_rotations(std::vector<Eigen::Matrix3d>& orientations,
                         const std::vector<RotationLink>& links, int iterations) {
  if (orientations.size() < 2 || links.empty()) return 0.0;
  for (int it = 0; it < iterations; ++it) step(orientations, links);
  double worst = 0.0;
  for (const RotationLink& l : links)
    worst = std::max(worst, log_of(l.rotation.transpose() * orientations[l.to].transpose() *
                                   orientations[l.from])
                                .norm());
  return worst;
}

}  // namespace vdfx::app::track
