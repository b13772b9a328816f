/// @file
/// @brief Sidecar format 1: every error class reported with its pointer, and exact round trips.
#include "io/sidecar.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include "io/input_error.h"
#include "io/sidecar_validate.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"

namespace vdfx::io {
namespace {

using nlohmann::json;

const char* kValid = R"({
  "format": "vdfx.sidecar",
  "version": 1,
  "video": {"path": "clip.mp4", "fps": 30.0, "frames": 900, "width": 3840, "height": 1920},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure",
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 0.0, "frame": 75,
                    "params": {"stops": 1.0}}]},
    {"type": "tint", "interpolation": {"exponent": 1.5, "time_scale": 2.0, "distance": "geodesic",
                                       "outside_span": "extrapolate"},
     "keyframes": [{"azimuth_deg": -90.0, "altitude_deg": 45.0, "frame": 0,
                    "params": {"gain": [1.0, 0.5, 2.0]}},
                   {"azimuth_deg": 180.0, "altitude_deg": -90.0, "frame": 899,
                    "params": {"gain": [0.0, 4.0, 1.0]}}]},
    {"type": "vignette",
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 90.0, "frame": 10,
                    "params": {"radius_deg": 40.0, "falloff_deg": 0.01}}]}
  ]
})";

std::filesystem::path temp_dir(const std::string& name) {
  const auto d = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "io" / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

TEST(Sidecar, ContractExampleIsValidAndReadsAsWritten) {
  const SidecarReport r = validate_sidecar_text(kValid, "t.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const Sidecar& s = *r.sidecar;
  EXPECT_EQ(s.video.path, "clip.mp4");
  EXPECT_EQ(s.video.frames, 900);
  EXPECT_EQ(s.video.width, 3840);
  ASSERT_EQ(s.effects.size(), 3u);
  EXPECT_EQ(s.effects[0].type, effects::EffectType::Exposure);
  EXPECT_FALSE(s.effects[0].interpolation.has_value());
  EXPECT_EQ(s.effects[0].keyframes[0].frame, 75);
  EXPECT_EQ(s.effects[0].keyframes[0].params, std::vector<double>{1.0});
  ASSERT_TRUE(s.effects[1].interpolation.has_value());
  EXPECT_EQ(s.effects[1].interpolation->distance, effects::AngularDistance::Geodesic);
  EXPECT_EQ(s.effects[1].interpolation->outside, effects::TimeOutside::Extrapolate);
  EXPECT_EQ(s.effects[1].interpolation->exponent, 1.5);
  EXPECT_EQ(s.effects[1].keyframes[0].params, (std::vector<double>{1.0, 0.5, 2.0}));
  EXPECT_EQ(s.effects[2].keyframes[0].params, (std::vector<double>{40.0, 0.01}));
  EXPECT_EQ(s.interpolation.distance, effects::AngularDistance::Chordal);
  EXPECT_EQ(s.interpolation.outside, effects::TimeOutside::Hold);  // absent: hold
}

struct BrokenCase {
  const char* name;
  std::function<void(json&)> mutate;
  const char* pointer;  //!< expected pointer of (one of) the problems
  const char* message;  //!< expected substring of that problem's message
};

const BrokenCase kBroken[] = {
    {"missing_format", [](json& j) { j.erase("format"); }, "", "missing field \"format\""},
    {"wrong_format", [](json& j) { j["format"] = "other"; }, "/format",
     "expected \"vdfx.sidecar\""},
    {"format_not_string", [](json& j) { j["format"] = 1; }, "/format", "expected a string"},
    {"version_2", [](json& j) { j["version"] = 2; }, "/version", "only version 1"},
    {"version_string", [](json& j) { j["version"] = "1"; }, "/version", "expected an integer"},
    {"missing_version", [](json& j) { j.erase("version"); }, "", "missing field \"version\""},
    {"root_array", [](json& j) { j = json::array(); }, "", "expected an object"},
    {"unknown_top_field", [](json& j) { j["colour"] = 1; }, "/colour", "unknown field"},
    {"missing_video", [](json& j) { j.erase("video"); }, "", "missing field \"video\""},
    {"missing_fps", [](json& j) { j["video"].erase("fps"); }, "/video", "missing field \"fps\""},
    {"fps_zero", [](json& j) { j["video"]["fps"] = 0.0; }, "/video/fps", "out of range"},
    {"fps_negative", [](json& j) { j["video"]["fps"] = -30; }, "/video/fps", "out of range"},
    {"fps_nan", [](json& j) { j["video"]["fps"] = std::nan(""); }, "/video/fps", "not a finite"},
    {"fps_inf", [](json& j) { j["video"]["fps"] = std::numeric_limits<double>::infinity(); },
     "/video/fps", "not a finite"},
    {"fps_string", [](json& j) { j["video"]["fps"] = "30"; }, "/video/fps", "expected a number"},
    {"frames_zero", [](json& j) { j["video"]["frames"] = 0; }, "/video/frames", "out of range"},
    {"frames_fraction", [](json& j) { j["video"]["frames"] = 90.5; }, "/video/frames",
     "expected an integer"},
    {"frames_huge", [](json& j) { j["video"]["frames"] = 1e19; }, "/video/frames", "out of range"},
    {"width_zero", [](json& j) { j["video"]["width"] = 0; }, "/video/width", "out of range"},
    {"height_too_big", [](json& j) { j["video"]["height"] = 1LL << 40; }, "/video/height",
     "out of range"},
    {"path_empty", [](json& j) { j["video"]["path"] = ""; }, "/video/path", "empty"},
    {"video_unknown_field", [](json& j) { j["video"]["codec"] = "h264"; }, "/video/codec",
     "unknown field"},
    {"missing_interpolation", [](json& j) { j.erase("interpolation"); }, "",
     "missing field \"interpolation\""},
    {"exponent_zero", [](json& j) { j["interpolation"]["exponent"] = 0.0; },
     "/interpolation/exponent", "out of range (0, 4)"},
    {"exponent_four", [](json& j) { j["interpolation"]["exponent"] = 4.0; },
     "/interpolation/exponent", "out of range"},
    {"time_scale_zero", [](json& j) { j["interpolation"]["time_scale"] = 0; },
     "/interpolation/time_scale", "out of range (0, 1000]"},
    {"time_scale_big", [](json& j) { j["interpolation"]["time_scale"] = 1000.5; },
     "/interpolation/time_scale", "out of range"},
    {"missing_exponent", [](json& j) { j["interpolation"].erase("exponent"); }, "/interpolation",
     "missing field \"exponent\""},
    {"distance_unknown", [](json& j) { j["interpolation"]["distance"] = "euclid"; },
     "/interpolation/distance", "unknown distance"},
    {"outside_span_unknown", [](json& j) { j["interpolation"]["outside_span"] = "clamp"; },
     "/interpolation/outside_span", "expected hold or extrapolate"},
    {"outside_span_not_string",
     [](json& j) { j["effects"][1]["interpolation"]["outside_span"] = 1; },
     "/effects/1/interpolation/outside_span", "expected a string"},
    {"reach_zero", [](json& j) { j["interpolation"]["reach_s"] = 0; }, "/interpolation/reach_s",
     "reach_s 0 is out of range (0, 1e+07]"},
    {"reach_negative", [](json& j) { j["effects"][1]["interpolation"]["reach_s"] = -2.5; },
     "/effects/1/interpolation/reach_s", "out of range"},
    {"reach_not_number", [](json& j) { j["interpolation"]["reach_s"] = "auto"; },
     "/interpolation/reach_s", "expected a number"},
    {"effect_interp_bad", [](json& j) { j["effects"][1]["interpolation"]["exponent"] = -1; },
     "/effects/1/interpolation/exponent", "out of range"},
    {"effects_not_array", [](json& j) { j["effects"] = json::object(); }, "/effects",
     "expected an array"},
    {"effect_not_object", [](json& j) { j["effects"][0] = 3; }, "/effects/0", "expected an object"},
    {"unknown_type", [](json& j) { j["effects"][0]["type"] = "sparkle"; }, "/effects/0/type",
     "unknown effect type \"sparkle\" (known: blur, tint, exposure, saturation, contrast, "
     "vignette, flare, grain)"},
    {"type_twice",
     [](json& j) {
       j["effects"][2]["type"] = "exposure";
       j["effects"][2]["keyframes"] = json::array();
     },
     "/effects/2/type", "appears twice (first at /effects/0)"},
    {"missing_type", [](json& j) { j["effects"][0].erase("type"); }, "/effects/0",
     "missing field \"type\""},
    {"missing_keyframes", [](json& j) { j["effects"][0].erase("keyframes"); }, "/effects/0",
     "missing field \"keyframes\""},
    {"effect_unknown_field", [](json& j) { j["effects"][0]["enabled"] = true; },
     "/effects/0/enabled", "unknown field"},
    {"keyframes_not_array", [](json& j) { j["effects"][0]["keyframes"] = 1; },
     "/effects/0/keyframes", "expected an array"},
    {"frame_missing", [](json& j) { j["effects"][1]["keyframes"][1].erase("frame"); },
     "/effects/1/keyframes/1", "missing field \"frame\""},
    {"frame_negative", [](json& j) { j["effects"][0]["keyframes"][0]["frame"] = -1; },
     "/effects/0/keyframes/0/frame", "out of range"},
    {"frame_past_end", [](json& j) { j["effects"][0]["keyframes"][0]["frame"] = 900; },
     "/effects/0/keyframes/0/frame", "out of range [0, 900)"},
    {"frame_fraction", [](json& j) { j["effects"][0]["keyframes"][0]["frame"] = 75.5; },
     "/effects/0/keyframes/0/frame", "expected an integer"},
    {"azimuth_minus_180", [](json& j) { j["effects"][0]["keyframes"][0]["azimuth_deg"] = -180.0; },
     "/effects/0/keyframes/0/azimuth_deg", "out of range (-180, 180]"},
    {"azimuth_big", [](json& j) { j["effects"][0]["keyframes"][0]["azimuth_deg"] = 181; },
     "/effects/0/keyframes/0/azimuth_deg", "out of range"},
    {"altitude_big", [](json& j) { j["effects"][0]["keyframes"][0]["altitude_deg"] = 90.5; },
     "/effects/0/keyframes/0/altitude_deg", "out of range [-90, 90]"},
    {"altitude_null", [](json& j) { j["effects"][0]["keyframes"][0]["altitude_deg"] = nullptr; },
     "/effects/0/keyframes/0/altitude_deg", "expected a number, found null"},
    {"keyframe_unknown_field", [](json& j) { j["effects"][0]["keyframes"][0]["roll"] = 0; },
     "/effects/0/keyframes/0/roll", "unknown field"},
    {"params_missing", [](json& j) { j["effects"][0]["keyframes"][0].erase("params"); },
     "/effects/0/keyframes/0", "missing field \"params\""},
    {"param_missing",
     [](json& j) { j["effects"][2]["keyframes"][0]["params"].erase("falloff_deg"); },
     "/effects/2/keyframes/0/params", "missing field \"falloff_deg\""},
    {"param_unknown", [](json& j) { j["effects"][0]["keyframes"][0]["params"]["ev"] = 1; },
     "/effects/0/keyframes/0/params/ev",
     "unknown parameter \"ev\" for effect exposure (expected: stops)"},
    {"param_out_of_range",
     [](json& j) { j["effects"][0]["keyframes"][0]["params"]["stops"] = 8.5; },
     "/effects/0/keyframes/0/params/stops", "out of range [-8, 8]"},
    {"vignette_falloff_zero",
     [](json& j) { j["effects"][2]["keyframes"][0]["params"]["falloff_deg"] = 0; },
     "/effects/2/keyframes/0/params/falloff_deg", "out of range [0.01, 180]"},
    {"tint_short",
     [](json& j) {
       j["effects"][1]["keyframes"][0]["params"]["gain"] = {1.0, 1.0};
     },
     "/effects/1/keyframes/0/params/gain", "expected an array of 3 numbers, found 2"},
    {"tint_long",
     [](json& j) {
       j["effects"][1]["keyframes"][0]["params"]["gain"] = {1, 1, 1, 1};
     },
     "/effects/1/keyframes/0/params/gain", "found 4"},
    {"tint_scalar", [](json& j) { j["effects"][1]["keyframes"][0]["params"]["gain"] = 1.0; },
     "/effects/1/keyframes/0/params/gain", "expected an array of 3 numbers, found number"},
    {"tint_component_range",
     [](json& j) { j["effects"][1]["keyframes"][1]["params"]["gain"][1] = 4.5; },
     "/effects/1/keyframes/1/params/gain/1", "out of range [0, 4]"},
    {"tint_component_type",
     [](json& j) { j["effects"][1]["keyframes"][1]["params"]["gain"][2] = "x"; },
     "/effects/1/keyframes/1/params/gain/2", "expected a number"},
};

void PrintTo(const BrokenCase& c, std::ostream* os) {
  *os << c.name;
}

class SidecarBroken : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(SidecarBroken, ReportsPointerAndReason) {
  const BrokenCase& c = GetParam();
  json j = json::parse(kValid);
  c.mutate(j);
  std::vector<Problem> problems;
  parse_sidecar(j, "f.vdfx.json", problems);
  ASSERT_FALSE(problems.empty()) << c.name;
  bool found = false;
  for (const Problem& p : problems) {
    EXPECT_EQ(p.file, "f.vdfx.json");
    found = found || (p.pointer == c.pointer && p.message.find(c.message) != std::string::npos);
  }
  std::string all;
  for (const Problem& p : problems) all += p.to_string() + "\n";
  EXPECT_TRUE(found) << "expected at " << c.pointer << ": " << c.message << "\ngot:\n" << all;
}

INSTANTIATE_TEST_SUITE_P(Cases, SidecarBroken, ::testing::ValuesIn(kBroken),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Sidecar, ReportsEveryProblemNotJustTheFirst) {
  json j = json::parse(kValid);
  j["video"]["fps"] = -1;
  j["effects"][0]["keyframes"][0]["frame"] = 5000;
  j["effects"][1]["keyframes"][1]["params"]["gain"] = {1, 2};
  std::vector<Problem> problems;
  parse_sidecar(j, "f", problems);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0].pointer, "/video/fps");
  EXPECT_EQ(problems[1].pointer, "/effects/0/keyframes/0/frame");
  EXPECT_EQ(problems[2].pointer, "/effects/1/keyframes/1/params/gain");
}

