/// @file
/// @brief `vdfx render` on stereo and VR180 video (docs/stereo.md): synthetic frames whose eyes
/// differ, in each layout, tagged (MP4 through vdfx's own encoder, Matroska stereo_mode through
/// the ffmpeg command line) and untagged with --layout. Each eye's render is compared with an
/// independent pinhole of its own half (written here, not vdfx's sampler) within 2/255; VR180 is
/// black outside its half turn; a 4-degree blur never reads the other eye; bad input exits 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "command_test_util.h"
#include "io/eye_picture.h"
#include "io/frame_decoder.h"
#include "tests/media_clips.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

constexpr double kPi = 3.14159265358979323846;
constexpr int kEyeW = 256, kEyeH = 128;  //!< one eye's 360 image
constexpr int kOutW = 64, kOutH = 48;

/// Eye `e`'s own smooth pattern (RGB 8-bit): the eyes differ everywhere, by tens of codes.
cv::Mat eye_pattern(int e, int w, int h) {
  cv::Mat m(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w, v = (y + 0.5) / h;
      const double a = std::sin(2 * kPi * u), b = std::cos(kPi * v);
      m.at<cv::Vec3b>(y, x) = e == 0 ? cv::Vec3b(cv::saturate_cast<uchar>(170 + 60 * a), 40,
                                                 cv::saturate_cast<uchar>(90 + 50 * b))
                                     : cv::Vec3b(40, cv::saturate_cast<uchar>(150 + 70 * b),
                                                 cv::saturate_cast<uchar>(160 + 60 * a));
    }
  return m;
}

/// A stereo frame (RGB) of `layout` from two eye images.
cv::Mat compose(const std::string& layout, const cv::Mat& left, const cv::Mat& right) {
  cv::Mat out;
  if (layout == "top-bottom") cv::vconcat(left, right, out);
  if (layout == "left-right") cv::hconcat(left, right, out);
  if (layout == "right-left") cv::hconcat(right, left, out);
  return out;
}

/// The eye's half of a decoded frame (RGB 8-bit).
cv::Mat half_of(const cv::Mat& frame, const std::string& layout, int eye) {
  const int w = frame.cols, h = frame.rows;
  if (layout == "top-bottom") return frame(cv::Rect(0, eye * h / 2, w, h / 2)).clone();
  const bool left_first = layout == "left-right";
  const int col = (eye == 0) == left_first ? 0 : w / 2;
  return frame(cv::Rect(col, 0, w / 2, h)).clone();
}

/// The reference: a pinhole looking at (az, alt), horizontal fov, square pixels, each pixel's
/// ray through its centre, bilinear in the eye's image (columns wrap for 360, clamp for 180;
/// rows clamp), black outside a 180 image's half turn (beyond the 2-degree fade). RGB 8-bit.
cv::Mat pinhole(const cv::Mat& img, double az_deg, double alt_deg, double hfov_deg, int coverage) {
  const double az = az_deg * kPi / 180, alt = alt_deg * kPi / 180;
  const cv::Vec3d f(std::cos(alt) * std::sin(az), std::sin(alt), -std::cos(alt) * std::cos(az));
  const cv::Vec3d right(std::cos(az), 0, std::sin(az));
  const cv::Vec3d up(-std::sin(alt) * std::sin(az), std::cos(alt), std::sin(alt) * std::cos(az));
  const double tx = std::tan(hfov_deg * kPi / 360), ty = tx * kOutH / kOutW;
  cv::Mat out(kOutH, kOutW, CV_8UC3);
  for (int j = 0; j < kOutH; ++j)
    for (int i = 0; i < kOutW; ++i) {
      const cv::Vec3d d =
          f + (2.0 * (i + 0.5) / kOutW - 1) * tx * right - (2.0 * (j + 0.5) / kOutH - 1) * ty * up;
      const double ray_az = std::atan2(d[0], -d[2]) * 180 / kPi;
      const double ray_alt = std::atan2(d[1], std::hypot(d[0], d[2])) * 180 / kPi;
      const double u = 0.5 + ray_az / coverage, v = 0.5 - ray_alt / 180;
      const double x = u * img.cols - 0.5, y = std::clamp(v * img.rows - 0.5, 0.0, img.rows - 1.0);
      const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
      const double fx = x - x0, fy = y - y0;
      const auto col = [&](int c) {
        return coverage == 360 ? (c % img.cols + img.cols) % img.cols
                               : std::clamp(c, 0, img.cols - 1);
      };
      const int y1 = std::min(y0 + 1, img.rows - 1);
      const double weight =
          coverage == 360 ? 1.0 : std::clamp((90.0 - std::abs(ray_az)) / 2.0, 0.0, 1.0);
      for (int c = 0; c < 3; ++c) {
        const auto at = [&](int yy, int xx) { return img.at<cv::Vec3b>(yy, col(xx))[c]; };
        const double top = (1 - fx) * at(y0, x0) + fx * at(y0, x0 + 1);
        const double bottom = (1 - fx) * at(y1, x0) + fx * at(y1, x0 + 1);
        out.at<cv::Vec3b>(j, i)[c] =
            cv::saturate_cast<uchar>(weight * ((1 - fy) * top + fy * bottom));
      }
    }
  return out;
}

