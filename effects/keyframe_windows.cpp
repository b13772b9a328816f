/// @file
/// @brief KeyframeWindows: local interpolation's windows kept across edits.
#include "effects/keyframe_windows.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace vdfx::effects {

KeyframeWindows::KeyframeWindows(const std::vector<Keyframe>& keyframes, int dimension,
                                 const InterpolationSettings& settings, double fps,
                                 const Eigen::VectorXd& neutral)
    : dimension_(dimension),
      settings_(settings),
      fps_(fps),
      kernel_(RbfKernel::from(settings, fps)),
      neutral_(neutral) {
  solve_all(keyframes, nullptr, nullptr);
}

KeyframeWindows::KeyframeWindows(const std::vector<Keyframe>& keyframes, int dimension,
                                 const InterpolationSettings& settings, double fps,
                                 const Eigen::VectorXd& neutral, const KeyframeWindows& previous,
                                 const std::vector<Keyframe>& previous_keyframes)
    : dimension_(dimension),
      settings_(settings),
      fps_(fps),
      kernel_(RbfKernel::from(settings, fps)),
      neutral_(neutral) {
  solve_all(keyframes, &previous, &previous_keyframes);
}

void KeyframeWindows::solve_all(const std::vector<Keyframe>& keyframes,
                                const KeyframeWindows* previous,
                                const std::vector<Keyframe>* previous_keyframes) {
  order_.resize(keyframes.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return keyframes[a].frame < keyframes[b].frame;
  });
  frames_.resize(order_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) frames_[i] = keyframes[order_[i]].frame;
  const auto layout = plan_windows(settings_, fps_, frames_);
  if (!layout) throw std::logic_error("KeyframeWindows: these keyframes are solved globally");
  if (layout->count > kMaxWindows)
    throw std::invalid_argument(
        "KeyframeSet: " + window_problem(settings_, fps_, frames_).value_or("too many windows"));
  layout_ = *layout;
  data_ = window_data(layout_, frames_);
  solved_.assign(data_.size(), nullptr);
  cores_.assign(data_.size(), {});
  last_solved_ = 0;
  for (std::size_t j = 0; j < data_.size(); ++j) {
    if (j > 0 && data_[j] == data_[j - 1]) {
      solved_[j] = solved_[j - 1];
    } else {
      if (previous)
        solved_[j] = reusable(keyframes, static_cast<int>(j), *previous, *previous_keyframes);
      if (!solved_[j]) {
        solved_[j] = RbfInterpolator::solve_window(keyframes, order_, data_[j], dimension_,
                                                   settings_, fps_, neutral_);
        ++last_solved_;
      }
    }
    cores_[j] = RbfInterpolator::core_counts(*solved_[j], layout_, static_cast<int>(j));
  }
  publish();
}

std::shared_ptr<const RbfInterpolator> KeyframeWindows::reusable(
    const std::vector<Keyframe>& keyframes, int j, const KeyframeWindows& previous,
    const std::vector<Keyframe>& previous_keyframes) const {
  if (previous.layout_.width != layout_.width) return nullptr;
  const std::int64_t o = layout_.first + j - previous.layout_.first;
  if (o < 0 || o >= static_cast<std::int64_t>(previous.data_.size())) return nullptr;
  const WindowData& now = data_[static_cast<std::size_t>(j)];
  const WindowData& then = previous.data_[static_cast<std::size_t>(o)];
  if (now.lo != then.lo || now.hi != then.hi || now.size() != then.size()) return nullptr;
  for (std::size_t i = 0; i < now.size(); ++i)
    if (!(keyframes[order_[now.begin + i]] == previous_keyframes[previous.order_[then.begin + i]]))
      return nullptr;
  return previous.solved_[static_cast<std::size_t>(o)];
}

void KeyframeWindows::insert(std::size_t index, std::int64_t frame) {
  // (frame, index) order: after every keyframe at an earlier frame or a lower index.
  std::size_t lo = 0, hi = order_.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (frames_[mid] < frame || (frames_[mid] == frame && order_[mid] < index))
      lo = mid + 1;
    else
      hi = mid;
  }
  order_.insert(order_.begin() + static_cast<std::ptrdiff_t>(lo), index);
  frames_.insert(frames_.begin() + static_cast<std::ptrdiff_t>(lo), frame);
}

void KeyframeWindows::erase(std::size_t index, std::int64_t frame) {
  auto it = std::lower_bound(frames_.begin(), frames_.end(), frame);
  std::size_t p = static_cast<std::size_t>(it - frames_.begin());
  while (p < order_.size() && order_[p] != index) ++p;
  order_.erase(order_.begin() + static_cast<std::ptrdiff_t>(p));
  frames_.erase(frames_.begin() + static_cast<std::ptrdiff_t>(p));
}

bool KeyframeWindows::update(const std::vector<Keyframe>& keyframes, const KeyframeChange& c) {
  std::int64_t touched[2] = {c.new_frame, c.old_frame};
  switch (c.kind) {
    case KeyframeChange::Added:
      for (std::size_t& i : order_)
        if (i >= c.index) ++i;
      insert(c.index, c.new_frame);
      touched[1] = c.new_frame;
      break;
    case KeyframeChange::Removed:
      erase(c.index, c.old_frame);
      for (std::size_t& i : order_)
        if (i > c.index) --i;
      touched[0] = c.old_frame;
      break;
    case KeyframeChange::Moved:
      erase(c.index, c.old_frame);
      insert(c.index, c.new_frame);
      break;
    case KeyframeChange::Values: break;
  }
  const auto layout = plan_windows(settings_, fps_, frames_);
  if (!layout || layout->width != layout_.width || layout->count > kMaxWindows) return false;
  std::vector<WindowData> data = window_data(*layout, frames_);
  std::vector<std::shared_ptr<const RbfInterpolator>> solved(data.size());
  std::vector<RbfInterpolator::WindowCore> cores(data.size());
  last_solved_ = 0;
  for (std::size_t j = 0; j < data.size(); ++j) {
    const WindowData& d = data[j];
    const std::int64_t old = layout->first + static_cast<std::int64_t>(j) - layout_.first;
    const bool hit =
        (touched[0] >= d.lo && touched[0] <= d.hi) || (touched[1] >= d.lo && touched[1] <= d.hi);
    // Same frames and no changed keyframe among them: the same keyframes in the same order.
    if (!hit && old >= 0 && old < static_cast<std::int64_t>(data_.size()) &&
        data_[static_cast<std::size_t>(old)].lo == d.lo &&
        data_[static_cast<std::size_t>(old)].hi == d.hi) {
      solved[j] = solved_[static_cast<std::size_t>(old)];
      cores[j] = cores_[static_cast<std::size_t>(old)];  // the same keyframes: the same core
      continue;
    }
    if (j > 0 && d == data[j - 1]) {
      solved[j] = solved[j - 1];
    } else {
      solved[j] = RbfInterpolator::solve_window(keyframes, order_, d, dimension_, settings_, fps_,
                                                neutral_);
      ++last_solved_;
    }
    cores[j] = RbfInterpolator::core_counts(*solved[j], *layout, static_cast<int>(j));
  }
  layout_ = *layout;
  data_ = std::move(data);
  solved_ = std::move(solved);
  cores_ = std::move(cores);
  publish();
  return true;
}

void KeyframeWindows::publish() {
  interpolator_ = std::make_shared<const RbfInterpolator>(
      layout_, solved_, cores_, kernel_, neutral_, frames_.front(), frames_.back());
}

}  // namespace vdfx::effects
