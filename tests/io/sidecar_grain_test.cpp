/// @file
/// @brief Sidecar grain entries: the guide's example, defaults, every field's validation with its
/// pointer and reason, several grains beside a flare, and exact round trips.
#include "io/sidecar_grain.h"

#include <gtest/gtest.h>

#include <functional>

#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "tests/io/sidecar_cases.h"
#include "tests/test_files.h"

namespace vdfx::io {
namespace {

using effects::GrainSetting;
using nlohmann::json;

// The guide's free_cloud example after an exposure effect and a flare, then a surface grain with
// one setting and an interpolation override, and a headset grain without settings.
const char* kValid = R"({
  "format": "vdfx.sidecar",
  "version": 1,
  "video": {"path": "clip.mp4", "fps": 30.0, "frames": 300, "width": 3840, "height": 1920},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure",
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 0.0, "frame": 75, "params": {"stops": 1.0}}]},
    {"type": "grain", "style": "free_cloud", "seed": 7,
     "settings": {"refresh_ms": 20.0, "count": 20000, "radius_m": 2.0, "height_m": 3.0},
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
                    "params": {"intensity": 0.4, "size": 1.0}}]},
    {"type": "flare", "style": "directional", "light": "auto", "keyframes": []},
    {"type": "grain", "style": "surface", "seed": 0,
     "settings": {"sphere_m": 4.5},
     "interpolation": {"exponent": 1.5, "time_scale": 2.0},
     "keyframes": [{"azimuth_deg": 90.0, "altitude_deg": 10.0, "frame": 0, "params": {"intensity": 1.0, "size": 0.25}},
                   {"azimuth_deg": -90.0, "altitude_deg": 0.0, "frame": 299, "params": {"intensity": 0.0, "size": 4.0}}]},
    {"type": "grain", "style": "headset", "seed": 9007199254740993, "keyframes": []},
    {"type": "grain", "style": "object_cloud", "seed": 3,
     "settings": {"sphere_m": 20.0, "shell": 1.25, "count": 1000, "refresh_ms": 40},
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 5, "params": {"intensity": 0.5, "size": 2.0}}]}
  ]
})";

TEST(SidecarGrain, SettingsLeftOutTakeTheStylesDefaults) {
  // object_cloud's shell defaults to 2 m (surface keeps 10 m); both clouds to a million particles.
  const std::string text = R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "clip.mp4", "fps": 30.0, "frames": 300, "width": 3840, "height": 1920},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "grain", "style": "object_cloud", "seed": 1, "keyframes": []},
    {"type": "grain", "style": "free_cloud", "seed": 2, "keyframes": []},
    {"type": "grain", "style": "surface", "seed": 3, "keyframes": []}]})";
  const SidecarReport r = validate_sidecar_text(text, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const auto& g = r.sidecar->grains;
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].settings.get(GrainSetting::SphereM), 2.0);
  EXPECT_EQ(g[0].settings.get(GrainSetting::Count), 1000000.0);
  EXPECT_EQ(g[1].settings.get(GrainSetting::Count), 1000000.0);
  EXPECT_EQ(g[2].settings.get(GrainSetting::SphereM), 10.0);
  EXPECT_EQ(g[0].settings, effects::GrainSettings(effects::GrainStyle::ObjectCloud));
}

TEST(SidecarGrain, GuideExampleReadsAsWrittenAndGrainsCoexist) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const Sidecar& s = *r.sidecar;
  ASSERT_EQ(s.effects.size(), 1u);
  ASSERT_EQ(s.flares.size(), 1u);
  ASSERT_EQ(s.grains.size(), 4u);

  const effects::GrainEffect& a = s.grains[0];
  EXPECT_EQ(a.style, effects::GrainStyle::FreeCloud);
  EXPECT_EQ(a.seed, 7u);
  EXPECT_EQ(a.settings.get(GrainSetting::RefreshMs), 20.0);
  EXPECT_EQ(a.settings.get(GrainSetting::Count), 20000.0);
  EXPECT_EQ(a.settings.get(GrainSetting::RadiusM), 2.0);
  EXPECT_EQ(a.settings.get(GrainSetting::HeightM), 3.0);
  ASSERT_EQ(a.keyframes.size(), 1u);
  EXPECT_EQ(a.keyframes[0].params, (std::vector<double>{0.4, 1.0}));
  EXPECT_FALSE(a.interpolation.has_value());

  const effects::GrainEffect& b = s.grains[1];
  EXPECT_EQ(b.style, effects::GrainStyle::Surface);
  EXPECT_EQ(b.seed, 0u);
  EXPECT_EQ(b.settings.get(GrainSetting::SphereM), 4.5);
  EXPECT_EQ(b.settings.get(GrainSetting::RefreshMs), 20.0);  // default
  ASSERT_TRUE(b.interpolation.has_value());
  EXPECT_EQ(b.interpolation->time_scale, 2.0);
  EXPECT_EQ(b.keyframes[1].frame, 299);
  EXPECT_EQ(b.keyframes[1].params, (std::vector<double>{0.0, 4.0}));

  const effects::GrainEffect& c = s.grains[2];
  EXPECT_EQ(c.style, effects::GrainStyle::Headset);
  EXPECT_EQ(c.seed, 9007199254740993u);  // above 2^53: read as an integer, not a double
  EXPECT_EQ(c.settings, effects::GrainSettings());
  EXPECT_EQ(c.settings.get(GrainSetting::PlaneM), 0.05);

  const effects::GrainEffect& d = s.grains[3];
  EXPECT_EQ(d.settings.get(GrainSetting::Shell), 1.25);
  EXPECT_EQ(d.settings.get(GrainSetting::RefreshMs), 40.0);
}

