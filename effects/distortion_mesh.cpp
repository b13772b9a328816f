/// @file
/// @brief Distortion mesh build, barycentric sampling and error measurement.
#include "effects/distortion_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {

DistortionMesh build_distortion_mesh(const EyeLens& eye, int n, bool lca_correction) {
  if (n < 2) throw std::invalid_argument("distortion mesh needs n >= 2 vertices per side");
  DistortionMesh mesh;
  mesh.n = n;
  mesh.width = eye.width;
  mesh.height = eye.height;
  mesh.lca_correction = lca_correction;
  mesh.vertices.reserve(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d px(static_cast<double>(i) / (n - 1) * eye.width,
                               static_cast<double>(j) / (n - 1) * eye.height);
      const ChannelSamples s = panel_source_uv(eye, px, lca_correction, InverseMethod::Newton);
      mesh.vertices.push_back({px, s.uv, s.valid});
    }
  }
  mesh.indices.reserve(static_cast<size_t>(n - 1) * (n - 1) * 6);
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const auto tl = static_cast<std::uint32_t>(j * n + i);
      const auto tr = tl + 1, bl = tl + static_cast<std::uint32_t>(n), br = bl + 1;
      for (const std::uint32_t v : {tl, bl, br, tl, br, tr}) mesh.indices.push_back(v);
    }
  }
  return mesh;
}

ChannelSamples sample_mesh(const DistortionMesh& mesh, const Eigen::Vector2d& px) {
  const double cells = mesh.n - 1;
  const double gx = std::clamp(px.x() / mesh.width * cells, 0.0, cells);
  const double gy = std::clamp(px.y() / mesh.height * cells, 0.0, cells);
  const int i = std::min(static_cast<int>(gx), mesh.n - 2);
  const int j = std::min(static_cast<int>(gy), mesh.n - 2);
  const double fx = gx - i, fy = gy - j;
  // Lower-left triangle (TL, BL, BR) when fy >= fx, else upper-right (TL, BR, TR).
  const MeshVertex& tl = mesh.at(i, j);
  const MeshVertex& br = mesh.at(i + 1, j + 1);
  const MeshVertex& third = fy >= fx ? mesh.at(i, j + 1) : mesh.at(i + 1, j);
  // Barycentric weights: TL at (0,0), BR at (1,1), BL at (0,1), TR at (1,0).
  const double w_br = std::min(fx, fy);
  const double w_third = std::abs(fy - fx);
  const double w_tl = 1.0 - w_br - w_third;
  ChannelSamples out;
  for (int c = 0; c < 3; ++c) {
    out.valid[c] = tl.valid[c] && br.valid[c] && third.valid[c];
    out.uv[c] = w_tl * tl.uv[c] + w_br * br.uv[c] + w_third * third.uv[c];
  }
  return out;
}

MeshError measure_mesh_error(const EyeLens& eye, const DistortionMesh& mesh, int stride) {
  if (stride < 1) throw std::invalid_argument("measure_mesh_error: stride must be >= 1");
  MeshError err;
  double sum_sq = 0.0;
  const Eigen::Vector2d to_px(eye.width, eye.height);
  for (int y = 0; y < eye.height; y += stride) {
    for (int x = 0; x < eye.width; x += stride) {
      const Eigen::Vector2d px(x + 0.5, y + 0.5);
      const ChannelSamples exact =
          panel_source_uv(eye, px, mesh.lca_correction, InverseMethod::Newton);
      const ChannelSamples approx = sample_mesh(mesh, px);
      for (int c = 0; c < 3; ++c) {
        if (!exact.valid[c] || !approx.valid[c]) {
          ++err.skipped;
          continue;
        }
        const double e = (exact.uv[c] - approx.uv[c]).cwiseProduct(to_px).norm();
        sum_sq += e * e;
        err.max_px = std::max(err.max_px, e);
        ++err.samples;
      }
    }
  }
  err.rms_px = err.samples > 0 ? std::sqrt(sum_sq / static_cast<double>(err.samples)) : 0.0;
  return err;
}

}  // namespace vdfx::effects
