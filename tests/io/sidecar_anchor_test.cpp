/// @file
/// @brief The sidecar's frames of reference: `camera`, `tracks` and each entry's `anchor` read as
/// the contract writes them, every broken field reported with its pointer and reason, exact
/// round trips, and files without them written byte for byte as before.
#include "io/sidecar_anchor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "tests/io/sidecar_cases.h"
#include "tests/test_files.h"

namespace vdfx::io {
namespace {

using nlohmann::json;

// Four frames; a camera turning about +y; a track over frames 1-3; one entry of each kind
// anchored.
const char* kValid = R"({
  "format": "vdfx.sidecar",
  "version": 1,
  "video": {"path": "clip.mp4", "fps": 30.0, "frames": 4, "width": 256, "height": 128},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure", "anchor": "world",
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": 1.0}}]},
    {"type": "saturation", "anchor": "track:actor-1",
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 1, "params": {"amount": 2.0}}]},
    {"type": "flare", "style": "directional", "anchor": "world",
     "light": {"azimuth_deg": 40.0, "altitude_deg": 12.0},
     "keyframes": [{"azimuth_deg": 40.0, "altitude_deg": 10.0, "frame": 0, "params": {"intensity": 1.0}}]},
    {"type": "grain", "style": "headset", "seed": 7, "anchor": "video",
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"intensity": 0.5, "size": 1.0}}]}
  ],
  "camera": {"source": "estimated", "orientation": [[1, 0, 0, 0], [0.9998476951563913, 0, 0.01745240643728351, 0],
             [0.9993908270190958, 0, 0.03489949670250097, 0], [0.9986295347545738, 0, 0.05233595624294383, 0]]},
  "tracks": [{"name": "actor-1", "points": [
    {"frame": 1, "azimuth_deg": 10.0, "altitude_deg": 0.0, "confidence": 0.9},
    {"frame": 2, "azimuth_deg": 12.0, "altitude_deg": 1.0, "confidence": 0.0},
    {"frame": 3, "azimuth_deg": 14.0, "altitude_deg": 2.0, "confidence": 1.0}]}]
})";

TEST(SidecarAnchor, ReadsTheContractsFields) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const Sidecar& s = *r.sidecar;
  EXPECT_EQ(s.effects[0].anchor.kind, effects::Anchor::Kind::World);
  EXPECT_EQ(s.effects[1].anchor, (effects::Anchor{effects::Anchor::Kind::Track, "actor-1"}));
  EXPECT_EQ(s.flares[0].anchor.kind, effects::Anchor::Kind::World);
  EXPECT_TRUE(s.grains[0].anchor.is_video());
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_EQ(s.camera->source, effects::CameraMotion::Source::Estimated);
  ASSERT_EQ(s.camera->orientation.size(), 4u);
  EXPECT_DOUBLE_EQ(s.camera->orientation[2][2], 0.03489949670250097);
  ASSERT_EQ(s.tracks.size(), 1u);
  EXPECT_EQ(s.tracks[0].name, "actor-1");
  ASSERT_EQ(s.tracks[0].points.size(), 3u);
  EXPECT_EQ(s.tracks[0].points[1], (effects::TrackPoint{2, effects::Direction{12.0, 1.0}, 0.0}));
}

