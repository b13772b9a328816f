/// @file
/// @brief The grain layers of one frame, laid out once from the head (cyclopean) pose
/// (flare-grain.md, stereo rules 1 and 2): every grain has one position in LOCAL space and each
/// eye renders it from its own pose, so disparity comes from geometry alone.
///
/// GrainSet holds a sidecar's grain effects with their interpolators; layout() is called once per
/// displayed frame and gives, for each effect whose interpolated intensity is above 0, what both
/// eyes need: the anchor (head position; the head's orientation for the headset plane), the
/// noise lattice and its phase for this refresh (shader styles) or the key of this refresh's
/// particles with the effect's settings (volumetric styles: the GPU generates the particles from
/// them, effects/grain_particles.h; no CPU sampling). An effect at intensity 0 yields no layer:
/// nothing is drawn.
///
/// Anchors (effects/anchor.h): an effect's intensity and size keyframes are interpolated at the
/// head's forward direction turned into the effect's anchor's frame. The grain itself (its
/// lattice, its particles) stays where its style puts it, about the head: an anchor says where
/// the keyframes are, not where the grains are.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "effects/anchor_sources.h"
#include "effects/grain.h"
#include "effects/grain_interpolator.h"
#include "effects/grain_particles.h"
#include "effects/head_pose.h"
#include "effects/perlin_noise.h"

namespace vdfx::effects {

/// Angle of one noise lattice cell at the style's distance, at size 1 (radians): 4 mrad, about
/// 2.4 px of a 1440-px, 100-degree eye, so a grain is one to three pixels wide there.
inline constexpr double kGrainCellRad = 0.004;
/// Second octave: twice the frequency, this weight (finer grains inside the coarse ones).
inline constexpr double kGrainOctave2Weight = 0.5;
/// Shader grain: the noise g becomes the modulation s = max(-1, intensity * kGrainGain * g) and
/// the eye colour C becomes C + s (C + kGrainFloor) (effects/grain_render.h).
inline constexpr double kGrainGain = 0.5;
inline constexpr double kGrainFloor = 0.1;

/// One grain layer of one frame (both eyes render it).
struct GrainFrame {
  std::size_t effect = 0;  //!< index of the effect in the GrainSet (file order of the grains)
  GrainStyle style = GrainStyle::Surface;
  GrainParams params;        //!< at the head's forward direction and the video frame
  std::int64_t refresh = 0;  //!< grain_refresh_index of the display time
  HeadPose head;             //!< anchor: volumes and sphere centred on head.position
  // Shader styles.
  double distance_m = 0.0;  //!< plane_m (headset) or sphere_m (surface)
  double cell_m = 0.0;      //!< lattice spacing of octave 1: kGrainCellRad * distance * size
  std::array<Eigen::Vector3d, 2> noise_offset{};  //!< per octave, lattice units, this refresh
  std::shared_ptr<const PerlinNoise> noise;       //!< the effect's permutation (from its seed)
  // Volumetric styles: particle i is grain_particle(style, settings, particle_key, i), i below
  // the settings' count.
  std::uint32_t particle_key = 0;  //!< grain_particle_key(seed, refresh)
  GrainSettings settings;          //!< the effect's (count, volumes)
};

class GrainSet {
 public:
  GrainSet() = default;
  /// Throws std::invalid_argument when an effect's keyframes cannot be interpolated or its
  /// anchor names what `anchors` lack.
  GrainSet(std::vector<GrainEffect> effects, const InterpolationSettings& defaults, double fps,
           const AnchorSources& anchors = {});

  bool empty() const { return effects_.empty(); }
  std::size_t size() const { return effects_.size(); }
  const GrainEffect& effect(std::size_t i) const { return effects_.at(i).effect; }
  /// Effect i's parameters at a direction (unit, of the video frame) and frame.
  GrainParams params(std::size_t i, const Eigen::Vector3d& unit, std::int64_t frame) const;
  const AnchorFrames& anchor(std::size_t i) const { return effects_.at(i).anchor; }
  /// Effect i's intensity and size from another solution of its keyframes (an editor's pending
  /// edit; keyframes in the effect's anchor's frame).
  void set_interpolant(std::size_t i, std::shared_ptr<const RbfInterpolator> rbf);

  /// The visible layers at a display time (file order). Parameters are interpolated at the
  /// head's forward direction; the refresh index comes from the display time alone.
  std::vector<GrainFrame> layout(const HeadPose& head, std::int64_t display_time_ns,
                                 std::int64_t video_frame);

 private:
  struct Entry {
    GrainEffect effect;
    GrainInterpolator interp;
    std::shared_ptr<const PerlinNoise> noise;
    AnchorFrames anchor;
  };
  std::vector<Entry> effects_;
};

/// The noise offsets of one refresh (lattice units in [0, 256), one per octave).
std::array<Eigen::Vector3d, 2> grain_noise_offsets(std::uint64_t seed, std::int64_t refresh);

/// The display time vdfx render and exports give a frame without a clock: the frame's start,
/// frame * 1e9 / fps nanoseconds, rounded.
std::int64_t frame_display_time_ns(std::int64_t frame, double fps);

}  // namespace vdfx::effects