struct TextCase {
  const char* name;
  const char* text;
  const char* pointer;
  const char* message;
};

const TextCase kBrokenText[] = {
    {"trailing_comma", "{\n  \"format\": \"vdfx.sidecar\",\n}", "", "line 3, column 1"},
    {"nan_literal", "{\"format\": NaN}", "", "line 1, column 12"},
    {"infinity_literal", "{\n\"version\": Infinity}", "", "line 2, column"},
    {"overflow", "{\"format\": \"vdfx.sidecar\",\n \"version\": 1e400}", "", "number overflow"},
    {"overflow_line", "{\"format\": \"vdfx.sidecar\",\n \"version\": 1e400}", "",
     "line 2, column 13"},
    {"empty", "", "", "line 1, column 1"},
    {"truncated", "{\"format\": \"vdfx.sidecar\", \"video\": {\"fps\": 3", "", "invalid JSON"},
    {"duplicate_key", "{\"format\": \"vdfx.sidecar\", \"format\": \"vdfx.sidecar\"}", "/format",
     "duplicate key"},
};

void PrintTo(const TextCase& c, std::ostream* os) {
  *os << c.name;
}

class SidecarBrokenText : public ::testing::TestWithParam<TextCase> {};

TEST_P(SidecarBrokenText, ReportsPlace) {
  const TextCase& c = GetParam();
  const SidecarReport r = validate_sidecar_text(c.text, "f.vdfx.json");
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(r.sidecar.has_value());
  bool found = false;
  for (const Problem& p : r.problems)
    found = found || (p.pointer == c.pointer && p.message.find(c.message) != std::string::npos);
  EXPECT_TRUE(found) << "expected at '" << c.pointer << "': " << c.message << "\ngot:\n"
                     << r.to_string();
}

