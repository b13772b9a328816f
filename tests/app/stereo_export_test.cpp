/// @file
/// @brief `vdfx export` of stereo and VR180 video (docs/stereo.md, docs/export.md): the baked
/// video keeps the source's layout, each half baked from its own eye alone (no blur across the
/// boundary), tagged (st3d, and for VR180 the equi bounds) as ffprobe and vdfx read back; a
/// VR180 blur stays inside each eye and clamps at the image's edge, matching an independent
/// gather; the viewer's path shows the eye --eye names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <string>

#include "command_test_util.h"
#include "export_test_util.h"
#include "io/eye_picture.h"
#include "io/frame_decoder.h"
#include "tests/media_clips.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::command_output;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

/// x264 lossless 4:4:4: the source's halves meet without chroma subsampling mixing them.
void lossless_444(test_media::ClipSpec& c) {
  c.ycbcr.log2_chroma_w = c.ycbcr.log2_chroma_h = 0;
  c.ycbcr.chroma_x = c.ycbcr.chroma_y = 0.0;
  c.options = {{"qp", "0"}};
}

/// A mono clip of one eye, encoded as stereo_clip encodes.
fs::path mono_clip(const fs::path& path, const cv::Mat& eye) {
  test_media::ClipSpec c;
  c.width = eye.cols;
  c.height = eye.rows;
  c.frames = 3;
  c.frame = [eye](int) { return eye; };
  lossless_444(c);
  return test_media::write_clip(path, c);
}

/// A clip of two eyes side by side or stacked: the left eye `l`, the right eye `r` (RGB 8-bit).
fs::path stereo_clip(const fs::path& path, const std::string& layout, const cv::Mat& l,
                     const cv::Mat& r, bool tagged, int coverage = 360) {
  cv::Mat frame;
  if (layout == "top-bottom") cv::vconcat(l, r, frame);
  if (layout == "left-right") cv::hconcat(l, r, frame);
  test_media::ClipSpec c;
  c.width = frame.cols;
  c.height = frame.rows;
  c.frames = 3;
  c.frame = [frame](int) { return frame; };
  lossless_444(c);
  c.spherical = tagged;
  c.stereo = {
      layout == "top-bottom" ? effects::StereoMode::TopBottom : effects::StereoMode::LeftRight,
      coverage};
  return test_media::write_clip(path, c);
}

std::string sidecar_json(int w, int h, const std::string& effects) {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "c.mp4", "fps": 24.0, "frames": 3, "width": )" +
         std::to_string(w) + R"(, "height": )" + std::to_string(h) + R"(},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": [)" +
         effects + "]}";
}

const char* kBlur4 =
    R"({"type": "blur", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
    "params": {"sigma_deg": 4.0}}]})";
const char* kExposure =
    R"({"type": "exposure", "keyframes": [
      {"azimuth_deg": 60.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": 1.0}},
      {"azimuth_deg": -60.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": -1.0}}]})";

TEST(StereoExport, BakedTopBottomKeepsItsLayoutAndNeverBlursAcrossTheHalves) {
  const fs::path dir = test_dir();
  const cv::Mat red(64, 128, CV_8UC3, cv::Scalar(230, 0, 0)),
      blue(64, 128, CV_8UC3, cv::Scalar(0, 0, 230));
  const fs::path clip = stereo_clip(dir / "tb.mp4", "top-bottom", red, blue, true);
  write_text(dir / "s.vdfx.json", sidecar_json(128, 128, kBlur4));
  const fs::path out = dir / "baked.mp4";
  const testing::CommandResult r =
      run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + out.string() + " --crf 0 --chroma 444 --preset ultrafast");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("top-bottom stereo"), std::string::npos) << r.output;
  // Tagged: vdfx's reader and ffprobe's own words.
  auto d = io::open_frame_decoder(out);
  EXPECT_EQ(d->properties().stereo_tags.mode, effects::StereoMode::TopBottom);
  EXPECT_EQ(d->properties().stereo_tags.coverage_deg, 360);
  const std::string probe = command_output("ffprobe -v error -show_streams '" + out.string() + "'");
  EXPECT_NE(probe.find("type=top and bottom"), std::string::npos) << probe;
  EXPECT_NE(probe.find("projection=equirectangular"), std::string::npos) << probe;
  // And ExifTool's (libimage-exiftool-perl, installed by .ci/deps.sh): the st3d box.
  const std::string exif = command_output("exiftool -s -Stereoscopic3D '" + out.string() + "'");
  EXPECT_NE(exif.find("Stereoscopic Top-Bottom"), std::string::npos) << exif;
  // The blur ran on each half alone: no blue in the upper (left eye) half, no red in the lower.
  const cv::Mat frame = testing::decoded_rgb8(*d, 1);
  std::vector<cv::Mat> ch;
  cv::split(frame, ch);
  double top_blue = 0, bottom_red = 0;
  cv::minMaxLoc(ch[2].rowRange(0, 64), nullptr, &top_blue);
  cv::minMaxLoc(ch[0].rowRange(64, 128), nullptr, &bottom_red);
  EXPECT_LE(top_blue, 2.0);
  EXPECT_LE(bottom_red, 2.0);
}

