/// @file
/// @brief FlareSet: intensity RBFs, light sources, layouts.
#include "effects/flare_set.h"

#include <algorithm>
#include <stdexcept>

#include "effects/flare_light.h"

namespace vdfx::effects {

namespace {

// The RBF reproduces a keyframe's 0 only to rounding; below this the brightest element (peak
// 1.05 x intensity) adds under 0.03 of an 8-bit step, so the flare is not drawn at all.
constexpr double kMinDrawnIntensity = 1e-4;

}  // namespace

FlareSet::FlareSet(std::vector<FlareEffect> flares, const InterpolationSettings& defaults,
                   double fps, const AnchorSources& anchors, AutoLightOptions auto_options)
    : tracker_(auto_options) {
  replace_flares(std::move(flares), defaults, fps, anchors);
}

void FlareSet::replace_flares(std::vector<FlareEffect> flares,
                              const InterpolationSettings& defaults, double fps,
                              const AnchorSources& anchors) {
  std::vector<std::shared_ptr<const RbfInterpolator>> intensity;
  std::vector<AnchorFrames> frames;
  AnchorResolver resolve(anchors);
  bool uses_auto = false;
  for (const FlareEffect& f : flares) {
    frames.push_back(resolve.resolve(f.anchor).frames);
    intensity.push_back(std::make_shared<const RbfInterpolator>(
        f.keyframes, 1, f.interpolation.value_or(defaults), fps,
        std::vector<double>{kFlareIntensitySpec.neutral}));
    uses_auto = uses_auto || std::holds_alternative<AutoLight>(f.light);
  }
  flares_ = std::move(flares);
  intensity_ = std::move(intensity);
  anchors_ = std::move(frames);
  uses_auto_ = uses_auto;
}

void FlareSet::set_intensity(std::size_t k, std::shared_ptr<const RbfInterpolator> intensity) {
  if (!intensity || intensity->dimension() != 1)
    throw std::invalid_argument("FlareSet::set_intensity: a one-value interpolant is needed");
  intensity_.at(k) = std::move(intensity);
}

void FlareSet::record_light(std::int64_t frame, const std::optional<Eigen::Vector3d>& measured) {
  if (uses_auto_) tracker_.record(frame, measured);
}

void FlareSet::set_auto_lights(std::vector<std::optional<Eigen::Vector3d>> lights) {
  given_lights_ = std::move(lights);
}

double FlareSet::intensity(std::size_t k, const Eigen::Vector3d& gaze, std::int64_t frame) const {
  const RbfInterpolator& rbf = *intensity_.at(k);
  if (rbf.empty()) return kFlareIntensitySpec.neutral;
  double v = 0.0;
  rbf.evaluate_into(anchors_[k].apply(gaze, frame), frame, &v);
  // The RBF may overshoot between keyframes; the sidecar's range holds for what is drawn.
  return std::clamp(v, kFlareIntensitySpec.min, kFlareIntensitySpec.max);
}

std::optional<Eigen::Vector3d> FlareSet::light(std::size_t k, std::int64_t frame) const {
  const FlareLight& l = flares_.at(k).light;
  // A fixed light is a direction of the flare's anchor's frame.
  if (const auto* d = std::get_if<Direction>(&l)) return anchors_[k].unapply(to_unit(*d), frame);
  if (const auto* t = std::get_if<std::vector<LightSample>>(&l)) return light_on_track(*t, frame);
  if (!given_lights_) return tracker_.light(frame);
  if (frame < 0 || frame >= static_cast<std::int64_t>(given_lights_->size())) return std::nullopt;
  return (*given_lights_)[static_cast<std::size_t>(frame)];
}

std::vector<FlareLayout> FlareSet::layouts(const HeadPose& head, std::int64_t frame) const {
  std::vector<FlareLayout> out;
  const Eigen::Vector3d gaze = head.forward().normalized();
  for (std::size_t k = 0; k < flares_.size(); ++k) {
    const double level = intensity(k, gaze, frame);
    if (!(level >= kMinDrawnIntensity)) continue;
    const auto l = light(k, frame);
    if (!l) continue;
    const FlareEffect& f = flares_[k];
    if (auto layout = layout_flare(f.style, f.settings, head, *l, level))
      out.push_back(std::move(*layout));
  }
  return out;
}

}  // namespace vdfx::effects