INSTANTIATE_TEST_SUITE_P(Cases, SidecarBrokenText, ::testing::ValuesIn(kBrokenText),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Sidecar, DuplicateKeyDeepInsideNamesItsPointer) {
  json j = json::parse(kValid);
  std::string text = j.dump();
  const std::string needle = "\"stops\":1.0";
  const auto at = text.find(needle);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + needle.size(), ",\"stops\":2.0");
  const SidecarReport r = validate_sidecar_text(text, "f");
  ASSERT_EQ(r.problems.size(), 1u) << r.to_string();
  EXPECT_EQ(r.problems[0].pointer, "/effects/0/keyframes/0/params/stops");
}

TEST(Sidecar, ReadSidecarThrowsListingEveryProblemWithTheFileName) {
  const auto dir = temp_dir("read_throws");
  const auto path = dir / "bad.vdfx.json";
  json j = json::parse(kValid);
  j["video"]["width"] = -1;
  j["effects"][0]["type"] = "glow";
  std::ofstream(path) << j.dump();
  try {
    read_sidecar(path);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string() + ": /video/width: "), std::string::npos) << what;
    EXPECT_NE(what.find(path.string() + ": /effects/0/type: unknown effect type \"glow\""),
              std::string::npos)
        << what;
  }
  EXPECT_THROW(read_sidecar(dir / "missing.vdfx.json"), InputError);
  const SidecarReport missing = validate_sidecar_file(dir / "missing.vdfx.json");
  ASSERT_EQ(missing.problems.size(), 1u);
  EXPECT_NE(missing.problems[0].message.find("no such file"), std::string::npos);
}

