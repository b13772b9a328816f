/// @file
/// @brief Sidecar flare entries: the guide's example, defaults, every field's validation with its
/// pointer and reason, coexisting flares, and exact round trips.
#include "io/sidecar_flare.h"

#include <gtest/gtest.h>

#include <functional>

#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "tests/io/sidecar_cases.h"
#include "tests/test_files.h"

namespace vdfx::io {
namespace {

using nlohmann::json;

// The guide's example (shared/guide/flare-grain.md), after an exposure effect, then a headset
// flare on a track and an auto flare without settings.
const char* kValid = R"({
  "format": "vdfx.sidecar",
  "version": 1,
  "video": {"path": "clip.mp4", "fps": 30.0, "frames": 300, "width": 3840, "height": 1920},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure",
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 0.0, "frame": 75, "params": {"stops": 1.0}}]},
    {"type": "flare", "style": "directional",
     "light": {"azimuth_deg": 40.0, "altitude_deg": 12.0},
     "settings": {"fade_deg": 15.0, "ramp_deg": 5.0, "rings": 6, "plane_m": 100.0},
     "keyframes": [{"azimuth_deg": 40.0, "altitude_deg": 10.0, "frame": 0,
                    "params": {"intensity": 1.0}}]},
    {"type": "flare", "style": "headset",
     "light": [{"frame": 0, "azimuth_deg": -20.0, "altitude_deg": 5.0},
               {"frame": 120, "azimuth_deg": 20.0, "altitude_deg": 25.0}],
     "settings": {"rings": 3},
     "interpolation": {"exponent": 1.5, "time_scale": 2.0},
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 10.0, "frame": 0, "params": {"intensity": 2.5}},
                   {"azimuth_deg": 90.0, "altitude_deg": 0.0, "frame": 299, "params": {"intensity": 0.0}}]},
    {"type": "flare", "style": "directional", "light": "auto", "keyframes": []}
  ]
})";

TEST(SidecarFlare, GuideExampleReadsAsWrittenAndFlaresCoexist) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const Sidecar& s = *r.sidecar;
  ASSERT_EQ(s.effects.size(), 1u);
  ASSERT_EQ(s.flares.size(), 3u);

  const effects::FlareEffect& a = s.flares[0];
  EXPECT_EQ(a.style, effects::FlareStyle::Directional);
  ASSERT_TRUE(std::holds_alternative<effects::Direction>(a.light));
  EXPECT_EQ(std::get<effects::Direction>(a.light), (effects::Direction{40.0, 12.0}));
  EXPECT_EQ(a.settings, (effects::FlareSettings{15.0, 5.0, 6, 100.0}));
  ASSERT_EQ(a.keyframes.size(), 1u);
  EXPECT_EQ(a.keyframes[0].direction, (effects::Direction{40.0, 10.0}));
  EXPECT_EQ(a.keyframes[0].params, std::vector<double>{1.0});
  EXPECT_FALSE(a.interpolation.has_value());

  const effects::FlareEffect& b = s.flares[1];
  EXPECT_EQ(b.style, effects::FlareStyle::Headset);
  const auto& track = std::get<std::vector<effects::LightSample>>(b.light);
  ASSERT_EQ(track.size(), 2u);
  EXPECT_EQ(track[1].frame, 120);
  EXPECT_EQ(track[1].direction, (effects::Direction{20.0, 25.0}));
  // Only rings given: the rest are the headset style's defaults (plane 5 cm).
  EXPECT_EQ(b.settings, (effects::FlareSettings{15.0, 5.0, 3, 0.05}));
  ASSERT_TRUE(b.interpolation.has_value());
  EXPECT_EQ(b.interpolation->exponent, 1.5);
  EXPECT_EQ(b.keyframes[1].params, std::vector<double>{0.0});

  const effects::FlareEffect& c = s.flares[2];
  EXPECT_TRUE(std::holds_alternative<effects::AutoLight>(c.light));
  EXPECT_EQ(c.settings, effects::default_flare_settings(effects::FlareStyle::Directional));
  EXPECT_TRUE(c.keyframes.empty());
}

using test::BrokenCase;