// At 4:2:0 each eye is decoded from its own planes and encoded from its own half: no chroma
// sample next to the boundary mixes red and blue (lossless, so only the conversions could).
TEST(StereoExport, A420BakedSideBySideMixesNoChromaAcrossTheHalves) {
  const fs::path dir = test_dir();
  const cv::Mat red(64, 64, CV_8UC3, cv::Scalar(230, 0, 0)),
      blue(64, 64, CV_8UC3, cv::Scalar(0, 0, 230));
  const fs::path clip = stereo_clip(dir / "lr.mp4", "left-right", red, blue, true);
  write_text(dir / "s.vdfx.json", sidecar_json(128, 64, ""));  // no effects: uniform halves
  const fs::path out = dir / "baked.mp4";
  const testing::CommandResult r =
      run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + out.string() + " --crf 0 --chroma 420 --preset ultrafast");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto d = io::open_frame_decoder(out);
  io::Picture pic;
  ASSERT_EQ(d->read_picture(pic), io::DecodeStatus::Ok);
  const cv::Mat frame =
      io::to_rgb_by_eye(pic, {effects::StereoMode::LeftRight, 360}, io::PixelFormat::Rgb8);
  // Each half one colour (red and blue as encoded): the columns at the boundary as the rest.
  for (const int x0 : {0, 64}) {
    const cv::Mat half = frame.colRange(x0, x0 + 64);
    const cv::Mat first(half.size(), half.type(), cv::Scalar(half.at<cv::Vec3b>(0, 0)));
    EXPECT_EQ(cv::norm(half, first, cv::NORM_INF), 0.0) << "half at column " << x0;
  }
  EXPECT_GT(frame.at<cv::Vec3b>(0, 0)[0], 200);
  EXPECT_GT(frame.at<cv::Vec3b>(0, 64)[2], 200);
}

TEST(StereoExport, EachBakedHalfIsItsEyeBakedAlone) {
  const fs::path dir = test_dir();
  const cv::Mat l = test_media::smooth_frame(0, 128, 64), r = test_media::patch_frame(1, 128, 64);
  const fs::path clip = stereo_clip(dir / "lr.mp4", "left-right", l, r, false);
  write_text(dir / "s.vdfx.json", sidecar_json(256, 64, kExposure));
  const fs::path out = dir / "baked.mkv";
  const testing::CommandResult res = run_vdfx(
      "export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() + " --baked " +
      out.string() + " --layout left-right --crf 0 --chroma 444 --param-step 1 --preset ultrafast");
  ASSERT_EQ(res.exit_code, 0) << res.output;
  auto got = io::open_frame_decoder(out);
  EXPECT_EQ(got->properties().stereo_tags.mode, effects::StereoMode::LeftRight);
  const cv::Mat baked = testing::decoded_rgb8(*got, 0);
  // Each half against the same export of that eye alone (a mono clip, the same pipeline).
  int eye = 0;
  for (const cv::Mat& img : {l, r}) {
    const fs::path mono = mono_clip(dir / ("eye" + std::to_string(eye) + ".mp4"), img);
    const fs::path mono_out = dir / ("eye" + std::to_string(eye) + "_baked.mkv");
    write_text(dir / "m.vdfx.json", sidecar_json(128, 64, kExposure));
    const testing::CommandResult m = run_vdfx(
        "export " + mono.string() + " --sidecar " + (dir / "m.vdfx.json").string() + " --baked " +
        mono_out.string() + " --crf 0 --chroma 444 --param-step 1 --preset ultrafast");
    ASSERT_EQ(m.exit_code, 0) << m.output;
    auto md = io::open_frame_decoder(mono_out);
    const cv::Mat want = testing::decoded_rgb8(*md, 0);
    EXPECT_LE(testing::max_abs_diff(baked(cv::Rect(eye * 128, 0, 128, 64)), want), 1.0)
        << "eye " << eye;
    ++eye;
  }
}

