/// @file
/// @brief Flares on the GPU through the app: `vdfx render --gpu` against the CPU path per style,
/// and `vdfx play`'s frame loop drawing the player's flares into both eyes (gone while the
/// unaltered key is held). Needs a display (Xvfb in CI); never skips.
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

std::string flare_entry(const std::string& style, const std::string& light, double intensity) {
  std::ostringstream s;
  s << R"(,
    {"type": "flare", "style": ")"
    << style << R"(", "light": )" << light << R"(,
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"intensity": )"
    << intensity << "}}]}";
  return s.str();
}

TEST(FlareGpu, RenderGpuMatchesTheCpuPathPerStyle) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  for (const char* style : {"directional", "headset"}) {
    write_text(
        dir / "s.vdfx.json",
        exposure_sidecar(flare_entry(style, R"({"azimuth_deg": 12.0, "altitude_deg": 8.0})", 0.6)));
    for (const std::string eye : {"left", "right"}) {
      const std::string common = "--view 4,2 --hmd generic90 --size 240x266 --eye " + eye + " ";
      const cv::Mat cpu = render(dir, common, "cpu.png");
      const cv::Mat gpu = render(dir, common + "--gpu", "gpu.png");
      ASSERT_EQ(cpu.size(), gpu.size());
      cv::Mat d;
      cv::absdiff(cpu, gpu, d);
      double err = 0;
      cv::minMaxLoc(d.reshape(1), nullptr, &err);
      std::cout << style << " " << eye << ": render --gpu vs CPU max " << err << "/255\n";
      EXPECT_LE(err, 2.0) << style << " " << eye;
    }
  }
}

/// The brightest value of a view, without alpha (always 1).
double peak_of(const cv::Mat& bgra) {
  cv::Mat bgr;
  cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  double p = 0.0;
  cv::minMaxLoc(bgr.reshape(1), nullptr, &p);
  return p;
}

TEST(FlareGpu, PlayDrawsThePlayersFlaresIntoBothEyesUnlessUnaltered) {
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 4; ++k) times.push_back(k * 33'333'333);
  auto video = std::make_unique<io::VideoSource>(
      std::make_unique<test::FakeDecoder>(10, 64, 32, 0.25, nullptr), io::VideoSourceOptions{});
  auto input = xr::create_replay_backend(test::still_head_recording(times), {});
  io::Sidecar sc = test::one_effect_sidecar(effects::EffectType::Exposure, {{0, 0, {0.0}}});
  effects::FlareEffect flare;
  flare.style = effects::FlareStyle::Directional;
  flare.light = effects::Direction{6.0, 4.0};
  flare.keyframes.push_back({{0.0, 0.0}, 0, {1.0}});
  sc.flares.push_back(flare);
  Player player(sc, video->properties());
  FrameLoopOptions o = test::small_hidden_loop();
  o.script = [](std::int64_t n) {
    return n == 2 ? std::vector<xr::DesktopEvent>{xr::KeyEvent{xr::Key::U, true}}
                  : std::vector<xr::DesktopEvent>{};
  };
  std::vector<std::array<double, 2>> peaks;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) {
    std::array<double, 2> p{};
    for (int e = 0; e < 2; ++e) p[static_cast<std::size_t>(e)] = peak_of(c.read_eye_buffer(e));
    peaks.push_back(p);
  };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  ASSERT_EQ(peaks.size(), 4u);
  const double grey = 64.0 / 255.0;
  for (int n = 0; n < 4; ++n) {
    for (int e = 0; e < 2; ++e) {
      if (n >= 2)
        EXPECT_NEAR(peaks[n][e], grey, 1e-3) << "unaltered frame " << n;
      else
        EXPECT_GT(peaks[n][e], grey + 0.5) << "frame " << n << " eye " << e;
    }
  }
}

TEST(FlareGpu, TheDesktopViewDrawsTheFlareFromTheHead) {
  std::vector<std::int64_t> times{0, 33'333'333};
  auto video = std::make_unique<io::VideoSource>(
      std::make_unique<test::FakeDecoder>(10, 64, 32, 0.25, nullptr), io::VideoSourceOptions{});
  auto input = xr::create_replay_backend(test::still_head_recording(times), {});
  io::Sidecar sc = test::one_effect_sidecar(effects::EffectType::Exposure, {{0, 0, {0.0}}});
  effects::FlareEffect flare;
  flare.style = effects::FlareStyle::Directional;
  flare.light = effects::Direction{6.0, 4.0};
  flare.keyframes.push_back({{0.0, 0.0}, 0, {1.0}});
  sc.flares.push_back(flare);
  Player player(sc, video->properties());
  FrameLoopOptions o;
  o.profile = xr::load_hmd_profile("generic90");
  o.window_width = 320;
  o.window_height = 180;
  o.visible = false;
  o.mirror = xr::MirrorMode::Desktop;
  o.decode_timeout = std::chrono::seconds(5);
  double peak = 0.0;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) { peak = peak_of(c.read_desktop()); };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  EXPECT_GT(peak, 64.0 / 255.0 + 0.5) << "the glare over the grey video";
}

}  // namespace
}  // namespace vdfx::app::testing