std::string sidecar_json(int width, int height, const std::string& effects = "",
                         const std::string& video_extra = "") {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "clip", "fps": 24.0, "frames": 2, "width": )" +
         std::to_string(width) + R"(, "height": )" + std::to_string(height) + video_extra +
         R"(},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": [)" +
         effects + "]}";
}

/// `vdfx render INPUT --sidecar S --view AZ,ALT --fov 60 --size 64x48 ARGS`: RGB 8-bit.
cv::Mat render_eye(const fs::path& dir, const fs::path& input, const fs::path& sidecar,
                   const std::string& view, const std::string& args) {
  static int n = 0;
  const fs::path out = dir / ("r" + std::to_string(n++) + ".png");
  const testing::CommandResult r =
      run_vdfx("render " + input.string() + " --sidecar " + sidecar.string() + " --view " + view +
               " --fov 60 --size " + std::to_string(kOutW) + "x" + std::to_string(kOutH) + " " +
               args + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  cv::Mat bgr = cv::imread(out.string(), cv::IMREAD_COLOR), rgb;
  if (bgr.empty()) return cv::Mat(kOutH, kOutW, CV_8UC3, cv::Scalar::all(0));
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return rgb;
}

double max_diff(const cv::Mat& a, const cv::Mat& b) {
  return testing::max_abs_diff(a, b);
}

/// The decoded frame 0 of `path` (RGB 8-bit), as vdfx decodes it: each eye's image converted
/// from its own planes (io::to_rgb_by_eye), so no eye's chroma is interpolated with the other's.
cv::Mat decoded(const fs::path& path, const std::string& layout, int coverage) {
  auto d = io::open_frame_decoder(path);
  io::Picture picture;
  EXPECT_EQ(d->read_picture(picture), io::DecodeStatus::Ok);
  const effects::StereoLayout l{*effects::stereo_mode_from_name(layout), coverage};
  return io::to_rgb_by_eye(picture, l, io::PixelFormat::Rgb8);
}

/// Each eye of `input` (shown with `args`) against the pinhole of its own half, at views that
/// cross the seam and look near a pole.
void expect_eyes_match(const fs::path& dir, const fs::path& input, const std::string& layout,
                       const std::string& args, int coverage = 360) {
  const cv::Mat frame = decoded(input, layout, coverage);
  const fs::path sidecar = dir / "empty.vdfx.json";
  write_text(sidecar, sidecar_json(frame.cols, frame.rows));
  for (int eye = 0; eye < 2; ++eye) {
    const cv::Mat half = half_of(frame, layout, eye);
    const cv::Mat other = half_of(frame, layout, 1 - eye);
    for (const auto& [az, alt] : {std::pair{0.0, 0.0}, {170.0, 20.0}, {-60.0, -15.0}}) {
      if (coverage == 180 && std::abs(az) > 60) continue;
      SCOPED_TRACE(layout + " eye " + std::to_string(eye) + " at " + std::to_string(az));
      const std::string view = std::to_string(az) + "," + std::to_string(alt);
      const cv::Mat got =
          render_eye(dir, input, sidecar, view, args + (eye == 0 ? " --eye left" : " --eye right"));
      const cv::Mat want = pinhole(half, az, alt, 60, coverage);
      EXPECT_LE(max_diff(got, want), 2.0);
      EXPECT_GT(max_diff(got, pinhole(other, az, alt, 60, coverage)), 40.0);  // not the other eye
    }
  }
}

TEST(StereoRender, UntaggedStillInEachLayoutWithLayoutOption) {
  const fs::path dir = test_dir();
  const cv::Mat left = eye_pattern(0, kEyeW, kEyeH), right = eye_pattern(1, kEyeW, kEyeH);
  for (const std::string layout : {"top-bottom", "left-right", "right-left"}) {
    cv::Mat bgr;
    cv::cvtColor(compose(layout, left, right), bgr, cv::COLOR_RGB2BGR);
    const fs::path png = dir / (layout + ".png");
    ASSERT_TRUE(cv::imwrite(png.string(), bgr));
    expect_eyes_match(dir, png, layout, "--layout " + layout);
  }
}

test_media::ClipSpec stereo_clip(const std::string& layout, const cv::Mat& left,
                                 const cv::Mat& right) {
  test_media::ClipSpec c;
  const cv::Mat frame = compose(layout, left, right);
  c.width = frame.cols;
  c.height = frame.rows;
  c.frames = 2;
  c.frame = [frame](int) { return frame; };
  return c;
}

TEST(StereoRender, TaggedMp4WrittenByVdfx) {
  const fs::path dir = test_dir();
  const cv::Mat left = eye_pattern(0, kEyeW, kEyeH), right = eye_pattern(1, kEyeW, kEyeH);
  for (const auto& [layout, mode] :
       {std::pair{std::string("top-bottom"), effects::StereoMode::TopBottom},
        {std::string("left-right"), effects::StereoMode::LeftRight}}) {
    test_media::ClipSpec c = stereo_clip(layout, left, right);
    c.spherical = true;
    c.stereo = {mode, 360};
    const fs::path mp4 = test_media::write_clip(dir / (layout + ".mp4"), c);
    expect_eyes_match(dir, mp4, layout, "");
  }
}

TEST(StereoRender, MatroskaStereoModeFromFfmpeg) {
  const fs::path dir = test_dir();
  const cv::Mat left = eye_pattern(0, kEyeW, kEyeH), right = eye_pattern(1, kEyeW, kEyeH);
  const fs::path plain =
      test_media::write_clip(dir / "plain.mkv", stereo_clip("top-bottom", left, right));
  const fs::path mkv = dir / "tb.mkv";
  const std::string cmd = "ffmpeg -v error -y -i " + plain.string() +
                          " -c copy -metadata:s:v stereo_mode=top_bottom " + mkv.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  expect_eyes_match(dir, mkv, "top-bottom", "");
}

TEST(StereoRender, Vr180TaggedHonoursItsBounds) {
  const fs::path dir = test_dir();
  // Side by side, each eye 180 x 180 degrees in a square image.
  const cv::Mat left = eye_pattern(0, kEyeH, kEyeH), right = eye_pattern(1, kEyeH, kEyeH);
  test_media::ClipSpec c = stereo_clip("left-right", left, right);
  c.spherical = true;
  c.stereo = {effects::StereoMode::LeftRight, 180};
  const fs::path mp4 = test_media::write_clip(dir / "vr180.mp4", c);
  expect_eyes_match(dir, mp4, "left-right", "", 180);
  // Behind the viewer: black. Looking at the edge: the covered side shows, the other is black.
  const fs::path sidecar = dir / "empty.vdfx.json";
  const cv::Mat back = render_eye(dir, mp4, sidecar, "180,0", "--eye right");
  EXPECT_EQ(cv::countNonZero(back.reshape(1)), 0);
  const cv::Mat edge = render_eye(dir, mp4, sidecar, "90,0", "--eye left");
  EXPECT_GT(cv::mean(edge.colRange(0, kOutW / 4))[0], 50.0);
  EXPECT_EQ(cv::countNonZero(edge.colRange(kOutW / 2 + 2, kOutW).reshape(1)), 0);
  // The same untagged with --layout --coverage.
  const fs::path plain =
      test_media::write_clip(dir / "plain180.mp4", stereo_clip("left-right", left, right));
  expect_eyes_match(dir, plain, "left-right", "--layout left-right --coverage 180", 180);
}

TEST(StereoRender, AFourDegreeBlurNeverReadsTheOtherEye) {
  const fs::path dir = test_dir();
  // Left eye pure red, right eye pure blue: any bleed shows in the other channel.
  const cv::Mat red(kEyeH, kEyeW, CV_8UC3, cv::Scalar(255, 0, 0));
  const cv::Mat blue(kEyeH, kEyeW, CV_8UC3, cv::Scalar(0, 0, 255));
  const fs::path sidecar = dir / "blur.vdfx.json";
  const std::string blur =
      R"({"type": "blur", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
      "params": {"sigma_deg": 4.0}}]})";
  for (const std::string layout : {"top-bottom", "left-right", "right-left"}) {
    SCOPED_TRACE(layout);
    cv::Mat bgr;
    cv::cvtColor(compose(layout, red, blue), bgr, cv::COLOR_RGB2BGR);
    const fs::path png = dir / (layout + ".png");
    ASSERT_TRUE(cv::imwrite(png.string(), bgr));
    write_text(sidecar, sidecar_json(bgr.cols, bgr.rows, blur));
    // Where the halves meet: the pole (top-bottom) or the seam behind (side by side).
    for (const std::string view : {"180,0", "0,-85", "0,85", "179,-80"}) {
      for (const std::string mode : {"view", "pixel"}) {
        const cv::Mat l = render_eye(dir, png, sidecar, view,
                                     "--layout " + layout + " --eye left --mode " + mode);
        const cv::Mat r = render_eye(dir, png, sidecar, view,
                                     "--layout " + layout + " --eye right --mode " + mode);
        std::vector<cv::Mat> lc, rc;
        cv::split(l, lc);
        cv::split(r, rc);
        EXPECT_EQ(cv::countNonZero(lc[2]), 0) << view << " " << mode;  // no blue in the left eye
        EXPECT_EQ(cv::countNonZero(rc[0]), 0) << view << " " << mode;  // no red in the right eye
      }
    }
  }
}