Sidecar awkward_sidecar() {
  // Values chosen to need all 17 significant digits, and tiny/huge exponents.
  Sidecar s;
  s.video = {"dir/clip ü.mp4", 30000.0 / 1001.0, 107892, 3840, 1920};
  s.interpolation = {0.1 + 0.2, 1.0 / 3.0, effects::AngularDistance::Geodesic};
  effects::EffectTrack blur{effects::EffectType::Blur, std::nullopt, {}};
  blur.keyframes.push_back({{179.99999999999997, -89.999999999999986}, 107891, {1e-300}});
  blur.keyframes.push_back({{180.0, 90.0}, 0, {10.0}});
  effects::EffectTrack tint{
      effects::EffectType::Tint,
      effects::InterpolationSettings{1.9999999999999998, 1000.0, effects::AngularDistance::Chordal},
      {}};
  tint.keyframes.push_back({{-179.99999999999997, 5e-324}, 3, {0.1, 2.0 / 3.0, 4.0}});
  effects::EffectTrack vignette{effects::EffectType::Vignette, std::nullopt, {}};
  vignette.keyframes.push_back({{0.0, 0.0}, 42, {123.456789012345678, 0.01}});
  effects::EffectTrack empty{effects::EffectType::Contrast, std::nullopt, {}};
  s.effects = {tint, blur, vignette, empty};
  return s;
}