using test::BrokenCase;

// Index 1 is the free cloud, 3 the surface grain, 4 the headset grain, 5 the object cloud.
const BrokenCase kBroken[] = {
    {"style_unknown", [](json& j) { j["effects"][1]["style"] = "snow"; }, "/effects/1/style",
     "unknown grain style \"snow\" (expected: headset, surface, object_cloud, free_cloud)"},
    {"style_missing", [](json& j) { j["effects"][1].erase("style"); }, "/effects/1",
     "missing field \"style\""},
    {"style_not_string", [](json& j) { j["effects"][1]["style"] = 2; }, "/effects/1/style",
     "expected a string"},
    {"unknown_field", [](json& j) { j["effects"][1]["colour"] = "red"; }, "/effects/1/colour",
     "unknown field \"colour\" (expected: type, style, seed, settings, anchor, interpolation, "
     "keyframes)"},
    {"light_is_not_grain", [](json& j) { j["effects"][1]["light"] = "auto"; }, "/effects/1/light",
     "unknown field \"light\""},
    {"seed_missing", [](json& j) { j["effects"][1].erase("seed"); }, "/effects/1",
     "missing field \"seed\""},
    {"seed_negative", [](json& j) { j["effects"][1]["seed"] = -1; }, "/effects/1/seed",
     "out of range [0, 2^63)"},
    {"seed_fraction", [](json& j) { j["effects"][1]["seed"] = 1.5; }, "/effects/1/seed",
     "expected an integer"},
    {"seed_huge", [](json& j) { j["effects"][1]["seed"] = 18446744073709551615ull; },
     "/effects/1/seed", "out of range [0, 2^63)"},
    {"seed_string", [](json& j) { j["effects"][1]["seed"] = "7"; }, "/effects/1/seed",
     "expected an integer"},
    {"settings_not_object", [](json& j) { j["effects"][1]["settings"] = 1; }, "/effects/1/settings",
     "expected an object"},
    {"settings_unknown", [](json& j) { j["effects"][1]["settings"]["density"] = 4; },
     "/effects/1/settings/density",
     "unknown field \"density\" (expected: refresh_ms, count, radius_m, height_m)"},
    {"setting_of_another_style", [](json& j) { j["effects"][1]["settings"]["sphere_m"] = 4; },
     "/effects/1/settings/sphere_m",
     "\"sphere_m\" is not a setting of style free_cloud (its settings: refresh_ms, count, "
     "radius_m, height_m)"},
    {"plane_on_surface", [](json& j) { j["effects"][3]["settings"]["plane_m"] = 0.1; },
     "/effects/3/settings/plane_m",
     "is not a setting of style surface (its settings: refresh_ms, sphere_m)"},
    {"refresh_small", [](json& j) { j["effects"][1]["settings"]["refresh_ms"] = 0.5; },
     "/effects/1/settings/refresh_ms", "out of range [1, 60000]"},
    {"refresh_nan", [](json& j) { j["effects"][1]["settings"]["refresh_ms"] = std::nan(""); },
     "/effects/1/settings/refresh_ms", "not a finite number"},
    {"refresh_string", [](json& j) { j["effects"][1]["settings"]["refresh_ms"] = "20"; },
     "/effects/1/settings/refresh_ms", "expected a number"},
    {"count_zero", [](json& j) { j["effects"][1]["settings"]["count"] = 0; },
     "/effects/1/settings/count", "out of range [1, 1000000]"},
    {"count_big", [](json& j) { j["effects"][1]["settings"]["count"] = 1000001; },
     "/effects/1/settings/count", "out of range [1, 1000000]"},
    {"count_fraction", [](json& j) { j["effects"][1]["settings"]["count"] = 10.5; },
     "/effects/1/settings/count", "expected an integer"},
    {"radius_small", [](json& j) { j["effects"][1]["settings"]["radius_m"] = 0.05; },
     "/effects/1/settings/radius_m", "out of range [0.1, 100]"},
    {"height_big", [](json& j) { j["effects"][1]["settings"]["height_m"] = 101; },
     "/effects/1/settings/height_m", "out of range [0.1, 100]"},
    {"sphere_small", [](json& j) { j["effects"][3]["settings"]["sphere_m"] = 0.05; },
     "/effects/3/settings/sphere_m", "out of range [0.1, 1000]"},
    {"plane_small",
     [](json& j) {
       j["effects"][4]["settings"] = {{"plane_m", 0.001}};
     },
     "/effects/4/settings/plane_m", "out of range [0.01, 100]"},
    {"shell_one", [](json& j) { j["effects"][5]["settings"]["shell"] = 1.0; },
     "/effects/5/settings/shell", "out of range (1, 4]"},
    {"shell_big", [](json& j) { j["effects"][5]["settings"]["shell"] = 4.5; },
     "/effects/5/settings/shell", "out of range (1, 4]"},
    {"interpolation_bad", [](json& j) { j["effects"][3]["interpolation"]["exponent"] = 5.0; },
     "/effects/3/interpolation/exponent", "out of range"},
    {"interpolation_unknown", [](json& j) { j["effects"][3]["interpolation"]["kernel"] = "tps"; },
     "/effects/3/interpolation/kernel", "unknown field"},
    {"keyframes_missing", [](json& j) { j["effects"][1].erase("keyframes"); }, "/effects/1",
     "missing field \"keyframes\""},
    {"keyframes_not_array", [](json& j) { j["effects"][1]["keyframes"] = json::object(); },
     "/effects/1/keyframes", "expected an array"},
    {"keyframe_not_object", [](json& j) { j["effects"][1]["keyframes"][0] = 1; },
     "/effects/1/keyframes/0", "expected an object"},
    {"intensity_big", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["intensity"] = 1.5; },
     "/effects/1/keyframes/0/params/intensity", "out of range [0, 1]"},
    {"intensity_negative",
     [](json& j) { j["effects"][3]["keyframes"][1]["params"]["intensity"] = -0.1; },
     "/effects/3/keyframes/1/params/intensity", "out of range [0, 1]"},
    {"intensity_missing",
     [](json& j) { j["effects"][1]["keyframes"][0]["params"].erase("intensity"); },
     "/effects/1/keyframes/0/params", "missing field \"intensity\""},
    {"size_small", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["size"] = 0.2; },
     "/effects/1/keyframes/0/params/size", "out of range [0.25, 4]"},
    {"size_big", [](json& j) { j["effects"][3]["keyframes"][0]["params"]["size"] = 4.01; },
     "/effects/3/keyframes/0/params/size", "out of range [0.25, 4]"},
    {"size_missing", [](json& j) { j["effects"][1]["keyframes"][0]["params"].erase("size"); },
     "/effects/1/keyframes/0/params", "missing field \"size\""},
    {"size_not_number",
     [](json& j) { j["effects"][1]["keyframes"][0]["params"]["size"] = json::array({1}); },
     "/effects/1/keyframes/0/params/size", "expected a number"},
    {"param_unknown", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["stops"] = 1.0; },
     "/effects/1/keyframes/0/params/stops", "unknown field \"stops\" (expected: intensity, size)"},
    {"params_missing", [](json& j) { j["effects"][1]["keyframes"][0].erase("params"); },
     "/effects/1/keyframes/0", "missing field \"params\""},
    {"keyframe_frame_past_end", [](json& j) { j["effects"][1]["keyframes"][0]["frame"] = 300; },
     "/effects/1/keyframes/0/frame", "out of range [0, 300)"},
    {"keyframe_azimuth", [](json& j) { j["effects"][1]["keyframes"][0]["azimuth_deg"] = 200.0; },
     "/effects/1/keyframes/0/azimuth_deg", "out of range"},
    {"keyframe_altitude_missing",
     [](json& j) { j["effects"][1]["keyframes"][0].erase("altitude_deg"); },
     "/effects/1/keyframes/0", "missing field \"altitude_deg\""},
    {"type_unknown_lists_grain", [](json& j) { j["effects"][1]["type"] = "grian"; },
     "/effects/1/type",
     "unknown effect type \"grian\" (known: blur, tint, exposure, saturation, contrast, vignette, "
     "flare, grain)"},
};

