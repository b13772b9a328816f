/// @file
/// @brief Anchors (effects/anchor.h): names, and the rotation each applies per frame, against the
/// contract's definitions computed independently (quaternion sandwich; the track's direction at a
/// frame taken to its first one).
#include "effects/anchor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace vdfx::effects {
namespace {

constexpr double kPi = 3.14159265358979323846;

Quat about(const Eigen::Vector3d& axis, double deg) {
  return from_eigen(Eigen::Quaterniond(Eigen::AngleAxisd(deg * kPi / 180.0, axis.normalized())));
}

TEST(Anchor, NamesRoundTripAndBadOnesAreRefused) {
  for (const char* text : {"video", "world", "track:actor", "track:A_b-9"}) {
    const auto a = parse_anchor(text);
    ASSERT_TRUE(a.has_value()) << text;
    EXPECT_EQ(anchor_name(*a), text);
  }
  for (const char* text : {"", "World", "track:", "track:a b", "track:a/b", "tracks:a"})
    EXPECT_FALSE(parse_anchor(text).has_value()) << text;
  EXPECT_TRUE(valid_track_name(std::string(64, 'x')));
  EXPECT_FALSE(valid_track_name(std::string(65, 'x')));
}

TEST(Anchor, VideoIsTheIdentityAndCostsNoRotation) {
  const AnchorFrames f;
  EXPECT_TRUE(f.identity());
  const Eigen::Vector3d n = to_unit({30.0, 10.0});
  EXPECT_EQ(f.apply(n, 17), n);
}

TEST(Anchor, WorldIsTheQuaternionSandwichAtEachFrame) {
  CameraMotion cam;
  for (int f = 0; f < 5; ++f) cam.orientation.push_back(about({0.3, 1.0, -0.2}, 7.0 * f));
  const AnchorFrames world = AnchorFrames::world(cam);
  const Eigen::Vector3d n = to_unit({-40.0, 25.0});
  for (int f = 0; f < 5; ++f) {
    const Eigen::Quaterniond q = to_eigen(cam.orientation[static_cast<std::size_t>(f)]);
    const Eigen::Quaterniond v(0.0, n.x(), n.y(), n.z());
    const Eigen::Vector3d expected = (q * v * q.conjugate()).vec();
    EXPECT_LT((world.apply(n, f) - expected).norm(), 1e-14) << f;
    EXPECT_LT((world.unapply(world.apply(n, f), f) - n).norm(), 1e-14) << f;
  }
  // Outside the stored frames: the nearest end's.
  EXPECT_LT((world.at(-3) - world.at(0)).norm(), 1e-15);
  EXPECT_LT((world.at(99) - world.at(4)).norm(), 1e-15);
}

TEST(Anchor, TrackTakesTheSubjectToWhereItStoodAtItsFirstFrame) {
  SubjectTrack t{"actor", {}};
  // Across the seam and up towards the pole.
  const Direction dirs[] = {{170.0, 0.0}, {178.0, 20.0}, {-175.0, 45.0}, {-160.0, 80.0}};
  for (int i = 0; i < 4; ++i) t.points.push_back({10 + i, dirs[i], 1.0});
  const AnchorFrames track = AnchorFrames::track(t);
  const Eigen::Vector3d first = to_unit(dirs[0]);
  for (int i = 0; i < 4; ++i) {
    const std::int64_t frame = 10 + i;
    EXPECT_LT((track.apply(to_unit(dirs[i]), frame) - first).norm(), 1e-12) << i;
    // A rotation: lengths and angles kept.
    const Eigen::Matrix3d r = track.at(frame);
    EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  }
  // Before the span the identity (the first point's), after it the last point's.
  EXPECT_LT((track.at(0) - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_LT((track.at(500) - track.at(13)).norm(), 1e-15);
}

TEST(Anchor, FramesComeFromTheSidecarsCameraAndTracks) {
  CameraMotion cam{CameraMotion::Source::Given, {about({0, 1, 0}, 0), about({0, 1, 0}, 90)}};
  const SubjectTrack tracks[] = {{"a", {{0, {0.0, 0.0}, 1.0}, {1, {90.0, 0.0}, 1.0}}}};
  const Eigen::Vector3d ahead = to_unit({0.0, 0.0});
  EXPECT_TRUE(anchor_frames({}, &cam, tracks).identity());
  const AnchorFrames world = anchor_frames({Anchor::Kind::World, {}}, &cam, tracks);
  // A quarter turn about +y takes ahead (0, 0, -1) to (-1, 0, 0): azimuth -90.
  EXPECT_LT((world.apply(ahead, 1) - to_unit({-90.0, 0.0})).norm(), 1e-12);
  const AnchorFrames track = anchor_frames({Anchor::Kind::Track, "a"}, &cam, tracks);
  EXPECT_LT((track.apply(to_unit({90.0, 0.0}), 1) - ahead).norm(), 1e-12);
  EXPECT_THROW(anchor_frames({Anchor::Kind::World, {}}, nullptr, tracks), std::invalid_argument);
  EXPECT_THROW(anchor_frames({Anchor::Kind::Track, "b"}, &cam, tracks), std::invalid_argument);
}

}  // namespace
}  // namespace vdfx::effects