TEST(StereoExport, Vr180IsTaggedWithItsBounds) {
  const fs::path dir = test_dir();
  const cv::Mat l = test_media::smooth_frame(0, 64, 64), r = test_media::patch_frame(1, 64, 64);
  const fs::path clip = stereo_clip(dir / "vr.mp4", "left-right", l, r, true, 180);
  write_text(dir / "s.vdfx.json", sidecar_json(128, 64, kExposure));
  const fs::path out = dir / "baked.mp4";
  testing::CommandResult res =
      run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + out.string() + " --preset ultrafast");
  ASSERT_EQ(res.exit_code, 0) << res.output;
  const io::StereoTags tags = io::open_frame_decoder(out)->properties().stereo_tags;
  EXPECT_EQ(tags.mode, effects::StereoMode::LeftRight);
  EXPECT_EQ(tags.coverage_deg, 180);
  const std::string probe = command_output("ffprobe -v error -show_streams '" + out.string() + "'");
  EXPECT_NE(probe.find("projection=tiled equirectangular"), std::string::npos) << probe;
  // ExifTool reads the st3d mode and the equi bounds: a quarter turn cut from each side.
  const std::string exif =
      command_output("exiftool -s -Stereoscopic3D -ProjectionBoundsLeft -ProjectionBoundsRight '" +
                     out.string() + "'");
  EXPECT_NE(exif.find("Stereoscopic Left-Right"), std::string::npos) << exif;
  EXPECT_NE(exif.find("ProjectionBoundsLeft            : 0.25"), std::string::npos) << exif;
  EXPECT_NE(exif.find("ProjectionBoundsRight           : 0.25"), std::string::npos) << exif;
}

/// The reference of a VR180 eye's blur, independent of effects/equirect_blur: the contract's
/// Gaussian gathered directly in double, every texel of the whole sphere at the image's texel
/// size (180 / w degrees) weighted by exp(-theta^2 / 2 sigma^2) cos(altitude) within 3 sigma,
/// a texel beyond azimuth +-90 reading the image's edge column of its row (the VR180 clamp).
cv::Mat vr180_blur_reference(const cv::Mat& eye8, double sigma_deg) {
  constexpr double kPi = 3.14159265358979323846;
  const int w = eye8.cols, h = eye8.rows;
  const double sigma = sigma_deg * kPi / 180.0, cos_radius = std::cos(3.0 * sigma);
  auto unit = [&](double az, double alt) {
    return cv::Vec3d(std::cos(alt) * std::sin(az), std::sin(alt), -std::cos(alt) * std::cos(az));
  };
  auto altitude = [&](int y) { return 0.5 * kPi - (y + 0.5) * kPi / h; };
  auto azimuth = [&](int c) { return ((c + 0.5) / w - 0.5) * kPi; };  // c may pass the edges
  const int reach = static_cast<int>(std::ceil(3.0 * sigma / (kPi / h))) + 1;
  cv::Mat out(h, w, CV_64FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Vec3d n = unit(azimuth(x), altitude(y));
      cv::Vec3d sum(0, 0, 0);
      double norm = 0;
      for (int j = std::max(0, y - reach); j <= std::min(h - 1, y + reach); ++j)
        for (int c = -w / 2; c < w + w / 2; ++c) {  // the whole turn around the image
          const double d = std::clamp(n.dot(unit(azimuth(c), altitude(j))), -1.0, 1.0);
          if (d < cos_radius) continue;
          const double theta = std::acos(d);
          const double wgt = std::exp(-theta * theta / (2 * sigma * sigma)) * std::cos(altitude(j));
          const cv::Vec3b v = eye8.at<cv::Vec3b>(j, std::clamp(c, 0, w - 1));
          for (int k = 0; k < 3; ++k) sum[k] += wgt * v[k];
          norm += wgt;
        }
      out.at<cv::Vec3d>(y, x) = sum / norm;
    }
  return out;
}

