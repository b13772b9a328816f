/// @file
/// @brief The mip chain every equirect sampler of the project filters from, defined once.
///
/// Level 0 is the image. Level l + 1 has GL's size, max(1, w_l / 2) x max(1, h_l / 2) (integer
/// division), down to 1 x 1, and each of its texels is the exact area average of the level-l
/// texels under it: texel k of a side of n -> m texels covers [k n / m, (k + 1) n / m) of level l,
/// each level-l texel weighted by how much of it lies inside (a plain 2 x 2 mean where n is even,
/// three or four weighted texels where n is odd). The CPU builds it here; the GPU builds the same
/// chain with mip_level_fragment_source() (effects/video_shaders.h) into its texture's levels, so
/// both filter from the same numbers (glGenerateMipmap leaves odd sizes to the driver).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace vdfx::effects {

/// Levels of the full chain of a width x height image (GL's count: down to 1 x 1).
int mip_level_count(int width, int height);

/// Level l + 1 of `level` (float images, any channel count; CV_32F in, CV_32F out).
cv::Mat mip_reduce(const cv::Mat& level);

/// Every level, [0] sharing `image`'s pixels. `image` must be non-empty float (CV_32F).
std::vector<cv::Mat> build_mip_chain(const cv::Mat& image);

}  // namespace vdfx::effects