const test::BrokenCase kBroken[] = {
    {"anchor_unknown", [](json& j) { j["effects"][0]["anchor"] = "floor"; }, "/effects/0/anchor",
     "unknown anchor \"floor\""},
    {"anchor_not_string", [](json& j) { j["effects"][0]["anchor"] = 1; }, "/effects/0/anchor",
     "expected a string"},
    {"anchor_bad_track_name", [](json& j) { j["effects"][1]["anchor"] = "track:a b"; },
     "/effects/1/anchor", "unknown anchor \"track:a b\""},
    {"anchor_names_no_track", [](json& j) { j["effects"][1]["anchor"] = "track:nobody"; },
     "/effects/1/anchor", "names no track in /tracks"},
    {"world_without_camera", [](json& j) { j.erase("camera"); }, "/effects/0/anchor",
     "no camera section"},
    {"flare_world_without_camera", [](json& j) { j.erase("camera"); }, "/effects/2/anchor",
     "no camera section"},
    {"camera_not_object", [](json& j) { j["camera"] = json::array(); }, "/camera",
     "expected an object"},
    {"camera_unknown_field", [](json& j) { j["camera"]["fov"] = 1; }, "/camera/fov",
     "unknown field"},
    {"camera_source", [](json& j) { j["camera"]["source"] = "gyro"; }, "/camera/source",
     "unknown source \"gyro\""},
    {"camera_missing_orientation", [](json& j) { j["camera"].erase("orientation"); }, "/camera",
     "missing field \"orientation\""},
    {"camera_short", [](json& j) { j["camera"]["orientation"].erase(3); }, "/camera/orientation",
     "3 orientations for a video of 4 frames"},
    {"camera_long",
     [](json& j) {
       j["camera"]["orientation"].push_back({1, 0, 0, 0});
     },
     "/camera/orientation", "5 orientations for a video of 4 frames"},
    {"quaternion_not_unit",
     [](json& j) {
       j["camera"]["orientation"][1] = {1, 0, 0.5, 0};
     },
     "/camera/orientation/1", "not a unit quaternion (length 1.118"},
    {"quaternion_zero",
     [](json& j) {
       j["camera"]["orientation"][1] = {0, 0, 0, 0};
     },
     "/camera/orientation/1", "not a unit quaternion (length 0)"},
    {"quaternion_nan", [](json& j) { j["camera"]["orientation"][2][0] = std::nan(""); },
     "/camera/orientation/2/0", "not a finite number"},
    {"quaternion_three",
     [](json& j) {
       j["camera"]["orientation"][0] = {1, 0, 0};
     },
     "/camera/orientation/0", "an array of 3"},
    {"tracks_not_array", [](json& j) { j["tracks"] = json::object(); }, "/tracks",
     "expected an array"},
    {"track_unknown_field", [](json& j) { j["tracks"][0]["size_deg"] = 5; }, "/tracks/0/size_deg",
     "unknown field"},
    {"track_name_bad", [](json& j) { j["tracks"][0]["name"] = "a/b"; }, "/tracks/0/name",
     "is not 1 to 64 of"},
    {"track_name_long", [](json& j) { j["tracks"][0]["name"] = std::string(65, 'a'); },
     "/tracks/0/name", "is not 1 to 64 of"},
    {"track_name_twice", [](json& j) { j["tracks"].push_back(j["tracks"][0]); }, "/tracks/1/name",
     "a second track named \"actor-1\""},
    {"track_no_points", [](json& j) { j["tracks"][0]["points"] = json::array(); },
     "/tracks/0/points", "found an empty one"},
    {"track_gap", [](json& j) { j["tracks"][0]["points"][2]["frame"] = 4; },
     "/tracks/0/points/2/frame", "out of range [0, 4)"},
    {"track_not_contiguous", [](json& j) { j["tracks"][0]["points"][0]["frame"] = 0; },
     "/tracks/0/points/1/frame", "frame 2 after frame 0: a track has one point per frame"},
    {"track_backwards", [](json& j) { j["tracks"][0]["points"][2]["frame"] = 1; },
     "/tracks/0/points/2/frame", "frame 1 after frame 2"},
    {"track_confidence", [](json& j) { j["tracks"][0]["points"][0]["confidence"] = 1.5; },
     "/tracks/0/points/0/confidence", "out of range [0, 1]"},
    {"track_confidence_missing", [](json& j) { j["tracks"][0]["points"][0].erase("confidence"); },
     "/tracks/0/points/0", "missing field \"confidence\""},
    {"track_altitude", [](json& j) { j["tracks"][0]["points"][1]["altitude_deg"] = 91.0; },
     "/tracks/0/points/1/altitude_deg", "out of range [-90, 90]"},
    {"track_nan", [](json& j) { j["tracks"][0]["points"][1]["azimuth_deg"] = std::nan(""); },
     "/tracks/0/points/1/azimuth_deg", "not a finite number"},
};

class SidecarAnchorBroken : public ::testing::TestWithParam<test::BrokenCase> {};

TEST_P(SidecarAnchorBroken, ReportsPointerAndReason) {
  EXPECT_TRUE(test::reports_as_expected(kValid, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Cases, SidecarAnchorBroken, ::testing::ValuesIn(kBroken),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SidecarAnchor, AThousandBadOrientationsAreTenLinesAndACount) {
  json j = json::parse(kValid);
  j["video"]["frames"] = 1000;
  j["camera"]["orientation"] = json::array();
  for (int i = 0; i < 1000; ++i) j["camera"]["orientation"].push_back({2, 0, 0, 0});
  std::vector<Problem> problems;
  parse_sidecar(j, "f.vdfx.json", problems);
  ASSERT_EQ(problems.size(), 11u);
  EXPECT_EQ(problems[10].pointer, "/camera/orientation");
  EXPECT_NE(problems[10].message.find("990 more items with problems"), std::string::npos);
}

TEST(SidecarAnchor, RoundTripIsExact) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  test::expect_exact_round_trip(*r.sidecar, test_files::fresh_dir("io/anchor_round_trip"));
}

TEST(SidecarAnchor, WrittenAfterTheEffectsAndOnlyWhenNotVideo) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const std::string text = format_sidecar(*r.sidecar);
  EXPECT_LT(text.find("\"effects\""), text.find("\"camera\""));
  EXPECT_LT(text.find("\"camera\""), text.find("\"tracks\""));
  // The grain's explicit "video" is the default: not written, so files without anchors keep
  // their bytes for readers that predate anchors.
  EXPECT_EQ(text.find("\"anchor\": \"video\""), std::string::npos);
  EXPECT_NE(text.find("\"anchor\": \"track:actor-1\""), std::string::npos);
  Sidecar plain = *r.sidecar;
  plain.camera.reset();
  plain.tracks.clear();
  for (auto& e : plain.effects) e.anchor = {};
  for (auto& f : plain.flares) f.anchor = {};
  const std::string plain_text = format_sidecar(plain);
  EXPECT_EQ(plain_text.find("anchor"), std::string::npos);
  EXPECT_EQ(plain_text.find("camera"), std::string::npos);
  EXPECT_EQ(plain_text.find("tracks"), std::string::npos);
}

}  // namespace
}  // namespace vdfx::io
