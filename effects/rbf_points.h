/// @file
/// @brief RBF centres in structure-of-arrays form, keyframe merging, and the polynomial basis.
///
/// Keyframes at one place (within kMergeChordTolerance) and one frame are one centre: their
/// values are averaged and counted. Frames are stored relative to an origin frame as doubles;
/// they are integers below 2^53, so frame differences stay exact.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "effects/keyframe.h"

namespace vdfx::effects {

/// Keyframes closer than this (chord of unit vectors, ~ radians) at one frame are merged.
inline constexpr double kMergeChordTolerance = 1e-12;

struct RbfPoints {
  Eigen::ArrayXd x, y, z;           //!< unit direction of each centre (OpenXR axes)
  Eigen::ArrayXd t;                 //!< frame - frame_origin, an exact integer
  std::vector<std::int64_t> frame;  //!< the frame of each centre
  std::int64_t frame_origin = 0;
  Eigen::MatrixXd values;              //!< m x D: the (averaged) parameters
  std::vector<int> counts;             //!< keyframes merged into each centre
  std::vector<int> point_of_keyframe;  //!< input keyframe -> centre

  int size() const { return static_cast<int>(x.size()); }
  int dimension() const { return static_cast<int>(values.cols()); }
  int merged() const;  //!< input keyframes that joined another centre
  Eigen::Vector3d unit(int i) const { return {x[i], y[i], z[i]}; }
  /// Appends one centre (no merging); used by incremental updates.
  void append(const Eigen::Vector3d& n, std::int64_t f, const Eigen::RowVectorXd& v);
  /// Removes centre i by moving the last centre into its place.
  void swap_remove(int i);
};

/// Builds the centres: checks each keyframe has `dimension` finite parameters and a finite
/// direction (throws std::invalid_argument naming the keyframe otherwise) and merges coincident
/// ones. Frames are stored relative to the smallest frame.
RbfPoints merge_keyframes(std::span<const Keyframe> keyframes, int dimension);

/// The linear polynomial of the contract: candidate columns 1, x, y, z, t, each input centred
/// (midrange) and scaled; directions share one scale (the fit stays rotation invariant and a
/// coordinate that hardly varies stays small instead of being blown up to [-1, 1]).
struct PolynomialBasis {
  enum Column { One = 0, X, Y, Z, T };
  Eigen::Vector3d dir_shift = Eigen::Vector3d::Zero();
  double dir_scale = 1.0;
  double t_shift = 0.0;
  double t_scale = 1.0;
  std::vector<int> columns;  //!< active columns, ascending; One first whenever non-empty

  int size() const { return static_cast<int>(columns.size()); }
  bool has(Column c) const;
  /// The basis row at a point (t relative to the same frame origin as the centres).
  void row(const Eigen::Vector3d& n, double t, double* out) const;
  bool same_columns(const PolynomialBasis& o) const { return columns == o.columns; }
};

/// Rank tolerance of the polynomial term selection, relative to sqrt(m) (scaled inputs are in
/// [-1, 1], so a determined column has |R_kk| of order sqrt(m)).
inline constexpr double kPolynomialRankTolerance = 1e-8;
/// Direction spreads below this count as a single direction (1e-6 rad ~ 0.2 arc seconds);
/// sin/cos roundoff at the poles is 1e-16.
inline constexpr double kMinDirectionScale = 1e-6;

/// Chooses the columns the centres determine: a column-pivoted Householder QR of the centred
/// linear columns with the constant projected out; pivots below tolerance are dropped, and the
/// polynomial keeps at most m - 1 terms so the radial part always shapes the interpolant.
PolynomialBasis select_polynomial_basis(const RbfPoints& points);

}  // namespace vdfx::effects
