/// @file
/// @brief What one view pixel shows of an equirect image: the image filtered over the pixel's
/// footprint, anisotropic where the equirect stretches (docs/effects.md, "Sampling a view").
///
/// The pixel square maps, to first order, onto the parallelogram spanned by the columns of J,
/// the Jacobian of the texture position (u, v) in level-0 texels with respect to the pixel
/// position: equirect_jacobian(), analytic (the pinhole ray's derivatives through the equirect
/// mapping), so nothing jumps at the azimuth seam. Its singular values s1 >= s2 are the lengths
/// of the footprint's major and minor axes (the box with the parallelogram's second moments),
/// its right singular vector the screen direction of the major axis.
///
/// The filter (footprint_taps()): taps along the major axis through the pixel centre, each one a
/// trilinear lookup in the mip chain (effects/mip_chain.h) at the level that matches the minor
/// axis, weighted as a box one pixel wide along that axis:
/// - r = clamp(s1 / max(s2, 1), 1, max_anisotropy) (s1 capped at one turn of azimuth, s2 at s1),
///   the spacing of the taps is 1 / r pixels, tap k sits at k / r pixels from the centre,
///   k = -K..K with K = ceil((r - 1) / 2), and weighs the part of [-1/2, 1/2] nearer to it than
///   to its neighbours ([k/r - 1/(2r), k/r + 1/(2r)] clipped to the pixel): every weight is a
///   continuous function of the footprint, so a tap appears with weight 0 and float and double
///   arithmetic never choose visibly different filters;
/// - lod = log2(max(s1 / r, s2, 1)): level 0 (bilinear) where the view enlarges the image,
///   the minor axis' level where it shrinks it, coarser only where the anisotropy exceeds
///   max_anisotropy (right at a pole).
/// Each tap's texture position is its own ray's (the ray through the pixel position of the tap),
/// so taps follow the footprint round a pole and wrap at the seam like any ray. The GPU's video
/// layer runs the same formulas in GLSL (effects/video_shaders.cpp).
#pragma once

#include <Eigen/Core>

namespace vdfx::effects {

/// Default largest ratio of the footprint's axes that taps resolve (the `vdfx bench` knob).
inline constexpr double kDefaultMaxAnisotropy = 16.0;

/// Texels per turn of azimuth and per half turn of altitude of an image (for a 360 image its
/// width and height; a 180 image spans half a turn in its width).
struct TexelScale {
  double per_turn = 0.0;
  double per_half_turn = 0.0;
};

/// d(u, v) / d(x, y) in level-0 texels (columns: x, y; rows: u, v with v down), for the
/// unnormalised world ray `d` whose change per pixel step is `ex` (in x) and `ey` (in y). Finite
/// everywhere: within 1e-6 of a radian of the pole axis, where every azimuth meets, the
/// azimuth's rate is |e_xz| / 1e-6 (that of a ray so far from the axis, moved across it) and the
/// altitude's 0.
Eigen::Matrix2d equirect_jacobian(const Eigen::Vector3d& d, const Eigen::Vector3d& ex,
                                  const Eigen::Vector3d& ey, const TexelScale& texels);

/// The taps of one pixel (see the file comment).
struct FootprintTaps {
  Eigen::Vector2d axis{1.0, 0.0};  //!< unit screen direction of the major axis (x, y as J's)
  double spacing = 1.0;            //!< pixels between neighbouring taps (1 / r)
  int half_count = 0;              //!< K: taps k = -K..K
  double lod = 0.0;                //!< mip level of every tap (>= 0)
  /// Tap k's share of the pixel (the shares of k = -K..K sum to 1).
  double weight(int k) const;
};

/// The taps for Jacobian `j` (texels per pixel), at most `max_anisotropy` (>= 1) taps' worth of
/// stretch resolved; `turn_texels` caps the major axis at one turn of azimuth.
FootprintTaps footprint_taps(const Eigen::Matrix2d& j, double max_anisotropy, double turn_texels);

}  // namespace vdfx::effects
