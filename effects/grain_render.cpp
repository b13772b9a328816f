/// @file
/// @brief The shader grain styles on the CPU, operation for operation as the GLSL.
#include "effects/grain_render.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

void composite_shader_grain(cv::Mat& image, const GrainFrame& f, const Eigen::Matrix3d& eye_rot,
                            const Eigen::Vector3d& eye_pos, const TanRect& fov) {
  if (is_volumetric(f.style) || !f.noise)
    throw std::invalid_argument(
        "composite_shader_grain: " + std::string(grain_style_name(f.style)) +
        " has no CPU reference (volumetric grain renders on the GPU)");
  if (image.type() != CV_32FC3)
    throw std::invalid_argument("composite_shader_grain: CV_32FC3 expected");
  const ShaderGrainUniforms u = shader_grain_uniforms(f, eye_rot, eye_pos, fov);
  const int w = image.cols, h = image.rows;
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      auto* row = image.ptr<cv::Vec3f>(j);
      // GL's fragment y grows upwards from the bottom edge; image row 0 is the top.
      const float fy = static_cast<float>(h - j) - 0.5f;
      for (int i = 0; i < w; ++i) {
        const std::optional<float> s =
            shader_grain_fragment(u, *f.noise, static_cast<float>(i) + 0.5f, fy, w, h);
        if (!s) continue;
        // The blend's operations: src0 + dst * src1.
        const float add = *s * u.floor, scale = 1.0f + *s;
        for (int c = 0; c < 3; ++c) row[i][c] = add + row[i][c] * scale;
      }
    }
  });
}

}  // namespace vdfx::effects
