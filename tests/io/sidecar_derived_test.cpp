/// @file
/// @brief Issue 11, classes 4 and 5: a sidecar that validates never evaluates to NaN or infinity
/// and stays within the solver's scale. The validator bounds what the maths derives from fps,
/// frames and time_scale (one frame is 24 / fps * time_scale apart in the RBF distance), and at
/// those bounds the interpolation is still finite and reproduces its keyframes; the number of
/// keyframes per effect is checked at load.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "effects/rbf_windows.h"
#include "effects/stack_interpolator.h"
#include "io/sidecar.h"
#include "io/sidecar_validate.h"

namespace vdfx::io {
namespace {

/// Four exposure keyframes, two pairs at one direction one frame apart (the hardest case for a
/// tiny time step), the last frame of the clip at the far end (the largest span).
std::string sidecar_text(double fps, long long frames, double exponent, double time_scale,
                         const char* effect_interpolation = "") {
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"({"format": "vdfx.sidecar", "version": 1,
    "video": {"path": "c.mp4", "fps": %.17g, "frames": %lld, "width": 2, "height": 1},
    "interpolation": {"exponent": %.17g, "time_scale": %.17g},
    "effects": [{"type": "exposure", %s "keyframes": [
      {"azimuth_deg": 90, "altitude_deg": 0, "frame": 0, "params": {"stops": 1}},
      {"azimuth_deg": 90, "altitude_deg": 0, "frame": 1, "params": {"stops": -1}},
      {"azimuth_deg": 0, "altitude_deg": -30, "frame": %lld, "params": {"stops": 0.5}},
      {"azimuth_deg": 0, "altitude_deg": -30, "frame": 0, "params": {"stops": -0.5}}]}]})",
                fps, frames, exponent, time_scale, effect_interpolation, frames - 1);
  return buf;
}

TEST(SidecarDerived, TimeScalingThatWouldOverflowOrMergeFramesIsRefused) {
  const struct {
    std::string text;
    const char* pointer;
    const char* says;
  } rows[] = {
      // fps 1e-200 validated, then eval printed null and render wrote a black image.
      {sidecar_text(1e-200, 2, 1.0, 1.0), "/video/fps", "fps must be at least 2.4e-59"},
      {sidecar_text(1e300, 2, 1.0, 1.0), "/video/fps", "fps must be at most 2.4e+06"},
      {sidecar_text(30, 2, 1.0, 1.0, R"("interpolation": {"exponent": 1, "time_scale": 1e-6},)"),
       "/effects/0/interpolation/time_scale", "time_scale must be at least 1.25e-05"},
  };
  for (const auto& row : rows) {
    const SidecarReport r = validate_sidecar_text(row.text, "s.vdfx.json");
    ASSERT_EQ(r.problems.size(), 1u) << r.to_string();
    EXPECT_EQ(r.problems[0].pointer, row.pointer) << r.to_string();
    EXPECT_NE(r.problems[0].message.find(row.says), std::string::npos) << r.to_string();
  }
  // One frame has no time axis: nothing to scale.
  std::string still = sidecar_text(1e-200, 1, 1.0, 1.0);
  still.replace(still.find("\"frame\": 1,"), 11, "\"frame\": 0,");
  const SidecarReport r = validate_sidecar_text(still, "s");
  EXPECT_TRUE(r.ok()) << r.to_string();
}

TEST(SidecarDerived, AtTheBoundsTheInterpolationIsFiniteAndReproducesKeyframes) {
  // Just inside each bound, for exponents across their open range (0, 4).
  const double frames = 3;
  const double fps_for_span = 24.0 * 1.0 * (frames - 1) / (0.99 * kMaxScaledTimeSpan);
  const double fps_for_step = 24.0 * 1.0 / (1.01 * kMinScaledFrameStep);
  for (const double fps : {fps_for_span, fps_for_step, 30.0}) {
    for (const double exponent : {0.01, 1.0, 2.0, 3.99}) {
      const SidecarReport r = validate_sidecar_text(
          sidecar_text(fps, static_cast<long long>(frames), exponent, 1.0), "s");
      ASSERT_TRUE(r.ok()) << r.to_string();
      const Sidecar& s = *r.sidecar;
      const effects::StackInterpolator stack(s.effects, s.interpolation, s.video.fps);
      for (const effects::Keyframe& k : s.effects[0].keyframes) {
        const double v = stack.evaluate(k.direction, k.frame).exposure_stops;
        EXPECT_NEAR(v, k.params[0], 1e-4) << "fps " << fps << " exponent " << exponent;
      }
      for (const std::int64_t f : {0, 1, 2})
        EXPECT_TRUE(
            std::isfinite(stack.evaluate(effects::Direction{37.0, 12.0}, f).exposure_stops));
    }
  }
}

/// A document with one exposure effect of `n` keyframes on a spiral over the sphere, at frames
/// 0 .. frames - 1 in turn (a clip of 40000 frames).
nlohmann::json keyframes_document(std::size_t n, std::size_t frames = 40000) {
  nlohmann::json doc = nlohmann::json::parse(sidecar_text(30, 40000, 1.0, 1.0));
  nlohmann::json& keys = doc["effects"][0]["keyframes"];
  keys = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n) - 1.0;
    keys.push_back({{"azimuth_deg", std::fmod(static_cast<double>(i) * 137.50776, 359.0) - 179.0},
                    {"altitude_deg", std::asin(z) * 180.0 / M_PI},
                    {"frame", i % frames},
                    {"params", {{"stops", static_cast<double>(i % 17) / 4.0 - 2.0}}}});
  }
  return doc;
}