TEST(Sidecar, RoundTripIsExact) {
  const auto dir = temp_dir("round_trip");
  const Sidecar s = awkward_sidecar();
  // The test's own values must be valid, or the round trip proves nothing about reading.
  std::vector<Problem> problems;
  parse_sidecar(to_json(s), "mem", problems);
  ASSERT_TRUE(problems.empty()) << problems[0].to_string();

  write_sidecar(dir / "a.vdfx.json", s);
  const Sidecar back = read_sidecar(dir / "a.vdfx.json");
  EXPECT_EQ(back, s);
  write_sidecar(dir / "b.vdfx.json", back);
  const std::string a = test_files::slurp(dir / "a.vdfx.json");
  EXPECT_EQ(a, test_files::slurp(dir / "b.vdfx.json"));
  EXPECT_EQ(a, format_sidecar(s));
  // The writer keeps the contract's key order (format first) and a final newline.
  EXPECT_EQ(a.rfind("{\n  \"format\": \"vdfx.sidecar\",\n  \"version\": 1,", 0), 0u);
  EXPECT_EQ(a.back(), '\n');
}

TEST(Sidecar, DefaultDistanceIsNotWrittenGeodesicIs) {
  Sidecar s;
  s.interpolation.distance = effects::AngularDistance::Chordal;
  EXPECT_FALSE(to_json(s)["interpolation"].contains("distance"));
  s.interpolation.distance = effects::AngularDistance::Geodesic;
  EXPECT_EQ(to_json(s)["interpolation"]["distance"], "geodesic");
}

