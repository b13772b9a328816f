/// @file
/// @brief The frame loop under Xvfb with a replayed input and a generated video: frame indices
/// from recorded times, late frames that never block, the unaltered key, the A/B switch, the
/// screenshot.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "app/window/frame_loop.h"
#include "app/window/player.h"
#include "io/input_error.h"
#include "io/video_source.h"
#include "player_test_support.h"
#include "tests/support/test_paths.h"
#include "xr/input/input_backend.h"
#include "xr/render/compositor.h"
#include "xr/render/video_layer.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

FrameLoopOptions small_options() {
  FrameLoopOptions o;
  o.profile = xr::load_hmd_profile("generic90");
  o.eye_scale = 0.05;  // 72 x 80 eyes
  o.window_width = 160;
  o.window_height = 90;
  o.visible = false;
  o.keep_records = true;
  o.mirror = xr::MirrorMode::PreDistorted;  // these tests read the eye buffers
  return o;
}

std::unique_ptr<io::VideoSource> grey_video(std::int64_t frames, double grey,
                                            std::shared_ptr<test::DecodeGate> gate = nullptr) {
  return std::make_unique<io::VideoSource>(
      std::make_unique<test::FakeDecoder>(frames, 64, 32, grey, std::move(gate)),
      io::VideoSourceOptions{});
}

std::unique_ptr<xr::InputBackend> replay(const std::vector<std::int64_t>& times, double az = 0) {
  return xr::create_replay_backend(test::still_head_recording(times, az), {});
}

std::vector<xr::DesktopEvent> key(xr::Key k, bool pressed) {
  return {xr::KeyEvent{k, pressed}};
}

// Mean of a column band of eye 0's buffer (BGRA float), middle rows, green channel.
double band_mean(const cv::Mat& eye, double x0, double x1) {
  const int c0 = static_cast<int>(x0 * eye.cols), c1 = static_cast<int>(x1 * eye.cols);
  const cv::Mat band = eye(cv::Range(eye.rows / 3, 2 * eye.rows / 3), cv::Range(c0, c1));
  return cv::mean(band)[1];
}

TEST(FrameLoopGl, FrameIndicesComeExactlyFromRecordedTimes) {
  // 90 Hz with a little jitter, starting far from 0: frame k shows frame_at_time(t_k - t_0).
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 200; ++k)
    times.push_back(5'000'000'000 + k * 11'111'111 + (k % 3) * 777);
  auto video = grey_video(1000, 0.5);
  auto input = replay(times);
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {1.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  o.decode_timeout = std::chrono::seconds(5);  // the fake decoder is fast: nothing is late
  FrameLoop loop(o, *input, *video, player);
  const FrameLoopResult r = loop.run();
  ASSERT_EQ(r.frames, 200);  // stops at the recording's end
  ASSERT_EQ(r.records.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(r.records[k].display_time_ns, times[k]);
    EXPECT_EQ(r.records[k].requested_frame, io::frame_at_time(times[k] - times[0], {30, 1})) << k;
    EXPECT_EQ(r.records[k].shown_frame, r.records[k].requested_frame) << k;
  }
  EXPECT_EQ(r.records.back().requested_frame, 66);  // 199 * 11.111 ms at 30 fps
  EXPECT_EQ(r.late_frames, 0);
}

TEST(FrameLoopGl, LateFramesAreCountedAndNeverBlockTheLoop) {
  // The decoder delivers frame 0 and then hangs until the test ends: a loop that waited for
  // the decoder would never finish.
  auto gate = std::make_shared<test::DecodeGate>();
  auto video = grey_video(100, 0.5, gate);
  struct Opener {
    std::shared_ptr<test::DecodeGate> g;
    ~Opener() { g->open(); }
  } opener{gate};
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 30; ++k) times.push_back(k * 33'333'334);
  auto input = replay(times);
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {1.0}}});
  Player player(sc, video->properties());
  FrameLoop loop(small_options(), *input, *video, player);
  const FrameLoopResult r = loop.run();
  ASSERT_EQ(r.frames, 30);
  EXPECT_GE(r.late_frames, 29);  // frames 1..29 never arrive; frame 0 may be late too
  for (const auto& rec : r.records) {
    EXPECT_LE(rec.shown_frame, 0);  // the previous frame (or none yet) stays on screen
    EXPECT_EQ(rec.late, rec.shown_frame != rec.requested_frame);
  }
}

TEST(FrameLoopGl, TheFirstFramesShowALoadingFieldUntilTheDecoderDelivers) {
  // The race of a slow first decode (a 4K long-GOP clip): the decoder is held until the loop
  // has drawn five frames. Those show the dark loading field (no failure), then the video.
  auto gate = std::make_shared<test::DecodeGate>();
  gate->from = 0;
  auto video = grey_video(100, 0.5, gate);
  struct Opener {
    std::shared_ptr<test::DecodeGate> g;
    ~Opener() { g->open(); }
  } opener{gate};
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 40; ++k) times.push_back(k * 33'333'334);
  auto input = replay(times);
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {0.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  std::vector<double> centre;  // the left eye's centre grey per loop frame
  o.on_frame = [&](xr::Compositor& c, std::int64_t n) {
    const cv::Mat eye = c.read_eye_buffer(0);
    centre.push_back(eye.at<cv::Vec4f>(eye.rows / 2, eye.cols / 2)[1]);
    if (n == 4) gate->open();
  };
  FrameLoop loop(o, *input, *video, player);
  const FrameLoopResult r = loop.run();
  ASSERT_EQ(r.frames, 40);
  for (int n = 0; n < 5; ++n) {
    EXPECT_EQ(r.records[static_cast<std::size_t>(n)].shown_frame, -1) << n;
    EXPECT_NEAR(centre[static_cast<std::size_t>(n)], xr::VideoLayerGl::kNoFrameGrey, 1e-3) << n;
  }
  EXPECT_GE(r.records.back().shown_frame, 0);
  EXPECT_NEAR(centre.back(), 0.5, 0.01) << "the video once decoded";
}

