/// @file
/// @brief sample_grain_particles: a whole refresh's particles on the CPU, split between threads
/// with OpenCV's parallel_for_ (grain_particles.cpp, the particle itself, builds without OpenCV
/// for the web player's module).
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

#include "effects/grain_particles.h"

namespace vdfx::effects {

ParticleSet sample_grain_particles(GrainStyle style, const GrainSettings& s, std::uint64_t seed,
                                   std::int64_t refresh, double size) {
  if (!is_volumetric(style))
    throw std::invalid_argument("sample_grain_particles: " + std::string(grain_style_name(style)) +
                                " is a shader style");
  ParticleSet out;
  out.refresh = refresh;
  const auto count = static_cast<std::size_t>(s.get(GrainSetting::Count));
  out.particles.resize(count);
  // Counter-based: particle i is a function of (key, i), so the set is the same however the work
  // is split between threads, and the GPU generates it the same way.
  const std::uint32_t key = grain_particle_key(seed, refresh);
  cv::parallel_for_(cv::Range(0, static_cast<int>(count)), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i)
      out.particles[static_cast<std::size_t>(i)] =
          grain_particle(style, s, key, static_cast<std::uint32_t>(i), size);
  });
  for (const GrainParticle& p : out.particles) ++out.region_count[p.region];
  return out;
}

}  // namespace vdfx::effects
