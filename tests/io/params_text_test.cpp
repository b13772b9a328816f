/// @file
/// @brief The eval JSON written as text is byte for byte what nlohmann::json's dump() makes of
/// the same object: numbers of every kind, and the "effects" object of a stack.
#include "io/params_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>

#include "effects/stack_interpolator.h"
#include "io/sidecar.h"

namespace vdfx::io {
namespace {

std::string number(double v) {
  std::string s;
  append_json_number(s, v);
  return s;
}

TEST(ParamsText, NumbersAreWrittenAsNlohmannWritesThem) {
  std::vector<double> values = {0.0,    -0.0, 1.0,    -2.0,    0.1,     1e-7,     1.5e20,
                                1e15,   1e16, 1e-5,   123.456, -1e-300, 5e-324,   1.7e308,
                                0.0001, 1e-4, 2.5e-4, 1e21,    4.0,     1.0 / 3.0};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-4.0, 4.0), e(-30.0, 30.0);
  for (int i = 0; i < 2000; ++i) values.push_back(u(rng) * std::pow(10.0, e(rng)));
  for (const double v : values) EXPECT_EQ(number(v), nlohmann::json(v).dump()) << v;
  EXPECT_EQ(number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(number(std::numeric_limits<double>::infinity()), "null");
  std::string i;
  append_json_integer(i, -9007199254740993);
  EXPECT_EQ(i, nlohmann::json(std::int64_t{-9007199254740993}).dump());
}

TEST(ParamsText, TheEffectsObjectIsTheDumpOfTheSameJson) {
  std::vector<effects::EffectTrack> tracks(2);
  tracks[0].type = effects::EffectType::Exposure;
  tracks[0].keyframes = {{{10.0, 0.0}, 0, {1.25}}};
  tracks[1].type = effects::EffectType::Tint;
  tracks[1].keyframes = {{{10.0, 0.0}, 0, {1.2, 0.9, 1.0}}};
  const effects::StackInterpolator stack(tracks, {}, 30.0);
  const effects::StackParams params = stack.evaluate(effects::Direction{33.0, -4.0}, 0);
  nlohmann::ordered_json want = nlohmann::ordered_json::object();
  for (const effects::EffectSpec& spec : effects::all_effect_specs()) {
    nlohmann::ordered_json e = params_to_json(spec.type, params.get(spec.type));
    e["active"] = stack.active(spec.type);
    want[std::string(spec.name)] = std::move(e);
  }
  std::string got;
  append_stack_params_json(got, stack, params);
  EXPECT_EQ(got, want.dump());
  EXPECT_NE(got.find("\"exposure\":{\"stops\":1.25,\"active\":true}"), std::string::npos) << got;
}

}  // namespace
}  // namespace vdfx::io