TEST(StereoRender, BadInputNamesTheFileAndTheField) {
  const fs::path dir = test_dir();
  const cv::Mat left = eye_pattern(0, kEyeW, kEyeH), right = eye_pattern(1, kEyeW, kEyeH);
  // A video tagged mono (vdfx's own Spherical Video V2 export of a mono frame).
  test_media::ClipSpec c = stereo_clip("top-bottom", left, right);
  c.spherical = true;
  const fs::path mono = test_media::write_clip(dir / "mono.mp4", c);
  const fs::path stereo_sidecar = dir / "tb.vdfx.json";
  write_text(stereo_sidecar, sidecar_json(kEyeW, 2 * kEyeH, "", R"(, "layout": "top-bottom")"));
  const std::string tail = " --view 0,0 --fov 60 --size 16x16 --out " + (dir / "o.png").string();
  testing::CommandResult r =
      run_vdfx("render " + mono.string() + " --sidecar " + stereo_sidecar.string() + tail);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(
      r.output.find(stereo_sidecar.string() + ": /video/layout: the sidecar says top-bottom but " +
                    mono.string() + " is tagged mono"),
      std::string::npos)
      << r.output;
  // --layout overrides the tag.
  r = run_vdfx("render " + mono.string() + " --sidecar " + stereo_sidecar.string() +
               " --layout top-bottom --eye right" + tail);
  EXPECT_EQ(r.exit_code, 0) << r.output;

  // A layout that does not divide the frame.
  const cv::Mat odd(kEyeH * 2 + 1, kEyeW, CV_8UC3, cv::Scalar::all(90));
  const fs::path odd_png = dir / "odd.png";
  cv::imwrite(odd_png.string(), odd);
  const fs::path plain_sidecar = dir / "plain.vdfx.json";
  write_text(plain_sidecar, sidecar_json(kEyeW, 2 * kEyeH + 1));
  r = run_vdfx("render " + odd_png.string() + " --sidecar " + plain_sidecar.string() +
               " --layout top-bottom" + tail);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(odd_png.string() + ": --layout: top-bottom needs an even frame height"),
            std::string::npos)
      << r.output;

  // A sidecar whose coverage covers nothing.
  const fs::path none = dir / "none.vdfx.json";
  write_text(none, sidecar_json(kEyeW, 2 * kEyeH, "", R"(, "coverage": 0)"));
  r = run_vdfx("render " + mono.string() + " --sidecar " + none.string() + tail);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(none.string() + ": /video/coverage: coverage 0 covers nothing"),
            std::string::npos)
      << r.output;

  // Usage: an unknown layout, --eye on mono without --hmd.
  r = run_vdfx("render " + odd_png.string() + " --sidecar " + plain_sidecar.string() +
               " --layout sbs" + tail);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_vdfx("render " + odd_png.string() + " --sidecar " + plain_sidecar.string() +
               " --eye right" + tail);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--eye: needs --hmd or a stereo video"), std::string::npos) << r.output;
}

TEST(StereoRender, AnUntaggedSquareFrameHintsAtLayout) {
  const fs::path dir = test_dir();
  const cv::Mat sq(kEyeW, kEyeW, CV_8UC3, cv::Scalar::all(90));
  const fs::path png = dir / "square.png";
  cv::imwrite(png.string(), sq);
  const fs::path sidecar = dir / "s.vdfx.json";
  write_text(sidecar, sidecar_json(kEyeW, kEyeW));
  const testing::CommandResult r =
      run_vdfx("render " + png.string() + " --sidecar " + sidecar.string() +
               " --view 0,0 --fov 60 --size 16x16 --out " + (dir / "o.png").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("hint: " + png.string() + ": the frame is 256x256"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--layout"), std::string::npos);
}

}  // namespace
}  // namespace vdfx::app