// Index 1 is the directional flare, 2 the headset flare on a track.
const BrokenCase kBroken[] = {
    {"style_unknown", [](json& j) { j["effects"][1]["style"] = "anamorphic"; }, "/effects/1/style",
     "unknown flare style \"anamorphic\" (expected headset or directional)"},
    {"style_missing", [](json& j) { j["effects"][1].erase("style"); }, "/effects/1",
     "missing field \"style\""},
    {"style_not_string", [](json& j) { j["effects"][1]["style"] = 1; }, "/effects/1/style",
     "expected a string"},
    {"unknown_field", [](json& j) { j["effects"][1]["colour"] = "red"; }, "/effects/1/colour",
     "unknown field \"colour\""},
    {"light_missing", [](json& j) { j["effects"][1].erase("light"); }, "/effects/1",
     "missing field \"light\""},
    {"light_azimuth_range", [](json& j) { j["effects"][1]["light"]["azimuth_deg"] = 181.0; },
     "/effects/1/light/azimuth_deg", "out of range (-180, 180]"},
    {"light_altitude_range", [](json& j) { j["effects"][1]["light"]["altitude_deg"] = -90.5; },
     "/effects/1/light/altitude_deg", "out of range [-90, 90]"},
    {"light_altitude_missing", [](json& j) { j["effects"][1]["light"].erase("altitude_deg"); },
     "/effects/1/light", "missing field \"altitude_deg\""},
    {"light_unknown_field", [](json& j) { j["effects"][1]["light"]["distance_m"] = 3; },
     "/effects/1/light/distance_m", "unknown field"},
    {"light_string", [](json& j) { j["effects"][1]["light"] = "sun"; }, "/effects/1/light",
     "unknown light \"sun\""},
    {"light_number", [](json& j) { j["effects"][1]["light"] = 4; }, "/effects/1/light",
     "expected a direction object, a track"},
    {"track_empty", [](json& j) { j["effects"][2]["light"] = json::array(); }, "/effects/2/light",
     "at least one"},
    {"track_not_increasing", [](json& j) { j["effects"][2]["light"][1]["frame"] = 0; },
     "/effects/2/light/1/frame", "not after the previous sample's 0"},
    {"track_frame_past_end", [](json& j) { j["effects"][2]["light"][1]["frame"] = 300; },
     "/effects/2/light/1/frame", "out of range [0, 300)"},
    {"track_sample_not_object", [](json& j) { j["effects"][2]["light"][0] = 3; },
     "/effects/2/light/0", "expected an object"},
    {"track_sample_unknown_field", [](json& j) { j["effects"][2]["light"][0]["roll"] = 0; },
     "/effects/2/light/0/roll", "unknown field"},
    {"track_sample_azimuth", [](json& j) { j["effects"][2]["light"][0]["azimuth_deg"] = -180.0; },
     "/effects/2/light/0/azimuth_deg", "out of range (-180, 180]"},
    {"track_antipodal",
     [](json& j) {
       j["effects"][2]["light"][1]["azimuth_deg"] = 160.0;
       j["effects"][2]["light"][1]["altitude_deg"] = -5.0;
     },
     "/effects/2/light/1", "opposite directions"},
    {"settings_not_object", [](json& j) { j["effects"][1]["settings"] = 1; }, "/effects/1/settings",
     "expected an object"},
    {"settings_unknown", [](json& j) { j["effects"][1]["settings"]["streaks"] = 4; },
     "/effects/1/settings/streaks", "unknown field"},
    {"fade_zero", [](json& j) { j["effects"][1]["settings"]["fade_deg"] = 0.0; },
     "/effects/1/settings/fade_deg", "out of range (0, 80]"},
    {"fade_big", [](json& j) { j["effects"][1]["settings"]["fade_deg"] = 80.5; },
     "/effects/1/settings/fade_deg", "out of range (0, 80]"},
    {"ramp_negative", [](json& j) { j["effects"][1]["settings"]["ramp_deg"] = -1.0; },
     "/effects/1/settings/ramp_deg", "out of range [0, 40]"},
    {"fade_plus_ramp",
     [](json& j) {
       j["effects"][1]["settings"]["fade_deg"] = 80.0;
       j["effects"][1]["settings"]["ramp_deg"] = 12.0;
     },
     "/effects/1/settings/ramp_deg", "fade_deg + ramp_deg / 2 = 86 exceeds 85"},
    {"rings_big", [](json& j) { j["effects"][1]["settings"]["rings"] = 17; },
     "/effects/1/settings/rings", "out of range [0, 16]"},
    {"rings_fraction", [](json& j) { j["effects"][1]["settings"]["rings"] = 2.5; },
     "/effects/1/settings/rings", "expected an integer"},
    {"plane_small", [](json& j) { j["effects"][1]["settings"]["plane_m"] = 0.005; },
     "/effects/1/settings/plane_m", "out of range [0.01, 10000]"},
    {"plane_nan", [](json& j) { j["effects"][1]["settings"]["plane_m"] = std::nan(""); },
     "/effects/1/settings/plane_m", "not a finite number"},
    {"interpolation_bad", [](json& j) { j["effects"][2]["interpolation"]["exponent"] = 5.0; },
     "/effects/2/interpolation/exponent", "out of range"},
    {"keyframes_missing", [](json& j) { j["effects"][1].erase("keyframes"); }, "/effects/1",
     "missing field \"keyframes\""},
    {"keyframes_not_array", [](json& j) { j["effects"][1]["keyframes"] = json::object(); },
     "/effects/1/keyframes", "expected an array"},
    {"intensity_big", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["intensity"] = 4.5; },
     "/effects/1/keyframes/0/params/intensity", "out of range [0, 4]"},
    {"intensity_negative",
     [](json& j) { j["effects"][2]["keyframes"][1]["params"]["intensity"] = -0.1; },
     "/effects/2/keyframes/1/params/intensity", "out of range [0, 4]"},
    {"intensity_missing",
     [](json& j) { j["effects"][1]["keyframes"][0]["params"].erase("intensity"); },
     "/effects/1/keyframes/0/params", "missing field \"intensity\""},
    {"param_unknown", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["stops"] = 1.0; },
     "/effects/1/keyframes/0/params/stops", "unknown field \"stops\" (expected: intensity)"},
    {"params_missing", [](json& j) { j["effects"][1]["keyframes"][0].erase("params"); },
     "/effects/1/keyframes/0", "missing field \"params\""},
    {"keyframe_frame_past_end", [](json& j) { j["effects"][1]["keyframes"][0]["frame"] = 300; },
     "/effects/1/keyframes/0/frame", "out of range [0, 300)"},
    {"keyframe_azimuth", [](json& j) { j["effects"][1]["keyframes"][0]["azimuth_deg"] = 200.0; },
     "/effects/1/keyframes/0/azimuth_deg", "out of range"},
};