TEST(Sidecar, DefaultHoldIsNotWrittenExtrapolateIs) {
  Sidecar s;
  EXPECT_FALSE(to_json(s)["interpolation"].contains("outside_span"));
  s.interpolation.outside = effects::TimeOutside::Extrapolate;
  EXPECT_EQ(to_json(s)["interpolation"]["outside_span"], "extrapolate");
}

TEST(Sidecar, ReachIsWrittenOnlyWhenSetAndReadsBack) {
  Sidecar s;
  s.video = {"clip.mp4", 30.0, 900, 64, 32};
  EXPECT_FALSE(to_json(s)["interpolation"].contains("reach_s"));
  s.interpolation.reach_s = 2.5;
  EXPECT_EQ(to_json(s)["interpolation"]["reach_s"], 2.5);
  effects::InterpolationSettings own;
  own.reach_s = 0.125;
  s.effects.push_back({effects::EffectType::Exposure, own, {{{30.0, 0.0}, 75, {1.0}}}});
  const SidecarReport r = validate_sidecar_text(format_sidecar(s), "t");
  ASSERT_TRUE(r.ok()) << r.to_string();
  EXPECT_EQ(*r.sidecar, s);
  EXPECT_EQ(r.sidecar->effects[0].interpolation->reach_s, 0.125);
}

TEST(Sidecar, NewSidecarUsesTheAuthorTimeScale) {
  const Sidecar s = new_sidecar({"clip.mp4", 25.0, 100, 64, 32});
  EXPECT_EQ(s.interpolation.time_scale, effects::kAuthorTimeScale);
  EXPECT_EQ(s.interpolation.outside, effects::TimeOutside::Hold);
  EXPECT_EQ(s.video.fps, 25.0);
  EXPECT_TRUE(s.effects.empty());
}

TEST(Sidecar, ToJsonOfContractExampleParsesBackEqual) {
  const SidecarReport r = validate_sidecar_text(kValid, "t");
  ASSERT_TRUE(r.ok());
  std::vector<Problem> problems;
  const Sidecar again = parse_sidecar(to_json(*r.sidecar), "t", problems);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(again, *r.sidecar);
}

TEST(Sidecar, IntegralFloatFrameIsAccepted) {
  json j = json::parse(kValid);
  j["effects"][0]["keyframes"][0]["frame"] = 75.0;
  std::vector<Problem> problems;
  const Sidecar s = parse_sidecar(j, "f", problems);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(s.effects[0].keyframes[0].frame, 75);
}

}  // namespace
}  // namespace vdfx::io
