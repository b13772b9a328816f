/// @file
/// @brief The editing state of one effect's keyframes interpolated locally in time
/// (effects/rbf_windows.h): the windows' solves, kept across edits. An edit re-solves only the
/// windows whose keyframes it changes (two to four for a keyframe placed or moved, each a dense
/// solve of about 3.5 reaches' keyframes); the others are shared, unchanged, with the published
/// interpolators. The result is the same, bit for bit, as a fresh RbfInterpolator of the same
/// keyframes in the same order: the windows' keyframes are taken in the same order (by frame,
/// then by index).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "effects/keyframe.h"
#include "effects/rbf_interpolator.h"
#include "effects/rbf_windows.h"

namespace vdfx::effects {

/// What one edit did to the keyframe list (KeyframeSet's add, move, remove, set_params).
struct KeyframeChange {
  enum Kind { Added, Removed, Moved, Values } kind = Values;
  std::size_t index = 0;       //!< the keyframe's index (Removed: before the removal)
  std::int64_t old_frame = 0;  //!< its frame before (Moved, Removed, Values)
  std::int64_t new_frame = 0;  //!< its frame after (Added, Moved, Values)
};

class KeyframeWindows {
 public:
  /// Solves every window of the layout plan_windows gives these keyframes (which must plan
  /// one: std::logic_error otherwise). Unlike RbfInterpolator's constructor it solves a window
  /// fuller than kMaxWindowKeyframes too (slowly): an edit is never refused; a sidecar that
  /// holds one is (the validator reports window_problem). Throws std::invalid_argument on a
  /// wrong parameter count.
  KeyframeWindows(const std::vector<Keyframe>& keyframes, int dimension,
                  const InterpolationSettings& settings, double fps,
                  const Eigen::VectorXd& neutral);
  /// The same for a whole new list (undo, redo), keeping the solves of `previous` (made for
  /// `previous_keyframes`, with the same settings) whose windows hold the same keyframes.
  KeyframeWindows(const std::vector<Keyframe>& keyframes, int dimension,
                  const InterpolationSettings& settings, double fps, const Eigen::VectorXd& neutral,
                  const KeyframeWindows& previous, const std::vector<Keyframe>& previous_keyframes);

  /// Follows one edit: `keyframes` is the list after it. Re-solves the windows whose keyframes
  /// changed and returns true; false when the keyframes now plan another layout or the global
  /// solve (this object is then stale: the caller solves afresh).
  bool update(const std::vector<Keyframe>& keyframes, const KeyframeChange& change);

  /// The interpolator of the current keyframes (shares the windows' solves).
  std::shared_ptr<const RbfInterpolator> interpolator() const { return interpolator_; }
  const WindowLayout& layout() const { return layout_; }
  /// Windows solved by the last update (or by the constructor).
  int last_solved() const { return last_solved_; }

 private:
  void solve_all(const std::vector<Keyframe>& keyframes, const KeyframeWindows* previous,
                 const std::vector<Keyframe>* previous_keyframes);
  /// previous's solve of the window at J = layout_.first + j when it held the same keyframes.
  std::shared_ptr<const RbfInterpolator> reusable(
      const std::vector<Keyframe>& keyframes, int j, const KeyframeWindows& previous,
      const std::vector<Keyframe>& previous_keyframes) const;
  void insert(std::size_t index, std::int64_t frame);
  void erase(std::size_t index, std::int64_t frame);
  void publish();

  int dimension_;
  InterpolationSettings settings_;
  double fps_;
  RbfKernel kernel_;
  Eigen::VectorXd neutral_;
  WindowLayout layout_;
  std::vector<std::size_t> order_;    //!< keyframe indices by (frame, index)
  std::vector<std::int64_t> frames_;  //!< their frames (ascending)
  std::vector<WindowData> data_;
  std::vector<std::shared_ptr<const RbfInterpolator>> solved_;
  std::vector<RbfInterpolator::WindowCore> cores_;  //!< core_counts of each window
  std::shared_ptr<const RbfInterpolator> interpolator_;
  int last_solved_ = 0;
};

}  // namespace vdfx::effects