class SidecarFlareBroken : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(SidecarFlareBroken, ReportsPointerAndReason) {
  EXPECT_TRUE(test::reports_as_expected(kValid, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Cases, SidecarFlareBroken, ::testing::ValuesIn(kBroken),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SidecarFlare, ReportsEveryProblemOfOneFlare) {
  json j = json::parse(kValid);
  j["effects"][1]["style"] = "x";
  j["effects"][1]["light"]["azimuth_deg"] = 400;
  j["effects"][1]["settings"]["rings"] = -1;
  j["effects"][1]["keyframes"][0]["params"]["intensity"] = 9;
  std::vector<Problem> problems;
  parse_sidecar(j, "f", problems);
  EXPECT_EQ(problems.size(), 4u);
}

effects::FlareEffect awkward_flare(effects::FlareLight light, effects::FlareStyle style) {
  effects::FlareEffect f;
  f.style = style;
  f.light = std::move(light);
  f.settings = {0.1 + 0.2, 1.0 / 3.0, 16, 9999.999999999998};
  f.keyframes.push_back({{179.99999999999997, -89.999999999999986}, 299, {4.0}});
  f.keyframes.push_back({{-0.1, 5e-324}, 0, {1.0 / 7.0}});
  return f;
}

Sidecar flare_sidecar() {
  Sidecar s;
  s.video = {"clip.mp4", 30000.0 / 1001.0, 300, 3840, 1920};
  effects::EffectTrack exposure{effects::EffectType::Exposure, std::nullopt, {}};
  exposure.keyframes.push_back({{10.0, 0.0}, 3, {0.5}});
  s.effects = {exposure};
  s.flares.push_back(awkward_flare(effects::Direction{-179.99999999999997, 89.999999999999986},
                                   effects::FlareStyle::Directional));
  s.flares.push_back(awkward_flare(
      std::vector<effects::LightSample>{
          {0, {1.0 / 3.0, -2.0 / 3.0}}, {1, {120.0, 0.0}}, {299, {-60.0, 45.0}}},
      effects::FlareStyle::Headset));
  s.flares.push_back(awkward_flare(effects::AutoLight{}, effects::FlareStyle::Directional));
  s.flares.back().interpolation =
      effects::InterpolationSettings{0.25, 999.0, effects::AngularDistance::Geodesic};
  s.flares.back().keyframes.clear();
  return s;
}

TEST(SidecarFlare, RoundTripIsExact) {
  const auto dir = test_files::fresh_dir("io/flare_round_trip");
  test::expect_exact_round_trip(flare_sidecar(), dir);
}

TEST(SidecarFlare, WrittenInTheGuidesKeyOrderAfterTheStackEffects) {
  Sidecar s = flare_sidecar();
  s.flares.resize(1);
  const std::string text = format_sidecar(s);
  const auto exposure = text.find("\"exposure\""), flare = text.find("\"flare\"");
  ASSERT_NE(flare, std::string::npos);
  EXPECT_LT(exposure, flare);
  const json e = json::parse(text)["effects"][1];
  EXPECT_EQ(e["type"], "flare");
  // Key order as the guide writes it; settings always explicit.
  const auto ordered = nlohmann::ordered_json::parse(text)["effects"][1];
  std::vector<std::string> keys;
  for (const auto& [k, v] : ordered.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"type", "style", "light", "settings", "keyframes"}));
  EXPECT_EQ(e["settings"].size(), 4u);
}

TEST(SidecarFlare, ReadingFillsTheStylesDefaultsAndWritingMakesThemExplicit) {
  json j = json::parse(kValid);
  j["effects"][1].erase("settings");
  j["effects"][1]["style"] = "headset";
  std::vector<Problem> problems;
  const Sidecar s = parse_sidecar(j, "f", problems);
  ASSERT_TRUE(problems.empty());
  EXPECT_EQ(s.flares[0].settings.plane_m, 0.05);
  EXPECT_EQ(flare_to_json(s.flares[0])["settings"]["plane_m"], 0.05);
}

}  // namespace
}  // namespace vdfx::io