/// A VR180 eye, RGB 8-bit, w x w: the left eye red and green only (a bright band along its left
/// edge, dark at its right edge), the right eye green and blue only (stripes, a ramp): any light
/// from one eye in the other, or from one edge at the other, shows.
cv::Mat vr180_eye(int w, bool left) {
  cv::Mat m(w, w, CV_8UC3);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const double g = 40 + 150.0 * x / w + 40 * ((x / 6 + y / 6) % 2);
      if (left)
        m.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uchar>(x < w / 8 ? 230 : 30 + 80.0 * y / w),
                                          static_cast<uchar>(g), 0);
      else
        m.at<cv::Vec3b>(y, x) =
            cv::Vec3b(0, static_cast<uchar>(250 - g), static_cast<uchar>((y / 8) % 2 ? 220 : 40));
    }
  return m;
}

TEST(StereoExport, Vr180BlurStaysInsideEachEyeAndClampsAtTheEdge) {
  const fs::path dir = test_dir();
  const int w = 128;  // each eye 128 x 128: 1.41 degrees a texel either way
  const cv::Mat l = vr180_eye(w, true), r = vr180_eye(w, false);
  const fs::path clip = stereo_clip(dir / "vr.mp4", "left-right", l, r, true, 180);
  write_text(dir / "b.vdfx.json", sidecar_json(2 * w, w, kBlur4));
  const fs::path out = dir / "blur.mkv";
  const testing::CommandResult res = run_vdfx(
      "export " + clip.string() + " --sidecar " + (dir / "b.vdfx.json").string() + " --baked " +
      out.string() + " --crf 0 --chroma 444 --preset ultrafast --frames 0-0");
  ASSERT_EQ(res.exit_code, 0) << res.output;
  auto d = io::open_frame_decoder(out);
  EXPECT_EQ(d->properties().stereo_tags.coverage_deg, 180);
  const cv::Mat baked = testing::decoded_rgb8(*d, 0);
  std::vector<cv::Mat> ch;
  cv::split(baked, ch);
  double left_blue = 0, right_red = 0;  // nothing crossed the boundary between the eyes
  cv::minMaxLoc(ch[2].colRange(0, w), nullptr, &left_blue);
  cv::minMaxLoc(ch[0].colRange(w, 2 * w), nullptr, &right_red);
  EXPECT_LE(left_blue, 2.0);
  EXPECT_LE(right_red, 2.0);
  // The left eye's right edge, away from the poles, keeps its dark red: its bright left band
  // (a wrap's neighbour) never reaches it.
  for (int y = w / 4; y < 3 * w / 4; ++y)
    EXPECT_NEAR(baked.at<cv::Vec3b>(y, w - 1)[0], l.at<cv::Vec3b>(y, w - 1)[0], 3.0) << y;
  int eye = 0;
  for (const cv::Mat& img : {l, r}) {
    cv::Mat want, got;
    vr180_blur_reference(img, 4.0).convertTo(want, CV_64FC3);
    baked(cv::Rect(eye * w, 0, w, w)).convertTo(got, CV_64FC3);
    // Within 2 rows (2.8 degrees) of a pole the blur's reduced levels are coarsest: the 360
    // blur of the two eyes as one 256 x 128 image differs from the same direct gather by up to
    // 7.4/255 in its pole rows (2.6/255 two rows in), so those rows get their own bound.
    const cv::Range inner(2, w - 2);
    const double mx = testing::max_abs_diff(got, want), mean = testing::mean_abs_diff(got, want),
                 mx_inner = testing::max_abs_diff(got.rowRange(inner), want.rowRange(inner));
    std::cout << "eye " << eye << ": baked VR180 blur against the direct gather: max " << mx
              << "/255 (" << mx_inner << "/255 beyond 2 rows of the poles), mean " << mean
              << "/255\n";
    EXPECT_LE(mx_inner, 6.0) << "eye " << eye;
    EXPECT_LE(mx, 14.0) << "eye " << eye;
    EXPECT_LE(mean, 1.2) << "eye " << eye;
    ++eye;
  }
}

