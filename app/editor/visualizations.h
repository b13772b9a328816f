/// @file
/// @brief What the editor shows about the keyframes: the effect track (one parameter over time
/// at the view), the effect minimap (one parameter over the sphere at a frame), which keyframes
/// lie near the view, and the keyframe nearest the view. Pure functions of the interpolant.
///
/// Directions given are of the video frame (the view, the minimap's cells); keyframes are stored
/// in their effect's anchor's frame (effects/anchor.h), so the anchor, where one is given, turns
/// the view at each frame before it is compared or evaluated. The default is the video anchor.
#pragma once

#include <atomic>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/edit_target.h"
#include "effects/anchor.h"
#include "effects/keyframe.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::app {

/// The one number the plot and the minimap show for a target: blur sigma, exposure stops,
/// saturation and contrast amounts, vignette radius, flare and grain intensity; tint: the colour
/// wheel's saturation.
double display_value(EditTarget target, std::span<const double> params);
/// The range of display_value (the contract's range; tint saturation [0, 1]).
std::pair<double, double> display_range(EditTarget target);

/// Frames at which the track is sampled: all frames up to `max_samples`, else evenly spaced
/// (first and last included).
std::vector<std::int64_t> track_sample_frames(std::int64_t frame_count, int max_samples);

/// display_value of the interpolant at `direction` (of the video frame at each frame, turned by
/// `anchor` there) for each of `frames` (neutral when null).
std::vector<double> effect_track(const effects::RbfInterpolator* rbf, EditTarget target,
                                 const effects::Direction& direction,
                                 std::span<const std::int64_t> frames,
                                 const effects::AnchorFrames& anchor = {});

/// display_value over an equirect grid (CV_32FC1, width x height, row 0 at the top); cell (x, y)
/// is the direction at uv ((x + 0.5) / width, (y + 0.5) / height) of the video frame at `frame`
/// (turned by `anchor` before it is evaluated). `cancel` (optional) is polled between rows: once
/// true, an empty Mat is returned (MinimapWorker's shutdown).
cv::Mat effect_minimap(const effects::RbfInterpolator* rbf, EditTarget target, std::int64_t frame,
                       int width, int height, const std::atomic<bool>* cancel = nullptr,
                       const effects::AnchorFrames& anchor = {});
effects::Direction minimap_cell_direction(int x, int y, int width, int height);

/// Indices of the keyframes within `cone_deg` of the view direction (any frame; the view in the
/// keyframes' frame).
std::vector<std::size_t> keyframes_near_view(std::span<const effects::Keyframe> keyframes,
                                             const effects::Direction& view, double cone_deg);

/// The keyframe nearest the view in the contract's RBF distance
/// sqrt(angle^2 + (|df| 24 / fps c)^2) (angle in radians; the view in the keyframes' frame),
/// nullopt when there is none.
std::optional<std::size_t> nearest_keyframe(std::span<const effects::Keyframe> keyframes,
                                            const effects::Direction& view, std::int64_t frame,
                                            double time_scale, double fps);

/// The keyframe to jump to from `frame`: the nearest frame strictly after (step +1) or before
/// (step -1); among keyframes on that frame the one nearest the view (of the video frame, turned
/// by `anchor` at that frame). nullopt when none.
std::optional<std::size_t> adjacent_keyframe(std::span<const effects::Keyframe> keyframes,
                                             const effects::Direction& view, std::int64_t frame,
                                             int step, const effects::AnchorFrames& anchor = {});

}  // namespace vdfx::app
