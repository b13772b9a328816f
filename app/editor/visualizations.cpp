/// @file
/// @brief Effect tracks, minimap, markers and nearest keyframes.
#include "app/editor/visualizations.h"

#include <algorithm>
#include <cmath>

#include "ui/colour_wheel.h"

namespace vdfx::app {

using effects::EffectType;

double display_value(EditTarget target, std::span<const double> p) {
  if (target == EffectType::Tint) return ui::hue_sat_from_tint_gain({p[0], p[1], p[2]}).y;
  return p[0];
}

std::pair<double, double> display_range(EditTarget target) {
  if (target == EffectType::Tint) return {0.0, 1.0};
  const auto& ps = target.params().front();
  return {ps.min, ps.max};
}

std::vector<std::int64_t> track_sample_frames(std::int64_t frame_count, int max_samples) {
  std::vector<std::int64_t> out;
  if (frame_count <= max_samples || max_samples < 2) {
    for (std::int64_t f = 0; f < frame_count; ++f) out.push_back(f);
    return out;
  }
  for (int i = 0; i < max_samples; ++i)
    out.push_back(static_cast<std::int64_t>(std::llround(
        static_cast<double>(i) * static_cast<double>(frame_count - 1) / (max_samples - 1))));
  return out;
}

namespace {
// What is drawn at a view: the stack's clamped (tint: normalised) values; a flare's or grain's
// first value clamped to its range, as their renderers clamp it.
double value_at(const effects::RbfInterpolator* rbf, EditTarget target, const Eigen::Vector3d& unit,
                std::int64_t frame) {
  const bool solved = rbf && !rbf->empty();
  const Eigen::VectorXd v = solved ? rbf->evaluate(unit, frame) : Eigen::VectorXd();
  if (const auto type = target.stack_effect()) {
    effects::StackParams sp;
    if (solved)
      sp.set(*type, std::span<const double>(v.data(), static_cast<std::size_t>(v.size())));
    return display_value(target, sp.get(*type));
  }
  const auto& first = target.params().front();
  return solved ? std::clamp(v[0], first.min, first.max) : first.neutral;
}
}  // namespace

std::vector<double> effect_track(const effects::RbfInterpolator* rbf, EditTarget target,
                                 const effects::Direction& direction,
                                 std::span<const std::int64_t> frames,
                                 const effects::AnchorFrames& anchor) {
  const Eigen::Vector3d unit = effects::to_unit(direction);
  std::vector<double> out;
  out.reserve(frames.size());
  for (const auto f : frames) out.push_back(value_at(rbf, target, anchor.apply(unit, f), f));
  return out;
}

effects::Direction minimap_cell_direction(int x, int y, int width, int height) {
  return effects::from_equirect_uv({(x + 0.5) / width, (y + 0.5) / height});
}

cv::Mat effect_minimap(const effects::RbfInterpolator* rbf, EditTarget target, std::int64_t frame,
                       int width, int height, const std::atomic<bool>* cancel,
                       const effects::AnchorFrames& anchor) {
  cv::Mat field(height, width, CV_32FC1);
  for (int y = 0; y < height; ++y) {
    if (cancel && cancel->load(std::memory_order_relaxed)) return {};
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector3d cell = effects::to_unit(minimap_cell_direction(x, y, width, height));
      field.at<float>(y, x) =
          static_cast<float>(value_at(rbf, target, anchor.apply(cell, frame), frame));
    }
  }
  return field;
}

std::vector<std::size_t> keyframes_near_view(std::span<const effects::Keyframe> keyframes,
                                             const effects::Direction& view, double cone_deg) {
  const Eigen::Vector3d v = effects::to_unit(view);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < keyframes.size(); ++i)
    if (effects::angle_between(v, effects::to_unit(keyframes[i].direction)) * effects::kRadToDeg <=
        cone_deg)
      out.push_back(i);
  return out;
}

std::optional<std::size_t> nearest_keyframe(std::span<const effects::Keyframe> keyframes,
                                            const effects::Direction& view, std::int64_t frame,
                                            double time_scale, double fps) {
  const Eigen::Vector3d v = effects::to_unit(view);
  std::optional<std::size_t> best;
  double best_d = 0.0;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const double a = effects::angle_between(v, effects::to_unit(keyframes[i].direction));
    const double dt =
        static_cast<double>(std::llabs(keyframes[i].frame - frame)) * (24.0 / fps) * time_scale;
    const double d = std::hypot(a, dt);
    if (!best || d < best_d) best = i, best_d = d;
  }
  return best;
}

std::optional<std::size_t> adjacent_keyframe(std::span<const effects::Keyframe> keyframes,
                                             const effects::Direction& view, std::int64_t frame,
                                             int step, const effects::AnchorFrames& anchor) {
  std::optional<std::int64_t> target;
  for (const auto& k : keyframes) {
    const bool ahead = step > 0 ? k.frame > frame : k.frame < frame;
    if (!ahead) continue;
    if (!target || (step > 0 ? k.frame < *target : k.frame > *target)) target = k.frame;
  }
  if (!target) return std::nullopt;
  const Eigen::Vector3d v = anchor.apply(effects::to_unit(view), *target);
  std::optional<std::size_t> best;
  double best_a = 0.0;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    if (keyframes[i].frame != *target) continue;
    const double a = effects::angle_between(v, effects::to_unit(keyframes[i].direction));
    if (!best || a < best_a) best = i, best_a = a;
  }
  return best;
}

}  // namespace vdfx::app
