/// @file
/// @brief run_suggest (suggest.h): sample the target field, fit it greedily, write the sidecar.
#include "app/suggest/suggest.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "app/cli/command_registry.h"
#include "app/cli/layout_options.h"
#include "io/eye_decoder.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/sidecar.h"
#include "io/sidecar_target.h"

namespace vdfx::app::suggest {

namespace fs = std::filesystem;
using effects::EffectType;

std::vector<std::int64_t> sampled_frames(std::int64_t frames, std::int64_t every,
                                         const std::vector<std::int64_t>& extra) {
  std::set<std::int64_t> out;
  const std::int64_t last = std::max<std::int64_t>(0, frames - 1);
  for (std::int64_t f = 0; f <= last; f += std::max<std::int64_t>(1, every)) out.insert(f);
  out.insert(last);
  for (const std::int64_t f : extra) out.insert(std::clamp<std::int64_t>(f, 0, last));
  return {out.begin(), out.end()};
}

namespace {

struct Clip {
  std::unique_ptr<io::FrameDecoder> decoder;
  effects::StereoLayout layout;  //!< the video's; the analyses see its left eye's image
  std::vector<std::int64_t> frames;
  std::int64_t every = 1;  //!< frames between sampled frames
  Progress* progress = nullptr;

  /// Says how far the suggestion is, and stops it (Cancelled) when asked to.
  void tick(double fraction) const {
    if (!progress) return;
    if (progress->cancel.load()) throw Cancelled();
    progress->fraction.store(std::clamp(fraction, 0.0, 1.0));
  }
};

void check_request(const SuggestRequest& r) {
  if (!(r.strength >= 0.0 && r.strength <= 1.0))
    throw UsageError("--strength must be within [0, 1]");
  if (r.tolerance && !(*r.tolerance > 0.0)) throw UsageError("--tolerance must be greater than 0");
  if (r.max_keyframes < 1 || r.max_keyframes > io::kMaxKeyframesPerEffect)
    throw UsageError("--max-keyframes must be within [1, " +
                     std::to_string(io::kMaxKeyframesPerEffect) + "]");
  if (r.every < 0) throw UsageError("--every must be at least 1");
  if (r.kind == Kind::Guide && r.points.empty())
    throw UsageError("suggest guide needs at least one --poi AZ,ALT[,FROM-TO]");
}

/// Points of interest must lie inside a VR180 image's coverage (docs/suggest.md, "VR180").
void check_points_covered(const SuggestRequest& r, const effects::StereoLayout& layout) {
  for (const PointOfInterest& p : r.points)
    if (effects::coverage_weight(layout, p.direction.azimuth_deg) <= 0.0) {
      std::ostringstream where;
      where << p.direction.azimuth_deg << "," << p.direction.altitude_deg;
      throw io::InputError(r.video.string() + ": --poi " + where.str() +
                           ": outside the video's image (VR180: azimuth -90 to 90)");
    }
}

/// The view directions the target fields are sampled at, and so where keyframes may go: the
/// lattice over the sphere, or the part of it inside a VR180 image (where the editor places
/// keyframes too).
std::vector<effects::Direction> field_directions(const SuggestRequest& r, const Clip& clip) {
  std::vector<effects::Direction> out;
  for (const effects::Direction& d : sphere_directions(r.directions))
    if (effects::coverage_weight(clip.layout, d.azimuth_deg) > 0.0) out.push_back(d);
  return out;
}

/// Opens the video for a suggestion into `sidecar` (none: the --sidecar-in file, else a new
/// sidecar for the video), which records the video's stereo layout.
Clip open_clip(const SuggestRequest& r, Progress* progress, std::optional<io::Sidecar>& sidecar) {
  Clip clip;
  clip.progress = progress;
  io::DecoderOptions decoder_options;
  decoder_options.format = io::PixelFormat::RgbF32;
  // The sampled frames come in order, a second or so apart: decoding on to the next one beats
  // seeking back to its key frame (long-GOP files have one every few seconds).
  decoder_options.max_forward_grab = 120;
  clip.decoder = io::open_frame_decoder(r.video, decoder_options);
  const io::VideoProperties whole = clip.decoder->properties();
  if (!sidecar)
    sidecar =
        r.sidecar_in
            ? io::read_sidecar(*r.sidecar_in)
            : io::new_sidecar({r.video.string(), whole.fps.value(),
                               std::max<std::int64_t>(1, whole.frames), whole.width, whole.height});
  // Stereo: the left eye's image is the sphere the analyses see (docs/stereo.md).
  const effects::StereoLayout layout =
      shown_layout(whole, r.layout, &sidecar->video, r.sidecar_in.value_or(fs::path()));
  check_points_covered(r, layout);
  io::record_layout(sidecar->video, layout);
  clip.layout = layout;
  clip.decoder = io::eye_decoder(std::move(clip.decoder), layout, effects::EyeIndex::Left);
  const auto& p = clip.decoder->properties();
  const double per_second = r.kind == Kind::Comfort ? 6.0 : 1.0;
  const std::int64_t every =
      r.every > 0 ? r.every : std::max<std::int64_t>(1, std::llround(p.fps.value() / per_second));
  std::vector<std::int64_t> extra;
  for (const auto& poi : r.points) {  // both sides of each range's ends (guide_segment)
    extra.push_back(poi.first_frame - 1);
    extra.push_back(poi.first_frame);
    if (poi.last_frame) {
      extra.push_back(*poi.last_frame);
      extra.push_back(*poi.last_frame + 1);
    }
  }
  clip.every = every;
  clip.frames = sampled_frames(p.is_still ? 1 : p.frames, every, extra);
  return clip;
}

/// The exposure target over the sampled directions and frames (metering.h's model).
TargetField exposure_field(const SuggestRequest& r, Clip& clip, SuggestReport& report) {
  const auto& p = clip.decoder->properties();
  const Transfer transfer = transfer_of(p.transfer, p.is_still);
  report.transfer = transfer_name(transfer);
  const MeterGeometry geometry(r.metering.grid_width);
  std::vector<LumaGrid> grids;
  double brightest = 0.0;
  for (const std::int64_t f : clip.frames) {
    clip.decoder->seek(p.is_still ? 0 : f);
    cv::Mat rgb;
    if (clip.decoder->read(rgb) != io::DecodeStatus::Ok)
      throw io::InputError(r.video.string() + ": frame " + std::to_string(f) +
                           " could not be decoded");
    grids.push_back(
        make_luma_grid(rgb, transfer, geometry, r.metering, f, clip.layout.coverage_deg));
    brightest = std::max(brightest, grids.back().max_luma);
    clip.tick(0.5 * static_cast<double>(grids.size()) / static_cast<double>(clip.frames.size()));
  }
  if (brightest <= r.metering.floor)
    throw io::InputError(r.video.string() + ": cannot be metered: every sampled frame (" +
                         std::to_string(grids.size()) + ") is black");
  report.reference_level = reference_level(grids, geometry);
  TargetField field;
  const auto directions = field_directions(r, clip);
  for (const LumaGrid& g : grids)
    for (const auto& d : directions) {
      const double level = metered_level(g, geometry, effects::to_unit(d), r.metering);
      const double stops = std::clamp(r.strength * (report.reference_level - level), -8.0, 8.0);
      field.add(d, g.frame, std::span(&stops, 1));
    }
  return field;
}

/// The guidance targets of one effect (guide.h's falloff).
TargetField guide_field(const SuggestRequest& r, const Clip& clip, EffectType type) {
  TargetField field;
  const auto directions = field_directions(r, clip);
  for (const std::int64_t f : clip.frames)
    for (const auto& d : directions) {
      const double g = r.strength * guide_weight_at(r.points, d, f);
      const double v = type == EffectType::Saturation ? 1.0 - kGuideSaturationDepth * g
                                                      : -kGuideExposureStops * g;
      field.add(d, f, std::span(&v, 1));
    }
  return field;
}

/// The camera's angular speed at every frame (motion.h), degrees per second.
std::vector<double> camera_speeds(const SuggestRequest& r, Clip& clip) {
  const auto& p = clip.decoder->properties();
  if (p.is_still || p.frames < 2)
    throw io::InputError(r.video.string() + ": cannot estimate the camera's motion: it has " +
                         std::to_string(p.frames) + " frame(s)");
  clip.decoder->seek(0);
  std::vector<double> speed(static_cast<std::size_t>(p.frames), 0.0);
  MotionOptions motion = r.motion;
  motion.coverage_deg = clip.layout.coverage_deg;
  cv::Mat rgb, previous;
  for (std::int64_t f = 0; f < p.frames; ++f) {
    if (clip.decoder->read(rgb) != io::DecodeStatus::Ok) {
      previous.release();  // a frame lost: no estimate across the gap
      continue;
    }
    cv::Mat grey = motion_frame(rgb, motion);
    if (!previous.empty())
      speed[static_cast<std::size_t>(f)] =
          estimate_rotation(previous, grey, motion).angle_deg * p.fps.value();
    previous = std::move(grey);
    clip.tick(0.5 * static_cast<double>(f + 1) / static_cast<double>(p.frames));
  }
  speed[0] = speed[1];
  return speed;
}

/// The comfort vignette's targets (comfort.h): the same at every direction of a frame.
TargetField comfort_field(const SuggestRequest& r, Clip& clip, SuggestReport& report) {
  report.speed_deg_per_s = camera_speeds(r, clip);
  const double fps = clip.decoder->properties().fps.value();
  const auto lead = static_cast<std::int64_t>(std::llround(kComfortLeadSeconds * fps));
  const std::vector<double> speed = look_ahead_max(report.speed_deg_per_s, lead);
  TargetField field;
  field.dimension = 2;
  const auto directions = field_directions(r, clip);
  for (const std::int64_t f : clip.frames) {
    const double v[2] = {comfort_radius_deg(speed[static_cast<std::size_t>(f)], r.strength),
                         kComfortFalloffDeg};
    for (const auto& d : directions) field.add(d, f, v);
  }
  return field;
}

effects::EffectTrack& track_of(io::Sidecar& sidecar, EffectType type, bool merge,
                               const SuggestRequest& r) {
  for (auto& t : sidecar.effects)
    if (t.type == type) {
      if (!t.keyframes.empty() && !merge)
        throw io::InputError((r.sidecar_in ? r.sidecar_in->string() : std::string("sidecar")) +
                             ": already has " + std::to_string(t.keyframes.size()) + " " +
                             std::string(effects::effect_name(type)) +
                             " keyframes; pass --merge to add the suggestion to them");
      if (t.keyframes.size() + r.max_keyframes > io::kMaxKeyframesPerEffect)
        throw UsageError("--max-keyframes " + std::to_string(r.max_keyframes) + " with the " +
                         std::to_string(t.keyframes.size()) + " " +
                         std::string(effects::effect_name(type)) +
                         " keyframes already there is over the limit of " +
                         std::to_string(io::kMaxKeyframesPerEffect) + " per effect");
      return t;
    }
  sidecar.effects.push_back({type, std::nullopt, {}});
  return sidecar.effects.back();
}

/// The frames [first, last] around `frame` over which the active points of interest stay the
/// same (so the guidance field does not change).
std::pair<std::int64_t, std::int64_t> guide_segment(const std::vector<PointOfInterest>& points,
                                                    std::int64_t frame, std::int64_t frames) {
  std::int64_t first = 0, last = std::max<std::int64_t>(0, frames - 1);
  for (const auto& p : points) {
    for (const std::int64_t b : {p.first_frame, p.last_frame ? *p.last_frame + 1 : frames}) {
      if (b <= frame)
        first = std::max(first, b);
      else
        last = std::min(last, b - 1);
    }
  }
  return {first, last};
}

/// The stamp of a field that does not vary with direction: the sample's value at the six axis
/// directions at its frame (equal values at directions spread over the sphere interpolate to
/// that value everywhere: the RBF's constant term carries it); inside a VR180 image, its centre
/// and four directions 60 degrees from it.
Stamp frame_stamp(const TargetField& field, std::size_t s, int coverage_deg) {
  Stamp st;
  const auto first = field.values.begin() + static_cast<std::ptrdiff_t>(s * field.dimension);
  const std::vector<double> v(first, first + field.dimension);
  const std::vector<effects::Direction> sphere = {{0, 0},   {90, 0}, {180, 0},
                                                  {-90, 0}, {0, 90}, {0, -90}},
                                        half = {{0, 0}, {60, 0}, {-60, 0}, {0, 60}, {0, -60}};
  for (const effects::Direction d : coverage_deg == 360 ? sphere : half)
    st.keyframes.push_back({d, field.frames[s], v});
  st.key = "frame " + std::to_string(field.frames[s]);
  return st;
}

/// The stamp of the guidance field: the sample's keyframe at every sampled frame of its segment
/// (the field is the same over it).
Stamp segment_stamp(const TargetField& field, std::size_t s,
                    const std::vector<PointOfInterest>& points, std::int64_t frames,
                    const std::vector<std::int64_t>& sampled) {
  const Stamp one = single_keyframe(field, s);
  const auto [first, last] = guide_segment(points, field.frames[s], frames);
  Stamp st;
  for (const std::int64_t f : sampled)
    if (f >= first && f <= last)
      st.keyframes.push_back({one.keyframes[0].direction, f, one.keyframes[0].params});
  st.key = std::to_string(one.keyframes[0].direction.azimuth_deg) + "," +
           std::to_string(one.keyframes[0].direction.altitude_deg) + "@" + std::to_string(first);
  return st;
}

/// A suggestion that changes in time gets its own time scale on a new track: one sampled-frame
/// step weighs like kStepDeg degrees of view (docs/suggest.md, "Time"). Under the author's default
/// (2 degrees a second) frames a fraction of a second apart are nearly the same point, and two
/// patterns on either side of a change blend across the sphere; at half a turn per step each
/// sampled frame's keyframes shape their own frame.
constexpr double kStepDeg = 180.0;

void fit_into(io::Sidecar& sidecar, EffectType type, const TargetField& field,
              const SuggestRequest& r, const Clip& clip, SuggestReport& report, StampFn stamp = {},
              std::int64_t step_frames = 0) {
  effects::EffectTrack& track = track_of(sidecar, type, r.merge, r);
  if (step_frames > 0 && track.keyframes.empty() && !track.interpolation) {
    effects::InterpolationSettings own = sidecar.interpolation;
    own.time_scale = effects::time_scale_from_deg_per_s(kStepDeg * sidecar.video.fps /
                                                        static_cast<double>(step_frames));
    track.interpolation = own;
  }
  FitOptions o;
  o.tolerance = r.tolerance.value_or(type == EffectType::Saturation ? kSaturationTolerance
                                     : type == EffectType::Vignette ? kVignetteToleranceDeg
                                                                    : kExposureToleranceStops);
  o.max_keyframes = r.max_keyframes;
  o.settings = track.interpolation.value_or(sidecar.interpolation);
  o.fps = sidecar.video.fps;
  o.neutral = effects::effect_spec(type).neutral();
  o.stamp = std::move(stamp);
  o.on_step = [&](std::size_t added) {
    clip.tick(0.5 + 0.5 * static_cast<double>(added) / static_cast<double>(o.max_keyframes));
  };
  SuggestedEffect s{type, o.tolerance, fit_greedy(field, o, track.keyframes)};
  track.keyframes.insert(track.keyframes.end(), s.fit.added.begin(), s.fit.added.end());
  report.effects.push_back(std::move(s));
}

/// The field's directions (of the video frame at each sample's frame) turned into the frame the
/// sidecar's `type` effect stores its keyframes in (its anchor: docs/anchors.md), so that the fit
/// measures and places keyframes where that effect's interpolant is evaluated. A new effect, or
/// one fixed in the video, keeps the field as it is.
TargetField in_anchor_frame(TargetField field, const io::Sidecar& sidecar, EffectType type) {
  for (const effects::EffectTrack& t : sidecar.effects) {
    if (t.type != type || t.anchor.is_video()) continue;
    effects::AnchorFrames anchor;
    try {
      anchor = effects::anchor_frames(t.anchor, sidecar.camera ? &*sidecar.camera : nullptr,
                                      sidecar.tracks);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(std::string("sidecar: ") + e.what());
    }
    for (std::size_t i = 0; i < field.size(); ++i)
      field.directions[i] = anchor.apply(field.directions[i], field.frames[i]);
  }
  return field;
}

/// One suggestion on `sidecar` (changed in place) from an opened clip.
SuggestReport suggest_clip(const SuggestRequest& r, Clip& clip, io::Sidecar& sidecar) {
  SuggestReport report;
  report.frames = clip.frames;
  if (r.kind == Kind::Exposure) {
    const TargetField field =
        in_anchor_frame(exposure_field(r, clip, report), sidecar, EffectType::Exposure);
    report.samples = field.size();
    fit_into(sidecar, EffectType::Exposure, field, r, clip, report);
  } else if (r.kind == Kind::Comfort) {
    const TargetField field =
        in_anchor_frame(comfort_field(r, clip, report), sidecar, EffectType::Vignette);
    report.samples = field.size();
    fit_into(
        sidecar, EffectType::Vignette, field, r, clip, report,
        [&field, &clip](std::size_t s) { return frame_stamp(field, s, clip.layout.coverage_deg); },
        clip.every);
  } else {
    std::vector<EffectType> types;
    if (r.guide_effect != GuideEffect::Exposure) types.push_back(EffectType::Saturation);
    if (r.guide_effect != GuideEffect::Saturation) types.push_back(EffectType::Exposure);
    for (const EffectType type : types) {
      const TargetField field = in_anchor_frame(guide_field(r, clip, type), sidecar, type);
      report.samples = field.size();
      const std::int64_t frames = sidecar.video.frames;
      const bool moves = clip.frames.size() > 1 &&
                         std::any_of(r.points.begin(), r.points.end(), [](const auto& p) {
                           return p.first_frame > 0 || p.last_frame.has_value();
                         });
      fit_into(
          sidecar, type, field, r, clip, report,
          [&](std::size_t s) { return segment_stamp(field, s, r.points, frames, clip.frames); },
          moves ? clip.every : 0);
    }
  }
  clip.tick(1.0);
  return report;
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

SuggestReport suggest_into(const SuggestRequest& request, io::Sidecar& sidecar,
                           Progress* progress) {
  const auto start = Clock::now();
  SuggestRequest r = request;
  r.merge = true;
  check_request(r);
  // The caller's sidecar is changed only once the whole suggestion is in.
  std::optional<io::Sidecar> work = sidecar;
  Clip clip = open_clip(r, progress, work);
  SuggestReport report = suggest_clip(r, clip, *work);
  sidecar = std::move(*work);
  report.seconds = seconds_since(start);
  return report;
}

SuggestReport run_suggest(const SuggestRequest& request) {
  const auto start = Clock::now();
  check_request(request);
  const io::SidecarTarget target =
      io::resolve_sidecar_target({request.sidecar_in, request.sidecar_out, request.force},
                                 {{"VIDEO", request.video}}, "vdfx suggest");
  SuggestRequest r = request;
  r.sidecar_in = target.base;  // an existing --sidecar-out is what the suggestion adds to
  std::optional<io::Sidecar> sidecar;
  if (target.base) sidecar = io::read_sidecar_base(target, {});
  Clip clip = open_clip(r, nullptr, sidecar);
  const io::Sidecar before = *sidecar;
  SuggestReport report = suggest_clip(r, clip, *sidecar);
  io::write_sidecar(r.sidecar_out, *sidecar);
  report.sidecar_note = io::sidecar_target_note(target, r.sidecar_out, before);
  report.seconds = seconds_since(start);
  return report;
}

}  // namespace vdfx::app::suggest