class SidecarGrainBroken : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(SidecarGrainBroken, ReportsPointerAndReason) {
  EXPECT_TRUE(test::reports_as_expected(kValid, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Cases, SidecarGrainBroken, ::testing::ValuesIn(kBroken),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SidecarGrain, ReportsEveryProblemOfOneGrainAndNamesTheFile) {
  json j = json::parse(kValid);
  j["effects"][1]["style"] = "x";
  j["effects"][1]["seed"] = -3;
  j["effects"][1]["settings"]["count"] = 0;
  j["effects"][1]["keyframes"][0]["params"]["size"] = 9;
  j["effects"][3]["keyframes"][0]["params"]["intensity"] = 2;
  const SidecarReport r = validate_sidecar_text(j.dump(), "shot.vdfx.json");
  ASSERT_EQ(r.problems.size(), 5u) << r.to_string();
  EXPECT_NE(r.to_string().find("shot.vdfx.json: /effects/1/seed: value -3 is out of range"),
            std::string::npos);
  EXPECT_FALSE(r.sidecar.has_value());
}

effects::GrainEffect awkward_grain(effects::GrainStyle style, std::uint64_t seed) {
  effects::GrainEffect g;
  g.style = style;
  g.seed = seed;
  for (effects::GrainSetting id : effects::grain_style_settings(style)) {
    const auto& spec = effects::grain_setting_spec(id);
    g.settings.set(id, spec.integer ? spec.max : spec.max * (1.0 / 3.0) + 0.1 + 0.2);
  }
  g.keyframes.push_back({{179.99999999999997, -89.999999999999986}, 299, {1.0 / 3.0, 0.1 + 0.2}});
  g.keyframes.push_back({{-0.1, 5e-324}, 0, {0.0, 4.0}});
  return g;
}

Sidecar grain_sidecar() {
  Sidecar s;
  s.video = {"clip.mp4", 30000.0 / 1001.0, 300, 3840, 1920};
  effects::EffectTrack exposure{effects::EffectType::Exposure, std::nullopt, {}};
  exposure.keyframes.push_back({{10.0, 0.0}, 3, {0.5}});
  s.effects = {exposure};
  s.grains.push_back(awkward_grain(effects::GrainStyle::Headset, 0));
  s.grains.push_back(awkward_grain(effects::GrainStyle::Surface, 9223372036854775807ull));
  s.grains.push_back(awkward_grain(effects::GrainStyle::ObjectCloud, 12345));
  s.grains.push_back(awkward_grain(effects::GrainStyle::FreeCloud, 1));
  s.grains.back().interpolation =
      effects::InterpolationSettings{0.25, 999.0, effects::AngularDistance::Geodesic};
  s.grains.back().keyframes.clear();
  return s;
}

TEST(SidecarGrain, RoundTripIsExact) {
  const auto dir = test_files::fresh_dir("io/grain_round_trip");
  test::expect_exact_round_trip(grain_sidecar(), dir);
  // The guide's file too: read -> write -> read gives the same model.
  const SidecarReport r = validate_sidecar_text(kValid, "t");
  ASSERT_TRUE(r.ok());
  write_sidecar(dir / "c.vdfx.json", *r.sidecar);
  EXPECT_EQ(read_sidecar(dir / "c.vdfx.json"), *r.sidecar);
}

TEST(SidecarGrain, WrittenInTheGuidesKeyOrderAfterTheFlares) {
  Sidecar s = grain_sidecar();
  s.grains.resize(1);
  s.flares.emplace_back();
  const std::string text = format_sidecar(s);
  const auto flare = text.find("\"flare\""), grain = text.find("\"grain\"");
  ASSERT_NE(grain, std::string::npos);
  EXPECT_LT(flare, grain);
  const auto ordered = nlohmann::ordered_json::parse(text)["effects"][2];
  std::vector<std::string> keys, settings;
  for (const auto& [k, v] : ordered.items()) keys.push_back(k);
  for (const auto& [k, v] : ordered["settings"].items()) settings.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"type", "style", "seed", "settings", "keyframes"}));
  // The headset style's settings, all explicit, in the guide's order; count is an integer.
  EXPECT_EQ(settings, (std::vector<std::string>{"refresh_ms", "plane_m"}));
  const auto cloud = nlohmann::ordered_json::parse(format_sidecar(grain_sidecar()))["effects"][3];
  EXPECT_TRUE(cloud["settings"]["count"].is_number_integer());
}

}  // namespace
}  // namespace vdfx::io