TEST(StereoExport, ViewersPathShowsTheEyeAskedOrBoth) {
  const fs::path dir = test_dir();
  const cv::Mat red(64, 128, CV_8UC3, cv::Scalar(230, 0, 0)),
      blue(64, 128, CV_8UC3, cv::Scalar(0, 0, 230));
  const fs::path clip = stereo_clip(dir / "tb.mp4", "top-bottom", red, blue, true);
  write_text(dir / "s.vdfx.json", sidecar_json(128, 128, ""));
  const fs::path rec = testing::write_path_recording(dir);
  for (const std::string eye : {"left", "right"}) {
    const fs::path out = dir / (eye + ".mp4");
    const testing::CommandResult res = run_vdfx(
        "export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() + " --path " +
        rec.string() + " --out " + out.string() + " --size 64x48 --frames 0-1 --eye " + eye);
    ASSERT_EQ(res.exit_code, 0) << res.output;
    auto d = io::open_frame_decoder(out);
    const cv::Scalar m = cv::mean(testing::decoded_rgb8(*d, 0));
    if (eye == "left") {
      EXPECT_GT(m[0], 200.0);
      EXPECT_LT(m[2], 20.0);
    } else {
      EXPECT_GT(m[2], 200.0);
      EXPECT_LT(m[0], 20.0);
    }
  }
  testing::CommandResult res =
      run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + (dir / "b.mp4").string() + " --eye right");
  EXPECT_EQ(res.exit_code, 2) << res.output;

  // Both eyes side by side, tagged as a flat 3D video (a stereo mode, no spherical mapping).
  const fs::path sbs = dir / "sbs.mp4";
  res = run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
                 " --path " + rec.string() + " --out " + sbs.string() +
                 " --size 64x48 --frames 0-1 --stereo left-right");
  ASSERT_EQ(res.exit_code, 0) << res.output;
  auto d = io::open_frame_decoder(sbs);
  EXPECT_EQ(d->properties().width, 128);
  EXPECT_EQ(d->properties().stereo_tags.mode, effects::StereoMode::LeftRight);
  EXPECT_FALSE(d->properties().stereo_tags.coverage_deg);
  const cv::Mat pair = testing::decoded_rgb8(*d, 0);
  EXPECT_GT(cv::mean(pair.colRange(0, 64))[0], 200.0);    // left eye red
  EXPECT_GT(cv::mean(pair.colRange(64, 128))[2], 200.0);  // right eye blue
  const std::string probe = command_output("ffprobe -v error -show_streams '" + sbs.string() + "'");
  EXPECT_NE(probe.find("type=side by side"), std::string::npos) << probe;
  // A mono source has no pair to show.
  const fs::path mono = mono_clip(dir / "mono.mp4", red);
  res = run_vdfx("export " + mono.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
                 " --path " + rec.string() + " --out " + (dir / "m.mp4").string() +
                 " --size 64x48 --frames 0-1 --stereo left-right");
  EXPECT_EQ(res.exit_code, 1) << res.output;
  EXPECT_NE(res.output.find("--stereo left-right needs a stereo video"), std::string::npos)
      << res.output;
}

TEST(StereoExport, FourChannelAudioIsCopiedAndTheMissingSa3dSaid) {
  // A first-order ambisonic track is 4 channels; FFmpeg 5.1 writes no SA3D box to mark it.
  const fs::path dir = test_dir();
  const fs::path clip = dir / "amb.mp4";
  const std::string make =
      "ffmpeg -v error -y -f lavfi -i testsrc2=size=128x64:rate=24 -f lavfi -i "
      "'sine=frequency=440:sample_rate=48000,aformat=channel_layouts=4.0' -t 0.5 -c:v libx264 "
      "-pix_fmt yuv420p -c:a aac -shortest '" +
      clip.string() + "'";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  write_text(dir / "s.vdfx.json", sidecar_json(128, 64, ""));
  const fs::path out = dir / "baked.mp4";
  const testing::CommandResult r =
      run_vdfx("export " + clip.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + out.string() + " --preset ultrafast");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("note: " + clip.string() +
                          ": audio stream 1 (4 channels) is copied with its channel layout, but "
                          "this FFmpeg"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("writes no spatial audio box (SA3D)"), std::string::npos);
  const std::string probe = command_output("ffprobe -v error -show_streams '" + out.string() + "'");
  EXPECT_NE(probe.find("channels=4"), std::string::npos) << probe;
  EXPECT_NE(probe.find("channel_layout=4.0"), std::string::npos) << probe;
}

}  // namespace
}  // namespace vdfx::app