TEST(FrameLoopGl, AVideoThatNeverDeliversIsAnInputErrorAfterTheStartTimeout) {
  auto gate = std::make_shared<test::DecodeGate>();
  gate->from = 0;
  auto video = grey_video(100, 0.5, gate);
  struct Opener {
    std::shared_ptr<test::DecodeGate> g;
    ~Opener() { g->open(); }
  } opener{gate};
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 1000; ++k) times.push_back(k * 33'333'334);
  auto input = replay(times);
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {0.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  o.start_timeout = std::chrono::milliseconds(300);
  FrameLoop loop(o, *input, *video, player);
  try {
    loop.run();
    FAIL() << "expected an input error";
  } catch (const io::InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("generated: cannot show the video: no frame was decoded within"),
        std::string::npos)
        << e.what();
  }
}

TEST(FrameLoopGl, UnalteredKeyShowsThePlainVideoLayer) {
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 6; ++k) times.push_back(k * 33'333'333);
  auto video = grey_video(10, 0.25);
  auto input = replay(times);
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {2.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  o.decode_timeout = std::chrono::seconds(5);
  o.script = [](std::int64_t n) {
    if (n == 2) return key(xr::Key::U, true);
    if (n == 4) return key(xr::Key::U, false);
    return std::vector<xr::DesktopEvent>{};
  };
  std::vector<double> centre;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) {
    const cv::Mat eye = c.read_eye_buffer(0);
    centre.push_back(band_mean(eye, 0.4, 0.6));
  };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  ASSERT_EQ(centre.size(), 6u);
  const double plain = 64.0 / 255.0;  // the 8-bit grey of 0.25
  for (int n = 0; n < 6; ++n) {
    const bool unaltered = n == 2 || n == 3;
    EXPECT_NEAR(centre[n], unaltered ? plain : 4.0 * plain, 2e-3) << "frame " << n;
  }
}

TEST(FrameLoopGl, ABSwitchBakesAPerPixelGradient) {
  std::vector<std::int64_t> times;
  for (std::int64_t k = 0; k < 4; ++k) times.push_back(k * 33'333'333);
  auto video = grey_video(10, 0.25);
  auto input = replay(times);  // looking at azimuth 0
  // -1 stop on the left, +1 on the right: view-dependent mode at azimuth 0 gets 0 everywhere.
  const auto sc =
      test::one_effect_sidecar(EffectType::Exposure, {{-60, 0, {-1.0}}, {60, 0, {1.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  o.decode_timeout = std::chrono::seconds(5);
  o.script = [](std::int64_t n) {
    return n == 2 ? key(xr::Key::V, true) : std::vector<xr::DesktopEvent>{};
  };
  std::vector<std::array<double, 3>> bands;
  o.on_frame = [&](xr::Compositor& c, std::int64_t) {
    const cv::Mat eye = c.read_eye_buffer(0);
    bands.push_back(
        {band_mean(eye, 0.05, 0.2), band_mean(eye, 0.45, 0.55), band_mean(eye, 0.8, 0.95)});
  };
  FrameLoop loop(o, *input, *video, player);
  loop.run();
  ASSERT_EQ(bands.size(), 4u);
  const double plain = 64.0 / 255.0;
  for (int n : {0, 1}) {  // view-dependent: one parameter set, no gradient
    EXPECT_NEAR(bands[n][0], bands[n][2], 2e-3) << n;
    EXPECT_NEAR(bands[n][1], plain, 0.02) << n;
  }
  for (int n : {2, 3}) {  // per-pixel: darker left, brighter right, increasing across
    EXPECT_LT(bands[n][0], plain * 0.8) << n;
    EXPECT_GT(bands[n][2], plain * 1.2) << n;
    EXPECT_LT(bands[n][0], bands[n][1]) << n;
    EXPECT_LT(bands[n][1], bands[n][2]) << n;
  }
}

TEST(FrameLoopGl, ScreenshotOfTheMirrorIsWritten) {
  const std::filesystem::path out =
      std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "frame_loop_mirror.png";
  std::filesystem::create_directories(out.parent_path());
  std::filesystem::remove(out);
  auto video = grey_video(10, 0.5);
  auto input = replay({0, 33'333'333, 66'666'666});
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {0.0}}});
  Player player(sc, video->properties());
  FrameLoopOptions o = small_options();
  o.decode_timeout = std::chrono::seconds(5);
  o.screenshot = out;
  o.mirror = xr::MirrorMode::SingleEye;  // the grey fills the eye's rectangle
  FrameLoop loop(o, *input, *video, player);
  EXPECT_EQ(loop.run().frames, 3);
  const cv::Mat png = cv::imread(out.string());
  ASSERT_FALSE(png.empty()) << out;
  EXPECT_EQ(png.cols, 160);
  EXPECT_EQ(png.rows, 90);
  EXPECT_NEAR(png.at<cv::Vec3b>(45, 80)[1], 128, 2);  // the grey, unchanged (0 stops)
}

}  // namespace
}  // namespace vdfx::app
