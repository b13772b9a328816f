/// @file
/// @brief The mesh-based lens pre-distortion: an N x N vertex grid over one eye's panel viewport,
/// each vertex carrying the exact per-channel source UVs, interpolated linearly inside cells; and
/// the measurement of its error against the exact per-pixel mapping.
///
/// Each cell is drawn as two triangles split along the diagonal from its top-left to its
/// bottom-right vertex, so interpolation is barycentric (what a GPU does with the same index
/// buffer), not bilinear.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "effects/lens_model.h"

namespace vdfx::effects {

struct MeshVertex {
  Eigen::Vector2d panel_px;           //!< position on the eye's panel viewport, pixels
  std::array<Eigen::Vector2d, 3> uv;  //!< source UV per channel (R, G, B)
  std::array<bool, 3> valid;          //!< false beyond the lens's monotonic limit
};

struct DistortionMesh {
  int n = 0;                           //!< vertices per side
  int width = 0, height = 0;           //!< the eye's panel viewport, pixels
  bool lca_correction = true;          //!< whether channels carry the inverse LCA scale
  std::vector<MeshVertex> vertices;    //!< row-major, row 0 at the top: index j * n + i
  std::vector<std::uint32_t> indices;  //!< triangle list, 6 per cell, diagonal TL-BR

  const MeshVertex& at(int i, int j) const { return vertices[static_cast<size_t>(j) * n + i]; }
};

/// Vertex counts per side the project measures (numerics.md); Monado uses 65, Cardboard 40.
inline constexpr std::array<int, 5> kMeshSizes{5, 9, 17, 33, 65};
inline constexpr int kDefaultMeshSize = 65;

/// Builds the mesh for one eye; vertices span the viewport's outer edges (0 .. width, 0 .. height).
/// Throws std::invalid_argument for n < 2.
DistortionMesh build_distortion_mesh(const EyeLens& eye, int n = kDefaultMeshSize,
                                     bool lca_correction = true);

/// Mesh-interpolated source UVs at panel position px (continuous pixels); a channel is invalid
/// when any vertex of the triangle containing px is invalid for it.
ChannelSamples sample_mesh(const DistortionMesh& mesh, const Eigen::Vector2d& px);

struct MeshError {
  double rms_px = 0.0;       //!< RMS over pixels and channels, in eye-image pixels
  double max_px = 0.0;       //!< largest single-channel error, in eye-image pixels
  std::int64_t samples = 0;  //!< channel samples compared
  std::int64_t skipped = 0;  //!< channel samples invalid in the exact map or in the mesh
};

/// Compares the mesh against the exact (Newton) mapping at the centre of every `stride`-th pixel
/// in x and y of the eye's panel viewport (stride 1: every pixel). Errors are source positions in
/// pixels of the undistorted eye image (which has the panel's resolution).
MeshError measure_mesh_error(const EyeLens& eye, const DistortionMesh& mesh, int stride = 1);

}  // namespace vdfx::effects
