/// @file
/// @brief A sidecar of film scale (one effect with 100000 keyframes over 20 minutes at 30 fps,
/// interpolated locally in time) through vdfx validate, eval and render and through the editor
/// (opened, one keyframe placed and undone). Each test writes it (about 20 MB) into its own
/// folder.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "app/editor/editor.h"
#include "command_test_util.h"
#include "editor_test_util.h"
#include "io/sidecar.h"

namespace vdfx::app::testing {
namespace {

using effects::EffectType;
using effects::Keyframe;

constexpr std::int64_t kFrames = 20 * 60 * 30;
constexpr std::size_t kKeyframes = io::kMaxKeyframesPerEffect;

/// The sidecar: exposure keyframes at random directions and frames, stops in [-2, 2]; the first
/// at frame 0 (the panorama is a still: render uses frame 0).
const io::Sidecar& film() {
  static const io::Sidecar s = [] {
    io::Sidecar sc;
    sc.video = {"pano.png", 30.0, kFrames, 256, 128};
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> az(-179.0, 180.0), h(-0.99, 0.99), stops(-2.0, 2.0);
    std::uniform_int_distribution<std::int64_t> frame(0, kFrames - 1);
    effects::EffectTrack t;
    t.type = EffectType::Exposure;
    for (std::size_t i = 0; i < kKeyframes; ++i)
      t.keyframes.push_back({{az(rng), std::asin(h(rng)) * effects::kRadToDeg},
                             i == 0 ? 0 : frame(rng),
                             {stops(rng)}});
    sc.effects.push_back(std::move(t));
    return sc;
  }();
  return s;
}

/// pano.png and film.vdfx.json in the running test's own folder (ctest runs tests side by side),
/// written once per test.
const std::filesystem::path& film_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = test_dir();
    write_test_panorama(d);
    io::write_sidecar(d / "film.vdfx.json", film());
    return d;
  }();
  return dir;
}

std::string film_path() {
  return (film_dir() / "film.vdfx.json").string();
}

TEST(FilmScale, ValidateAcceptsItAndSaysHowItIsInterpolated) {
  const CommandResult r = run_vdfx("validate " + film_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("valid (1 effects, 100000 keyframes)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("exposure: 100000 keyframes interpolated locally in time: reach"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("(automatic)"), std::string::npos) << r.output;
}

TEST(FilmScale, EvalReproducesKeyframes) {
  const auto& k = film().effects[0].keyframes;
  std::string args = "eval " + film_path();
  const std::vector<std::size_t> picks = {0, 1, 777, 31337, 99999};
  for (const std::size_t i : picks) {
    std::ostringstream at;
    at.precision(17);
    at << " --at " << k[i].direction.azimuth_deg << "," << k[i].direction.altitude_deg << ","
       << k[i].frame;
    args += at.str();
  }
  const CommandResult r = run_vdfx(args);
  ASSERT_EQ(r.exit_code, 0) << r.output.substr(0, 2000);
  std::istringstream lines(r.output);
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    ASSERT_LT(n, picks.size()) << line;
    const double stops = nlohmann::json::parse(line)["effects"]["exposure"]["stops"].get<double>();
    EXPECT_NEAR(stops, k[picks[n]].params[0], 1e-9) << "keyframe " << picks[n];
    ++n;
  }
  EXPECT_EQ(n, picks.size());
}

TEST(FilmScale, RenderAppliesTheKeyframeLookedAt) {
  // View mode applies the view centre's parameters to the whole picture: at keyframe 0 that is
  // its value, the same picture as a sidecar of that one keyframe renders.
  const auto dir = film_dir();
  const Keyframe& k = film().effects[0].keyframes[0];
  io::Sidecar one = film();
  one.effects[0].keyframes = {k};
  io::write_sidecar(dir / "one.vdfx.json", one);
  std::ostringstream view;
  view.precision(17);
  view << k.direction.azimuth_deg << "," << k.direction.altitude_deg;
  const std::string common = " --view " + view.str() + " --frame 0 --fov 90 --size 96x64 --out ";
  const auto run = [&](const std::string& sidecar, const std::string& out) {
    const CommandResult r = run_vdfx("render " + (dir / "pano.png").string() + " --sidecar " +
                                     (dir / sidecar).string() + common + (dir / out).string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return cv::imread((dir / out).string(), cv::IMREAD_COLOR);
  };
  const cv::Mat many = run("film.vdfx.json", "many.png"), single = run("one.vdfx.json", "one.png");
  ASSERT_FALSE(many.empty());
  ASSERT_EQ(many.size(), cv::Size(96, 64));
  EXPECT_EQ(max_abs_diff(many, single), 0.0);
}

TEST(FilmScale, EditorOpensPlacesAKeyframeAndUndoesIt) {
  Editor ed(io::read_sidecar(film_path()), DocumentOptions{{.async = false}}, EditorOptions{});
  ASSERT_TRUE(ed.document().keyframe_set(EffectType::Exposure).local());
  const std::string before = io::format_sidecar(ed.document().sidecar());
  ed.set_chosen_params({1.5});
  ed.seek(18000);
  std::int64_t t = 0;
  xr::ActionSync sync;
  for (int step = 0; step < 3; ++step) {  // trigger held: the preview follows the view
    t += 33'333'333;
    auto in = test::looking(20.0 + 2.0 * step, 5.0, t);
    in.right.trigger = 1.0;
    ed.update(sync.sync(in), t);
    ASSERT_TRUE(ed.previewing());
  }
  t += 33'333'333;
  ed.update(sync.sync(test::looking(24.0, 5.0, t)), t);  // released: placed
  ASSERT_EQ(ed.document().keyframes(EffectType::Exposure).size(), kKeyframes + 1);
  const auto placed = ed.document().keyframe_set(EffectType::Exposure).solution();
  EXPECT_NEAR(
      placed->evaluate(ed.document().keyframes(EffectType::Exposure).back().direction, 18000)[0],
      1.5, 1e-9);
  const auto stats = ed.document().keyframe_set(EffectType::Exposure).stats();
  EXPECT_EQ(stats.local_edits, 1u);
  EXPECT_LE(stats.windows_solved, 8u);
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(ed.document().keyframes(EffectType::Exposure).size(), kKeyframes);
  EXPECT_EQ(io::format_sidecar(ed.document().sidecar()), before);
  const auto undone = ed.document().keyframe_set(EffectType::Exposure).solution();
  const auto& k = film().effects[0].keyframes;
  for (std::size_t i = 0; i < k.size(); i += 997)
    ASSERT_NEAR(undone->evaluate(k[i].direction, k[i].frame)[0], k[i].params[0], 1e-9) << i;
  // The undo kept the windows the placement had not touched.
  EXPECT_EQ(undone->windows()[0].get(), placed->windows()[0].get());
}

}  // namespace
}  // namespace vdfx::app::testing