TEST(SidecarDerived, KeyframesPerEffectAreCheckedAtLoad) {
  std::vector<Problem> problems;
  (void)parse_sidecar(keyframes_document(kMaxKeyframesPerEffect), "s", problems);
  EXPECT_TRUE(problems.empty());
  (void)parse_sidecar(keyframes_document(kMaxKeyframesPerEffect + 1), "s", problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].pointer, "/effects/0/keyframes");
  EXPECT_NE(problems[0].message.find("100001 keyframes, more than the 100000 an effect may have"),
            std::string::npos)
      << problems[0].message;
}

TEST(SidecarDerived, KeyframesCrowdedIntoOneWindowAreRefused) {
  // Local interpolation splits an effect in time; keyframes crowded into a few frames cannot be
  // split: more than one window's dense solve takes is refused where they are.
  std::vector<Problem> problems;
  (void)parse_sidecar(keyframes_document(effects::kMaxWindowKeyframes + 4, 3), "s", problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].pointer, "/effects/0/keyframes");
  EXPECT_NE(problems[0].message.find("4100 keyframes between frames"), std::string::npos)
      << problems[0].message;
  EXPECT_NE(problems[0].message.find("fall into one window"), std::string::npos)
      << problems[0].message;
  // The same keyframes spread over the clip are fine; so are 4096 in three frames (one global
  // solve, as before local interpolation).
  problems.clear();
  (void)parse_sidecar(keyframes_document(effects::kMaxWindowKeyframes + 4), "s", problems);
  EXPECT_TRUE(problems.empty());
  (void)parse_sidecar(keyframes_document(effects::kMaxWindowKeyframes, 3), "s", problems);
  EXPECT_TRUE(problems.empty());
  // An explicit reach_s that makes a window too full is named in the message.
  nlohmann::json doc = keyframes_document(effects::kMaxWindowKeyframes, 3);
  doc["effects"][0]["interpolation"] = {{"exponent", 1}, {"time_scale", 1}, {"reach_s", 1.0}};
  (void)parse_sidecar(doc, "s", problems);
  EXPECT_TRUE(problems.empty());
  doc = keyframes_document(8000, 3);
  doc["effects"][0]["interpolation"] = {{"exponent", 1}, {"time_scale", 1}, {"reach_s", 1.0}};
  (void)parse_sidecar(doc, "s", problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("(reach_s 1)"), std::string::npos) << problems[0].message;
  EXPECT_NE(problems[0].message.find("lower reach_s"), std::string::npos) << problems[0].message;
}

TEST(SidecarDerived, FlareAndGrainEntriesKeepTheSameLimits) {
  // The extension types are read by readers of their own; the keyframe limit and the time-scaling
  // check hold for them too, and every problem is reported at the entry's own index in the file
  // (the stack effects' in-memory index differs once flares or grains come before them).
  nlohmann::json doc = keyframes_document(kMaxKeyframesPerEffect + 1);
  nlohmann::json many = doc["effects"][0]["keyframes"];
  for (auto& k : many) k["params"] = {{"intensity", 0.5}};
  nlohmann::json many_grain = many;
  for (auto& k : many_grain) k["params"] = {{"intensity", 0.5}, {"size", 1.0}};
  const nlohmann::json tiny = {{"exponent", 1}, {"time_scale", 1e-6}};
  nlohmann::json exposure = nlohmann::json::parse(sidecar_text(30, 50, 1.0, 1.0))["effects"][0];
  exposure["interpolation"] = tiny;
  doc["effects"] = {
      {{"type", "flare"}, {"style", "headset"}, {"light", "auto"}, {"keyframes", many}},
      {{"type", "grain"}, {"style", "headset"}, {"seed", 1}, {"keyframes", many_grain}},
      {{"type", "flare"},
       {"style", "headset"},
       {"light", "auto"},
       {"interpolation", tiny},
       {"keyframes", nlohmann::json::array()}},
      {{"type", "grain"},
       {"style", "headset"},
       {"seed", 1},
       {"interpolation", tiny},
       {"keyframes", nlohmann::json::array()}},
      exposure};
  std::vector<Problem> problems;
  (void)parse_sidecar(doc, "s", problems);
  const std::vector<std::string> expected = {
      "/effects/0/keyframes", "/effects/1/keyframes", "/effects/2/interpolation/time_scale",
      "/effects/3/interpolation/time_scale", "/effects/4/interpolation/time_scale"};
  ASSERT_EQ(problems.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(problems[i].pointer, expected[i]) << problems[i].message;
    EXPECT_NE(problems[i].message.find(i < 2 ? "100001 keyframes, more than the 100000"
                                             : "time_scale must be at least"),
              std::string::npos)
        << problems[i].message;
  }
}

}  // namespace
}  // namespace vdfx::io
