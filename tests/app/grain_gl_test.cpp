/// @file
/// @brief Grain on the GPU through the app: `vdfx render --gpu` against the CPU path for the
/// shader styles and the volumetric styles drawn, and `vdfx play`'s frame loop drawing the
/// player's grain into both eyes with the pattern changing on the 20 ms refresh boundaries of
/// 90 Hz display times and nowhere else (gone while the unaltered key is held). Needs a display
/// (Xvfb in CI); never skips.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <sstream>

#include "app/window/frame_loop.h"
#include "app/window/player.h"
#include "command_test_util.h"
#include "io/video_source.h"
#include "player_test_support.h"
#include "xr/input/input_backend.h"
#include "xr/render/compositor.h"

namespace vdfx::app::testing {
namespace {

std::string grain_entry(const std::string& style, double intensity,
                        const std::string& settings = "{}", double size = 1.0) {
  std::ostringstream s;
  s << R"(,
    {"type": "grain", "style": ")"
    << style << R"(", "seed": 11, "settings": )" << settings << R"(,
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"intensity": )"
    << intensity << R"(, "size": )" << size << "}}]}";
  return s.str();
}

TEST(GrainGpu, RenderGpuMatchesTheCpuPathForTheShaderStyles) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  for (const char* style : {"surface", "headset"}) {
    // Eyes at a sixth of generic90's size: size 4 keeps the grain resolved (16 mrad cells).
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 0.7, "{}", 4.0)));
    for (const std::string eye : {"left", "right"}) {
      const std::string common = "--view 4,2 --hmd generic90 --size 240x266 --eye " + eye + " ";
      const cv::Mat cpu = render(dir, common, "cpu.png");
      const cv::Mat gpu = render(dir, common + "--gpu", "gpu.png");
      ASSERT_EQ(cpu.size(), gpu.size());
      const double err = max_abs_diff(cpu, gpu);
      std::cout << style << " " << eye << ": render --gpu vs CPU max " << err << "/255\n";
      EXPECT_LE(err, 2.0) << style << " " << eye;
    }
  }
}

TEST(GrainGpu, RenderGpuDrawsTheVolumetricStyles) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  const std::string common = "--view 4,2 --hmd generic90 --size 240x266 --gpu ";
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const cv::Mat plain = render(dir, common, "plain.png");
  for (const auto& [style, settings] :
       {std::pair{"object_cloud", R"({"sphere_m": 2.0, "count": 50000})"},
        std::pair{"free_cloud", R"({"count": 50000})"}}) {
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 1.0, settings)));
    const cv::Mat on = render(dir, common, "on.png");
    cv::Mat d;
    cv::absdiff(on, plain, d);
    const double changed = cv::countNonZero(d.reshape(1) > 2) / static_cast<double>(d.total() * 3);
    std::cout << style << ": " << changed * 100
              << " % of the channels changed by more than 2/255\n";
    EXPECT_GT(changed, 0.005) << style;
    EXPECT_EQ(max_abs_diff(on, render(dir, common, "again.png")), 0.0) << style;  // reproducible
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 0.0, settings)));
    EXPECT_EQ(max_abs_diff(plain, render(dir, common, "off.png")), 0.0) << style;
  }
}

TEST(GrainGpu, PlayChangesTheGrainOnRefreshBoundariesOnlyAndNotWhileUnaltered) {
  // 90 Hz display times (the session's period) from a start that is no multiple of 20 ms.
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 12; ++k) times.push_back(7'000'000 + k * 11'111'111);
  auto video = std::make_unique<io::VideoSource>(
      std::make_unique<test::FakeDecoder>(10, 64, 32, 0.5, nullptr), io::VideoSourceOptions{});
  auto input = xr::create_replay_backend(test::still_head_recording(times), {});
  io::Sidecar sc = test::one_effect_sidecar(effects::EffectType::Exposure, {{0, 0, {0.0}}});
  effects::GrainEffect g;
  g.style = effects::GrainStyle::Surface;
  g.keyframes.push_back({{0.0, 0.0}, 0, {1.0, 4.0}});  // 16 mrad cells: 5 px at half size
  sc.grains.push_back(g);
  Player player(sc, video->properties());
  FrameLoopOptions o = test::small_hidden_loop();
  o.eye_scale = 0.5;  // grain finer than the pixels would be band-limited away
  o.script = [](std::int64_t n) {
    return n == 10 ? std::vector<xr::DesktopEvent>{xr::KeyEvent{xr::Key::U, true}}
                   : std::vector<xr::DesktopEvent>{};
  };
  std::vector<std::array<cv::Mat, 2>> eyes;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) {
    std::array<cv::Mat, 2> e;
    for (int k = 0; k < 2; ++k)
      cv::cvtColor(c.read_eye_buffer(k), e[static_cast<std::size_t>(k)], cv::COLOR_BGRA2BGR);
    eyes.push_back(e);
  };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  ASSERT_EQ(eyes.size(), times.size());
  // The fake decoder's grey, as the 8-bit frame holds it.
  const double level = 128.0 / 255.0;
  const cv::Mat grey(eyes[0][0].size(), CV_32FC3, cv::Scalar(level, level, level));
  for (std::size_t n = 0; n < times.size(); ++n) {
    for (int e = 0; e < 2; ++e) {
      const double from_grey = max_abs_diff(eyes[n][static_cast<std::size_t>(e)], grey);
      if (n >= 10)
        EXPECT_LT(from_grey, 1e-3) << "unaltered frame " << n;
      else
        EXPECT_GT(from_grey, 0.05) << "frame " << n << " eye " << e;
    }
    if (n == 0 || n >= 10) continue;
    const bool boundary = times[n] / 20'000'000 != times[n - 1] / 20'000'000;
    const double change = max_abs_diff(eyes[n][0], eyes[n - 1][0]);
    if (boundary)
      EXPECT_GT(change, 0.05) << "frame " << n << " starts a refresh";
    else
      EXPECT_EQ(change, 0.0) << "frame " << n << " is in the same refresh";
  }
}

}  // namespace
}  // namespace vdfx::app::testing
