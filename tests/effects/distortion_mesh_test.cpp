/// @file
/// @brief Distortion mesh: exact at vertices, linear maps reproduced, error falls with N.
#include "effects/distortion_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "effects/coords.h"

namespace vdfx::effects {
namespace {

/// The generic90 profile's left eye (xr/headset/profiles/generic90.json): 1440 x 1600, FOV
/// -52/+47/+53/-53 degrees, c = (0.22, 0.24), R = 1.8, DK2 LCA.
EyeLens generic90_left() {
  EyeLens eye;
  eye.width = 1440;
  eye.height = 1600;
  const auto t = [](double deg) { return std::tan(deg * kPi / 180.0); };
  eye.fov = {t(-52), t(47), t(53), t(-53)};
  eye.lens = LensModel({0.22, 0.24, 1.8, {0.985, 1.0, 1.015}});
  return eye;
}

TEST(DistortionMesh, GridTopologyAndExactVertices) {
  const EyeLens eye = generic90_left();
  const DistortionMesh mesh = build_distortion_mesh(eye, 9);
  ASSERT_EQ(mesh.vertices.size(), 81u);
  ASSERT_EQ(mesh.indices.size(), 8u * 8u * 6u);
  EXPECT_EQ(mesh.at(8, 8).panel_px, Eigen::Vector2d(1440, 1600));
  for (const std::uint32_t i : mesh.indices) EXPECT_LT(i, 81u);
  // At a vertex the mesh returns exactly the exact mapping.
  for (const auto& [i, j] : {std::pair{0, 0}, {3, 5}, {8, 8}, {8, 0}}) {
    const Eigen::Vector2d px = mesh.at(i, j).panel_px;
    const ChannelSamples exact = panel_source_uv(eye, px, true);
    const ChannelSamples interp = sample_mesh(mesh, px);
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(interp.valid[c]);
      EXPECT_LT((exact.uv[c] - interp.uv[c]).norm(), 1e-12) << i << "," << j << " ch " << c;
    }
  }
}

TEST(DistortionMesh, WithoutDistortionEvenTheCoarsestMeshIsExact) {
  EyeLens eye = generic90_left();
  eye.lens = LensModel({0.0, 0.0, 1.8, {1, 1, 1}});  // the map is linear: the mesh is exact
  const MeshError err = measure_mesh_error(eye, build_distortion_mesh(eye, 5), 7);
  EXPECT_GT(err.samples, 0);
  EXPECT_LT(err.max_px, 1e-9);
}

TEST(DistortionMesh, ErrorFallsAsTheGridGrows) {
  const EyeLens eye = generic90_left();
  double prev_rms = 1e300, prev_max = 1e300;
  for (const int n : kMeshSizes) {
    // Every 3rd pixel in x and y keeps the test quick; the benchmark measures every pixel.
    const MeshError err = measure_mesh_error(eye, build_distortion_mesh(eye, n), 3);
    std::printf("mesh %2dx%-2d  rms %.4f px  max %.4f px  (%lld samples)\n", n, n, err.rms_px,
                err.max_px, static_cast<long long>(err.samples));
    EXPECT_EQ(err.skipped, 0) << n;
    EXPECT_GT(err.rms_px, 0.0) << n;
    EXPECT_LT(err.rms_px, prev_rms) << n;
    EXPECT_LT(err.max_px, prev_max) << n;
    prev_rms = err.rms_px;
    prev_max = err.max_px;
  }
  // Linear interpolation: the error of a smooth map falls ~4x per halving of the cell size.
  EXPECT_LT(prev_max, 0.1);
}

TEST(DistortionMesh, VerticesBeyondTheMonotonicLimitAreInvalid) {
  EyeLens eye = generic90_left();
  eye.lens = LensModel({-0.6, 0.1, 1.0, {1, 1, 1}});  // folds at r_u ~ 0.9, r_d ~ 0.59
  const DistortionMesh mesh = build_distortion_mesh(eye, 17);
  int invalid = 0;
  for (const MeshVertex& v : mesh.vertices) {
    const double r_d = eye.pixel_to_tan(v.panel_px).norm();
    EXPECT_EQ(v.valid[1], r_d < eye.lens.max_distorted_radius()) << v.panel_px.transpose();
    invalid += !v.valid[1];
  }
  EXPECT_GT(invalid, 0);
  EXPECT_FALSE(sample_mesh(mesh, {0.5, 0.5}).valid[1]);  // the top-left corner is beyond
  EXPECT_TRUE(sample_mesh(mesh, eye.centre_pixel()).valid[1]);
}

}  // namespace
}  // namespace vdfx::effects
