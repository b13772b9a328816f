/// @file
/// @brief The shader grain styles' uniforms and fragment, operation for operation as the GLSL.
#include "effects/grain_uniforms.h"

#include <algorithm>
#include <cmath>

namespace vdfx::effects {

ShaderGrainUniforms shader_grain_uniforms(const GrainFrame& f, const Eigen::Matrix3d& eye_rot,
                                          const Eigen::Vector3d& eye_pos, const TanRect& fov) {
  ShaderGrainUniforms u;
  u.style = f.style == GrainStyle::Headset ? 0 : 1;
  // The grain frame: the head's axes for the head-anchored plane, LOCAL's for the sphere; its
  // origin is the head position either way.
  const Eigen::Matrix3d to_grain = f.style == GrainStyle::Headset
                                       ? Eigen::Matrix3d(f.head.orientation.transpose())
                                       : Eigen::Matrix3d::Identity().eval();
  u.eye_to_grain = (to_grain * eye_rot).cast<float>();
  u.eye = (to_grain * (eye_pos - f.head.position)).cast<float>();
  u.distance = static_cast<float>(f.distance_m);
  u.inv_cell = static_cast<float>(1.0 / f.cell_m);
  u.offset1 = f.noise_offset[0].cast<float>();
  u.offset2 = f.noise_offset[1].cast<float>();
  u.gain = static_cast<float>(f.params.intensity * kGrainGain);
  u.tangents = {static_cast<float>(fov.left), static_cast<float>(fov.right),
                static_cast<float>(fov.down), static_cast<float>(fov.up)};
  if (f.noise)
    for (std::size_t i = 0; i < 256; ++i) u.perm[i] = f.noise->permutation()[i];
  return u;
}

std::optional<float> shader_grain_fragment(const ShaderGrainUniforms& u, const PerlinNoise& noise,
                                           float frag_x, float frag_y, int width, int height) {
  const auto& t = u.tangents;
  const float tx = t[0] + (frag_x / static_cast<float>(width)) * (t[1] - t[0]);
  const float ty = t[2] + (frag_y / static_cast<float>(height)) * (t[3] - t[2]);
  const Eigen::Matrix3f& m = u.eye_to_grain;
  Eigen::Vector3f d = m.col(0) * tx + m.col(1) * ty - m.col(2);
  d = d * (1.0f / std::sqrt(d.dot(d)));
  const Eigen::Vector3f& e = u.eye;
  // The pixel's angular size (tangent step over the ray's length, the larger of its two axes).
  const float pixel_rad =
      (t[1] - t[0]) / static_cast<float>(width) / std::sqrt(1.0f + tx * tx + ty * ty);
  Eigen::Vector3f lattice;
  float cells_per_pixel;
  if (u.style == 0) {
    if (!(d.z() < 0.0f)) return std::nullopt;  // the plane is not ahead
    const float s = (-u.distance - e.z()) / d.z();
    const Eigen::Vector3f q = e + d * s;
    lattice = Eigen::Vector3f(q.x() * u.inv_cell, q.y() * u.inv_cell, 0.0f);
    cells_per_pixel = s * pixel_rad / -d.z() * u.inv_cell;  // oblique on the plane off axis
  } else {
    const float b = d.dot(e), c = e.dot(e) - u.distance * u.distance;
    const float disc = b * b - c;
    if (!(disc >= 0.0f)) return std::nullopt;  // the eye is outside and misses it
    const float s = -b + std::sqrt(disc);
    lattice = (e + d * s) * u.inv_cell;
    cells_per_pixel = s * pixel_rad * u.inv_cell;
  }
  // Band limit: an octave fades out between 0.5 and 1 lattice cells per pixel, where a pixel
  // could only sample it as aliased moire, not as grain.
  const float w1 = std::clamp(2.0f - 2.0f * cells_per_pixel, 0.0f, 1.0f);
  const float w2 = std::clamp(2.0f - 4.0f * cells_per_pixel, 0.0f, 1.0f);
  const Eigen::Vector3f p1 = lattice + u.offset1;
  const Eigen::Vector3f p2 = lattice * 2.0f + u.offset2;
  // An octave at weight 0 is not evaluated (coarse eyes pay nothing for grain they cannot show).
  const float n1 = w1 > 0.0f ? noise(p1.x(), p1.y(), p1.z()) : 0.0f;
  const float n2 = w2 > 0.0f ? noise(p2.x(), p2.y(), p2.z()) : 0.0f;
  const float g = w1 * n1 + u.octave2 * w2 * n2;
  return std::max(-1.0f, u.gain * g);
}

}  // namespace vdfx::effects
