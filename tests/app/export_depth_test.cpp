/// @file
/// @brief `vdfx export --depth 10` (docs/export.md, "10 bits"): a smooth gradient with more levels
/// than 8 bits hold, exported with +1 stop, keeps more than 600 distinct luma codes in HEVC
/// Main10 where the 8-bit export has at most 256; ProRes output is ProRes 422 HQ, 10-bit 4:2:2;
/// the combinations that cannot work are usage errors. The viewer's path renders its views in
/// float and converts them straight to 10-bit codes too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <string>

#include "command_test_util.h"
#include "io/frame_decoder.h"
#include "io/recording.h"
#include "xr/headset/pose.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::command_output;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

/// A 16-bit PNG, 1024 x 64, grey rising linearly from 0 to 0.45 left to right: every column
/// its own value, far more levels than 8 (or 10) bits hold.
fs::path gradient_png(const fs::path& dir) {
  cv::Mat m(64, 1024, CV_16UC3);
  for (int x = 0; x < m.cols; ++x) {
    const auto v = static_cast<std::uint16_t>(std::lround(x / 1023.0 * 0.45 * 65535.0));
    m.col(x).setTo(cv::Scalar::all(v));
  }
  const fs::path p = dir / "gradient.png";
  cv::imwrite(p.string(), m);
  return p;
}

/// Distinct luma codes of frame 0 as decoded (its own planes, no conversion).
std::size_t luma_levels(const fs::path& video) {
  auto d = io::open_frame_decoder(video);
  io::Picture p;
  EXPECT_EQ(d->read_picture(p), io::DecodeStatus::Ok);
  std::set<int> codes;
  const cv::Mat& y = p.planes[0];
  for (int r = 0; r < y.rows; ++r)
    for (int c = 0; c < y.cols; ++c)
      codes.insert(y.depth() == CV_16U ? y.at<std::uint16_t>(r, c) : y.at<std::uint8_t>(r, c));
  return codes.size();
}

constexpr const char* kPlusOneStop = R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "gradient.png", "fps": 30.0, "frames": 1, "width": 1024, "height": 64},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [{"type": "exposure", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0,
    "frame": 0, "params": {"stops": 1.0}}]}]})";

/// Runs `base` + OUT twice, h265 lossless at 10 and at 8 bits: the 10-bit export announces
/// itself, is Main10 4:2:0 and keeps more than 600 luma levels where 8 bits keep at most 256.
void expect_ten_bits_keep_the_levels(const fs::path& dir, const std::string& base) {
  testing::CommandResult r =
      run_vdfx(base + (dir / "ten.mkv").string() + " --codec h265 --depth 10 --crf 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("10-bit"), std::string::npos) << r.output;
  r = run_vdfx(base + (dir / "eight.mkv").string() + " --codec h265 --crf 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::size_t ten = luma_levels(dir / "ten.mkv"), eight = luma_levels(dir / "eight.mkv");
  EXPECT_GT(ten, 600u);
  EXPECT_LE(eight, 256u);
  const std::string probe =
      command_output("ffprobe -v error -show_streams '" + (dir / "ten.mkv").string() + "'");
  EXPECT_NE(probe.find("profile=Main 10"), std::string::npos) << probe;
  EXPECT_NE(probe.find("pix_fmt=yuv420p10le"), std::string::npos) << probe;
}

TEST(ExportDepth, TenBitsKeepTheGradientsLevels) {
  const fs::path dir = test_dir();
  const fs::path png = gradient_png(dir);
  write_text(dir / "s.vdfx.json", kPlusOneStop);
  const std::string base =
      "export " + png.string() + " --sidecar " + (dir / "s.vdfx.json").string() + " --baked ";
  expect_ten_bits_keep_the_levels(dir, base);
}

TEST(ExportDepth, TheDefaultIsTheSourcesDepthWhereTheCodecCarriesIt) {
  const fs::path dir = test_dir();
  const fs::path png = gradient_png(dir);
  const fs::path source = dir / "main10.mkv";  // a 10-bit HEVC source
  const std::string make = "ffmpeg -v error -y -i '" + png.string() +
                           "' -c:v libx265 -pix_fmt yuv420p10le -x265-params log-level=error '" +
                           source.string() + "'";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  EXPECT_EQ(io::open_frame_decoder(source)->properties().bit_depth, 10);
  std::string sidecar = kPlusOneStop;
  sidecar.replace(sidecar.find("gradient.png"), 12, "main10.mkv");
  write_text(dir / "s.vdfx.json", sidecar);
  const std::string base =
      "export " + source.string() + " --sidecar " + (dir / "s.vdfx.json").string() + " --baked ";
  testing::CommandResult r = run_vdfx(base + (dir / "h265.mkv").string() + " --codec h265");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("10-bit"), std::string::npos) << r.output;
  EXPECT_NE(command_output("ffprobe -v error -show_streams '" + (dir / "h265.mkv").string() + "'")
                .find("pix_fmt=yuv420p10le"),
            std::string::npos);
  r = run_vdfx(base + (dir / "h264.mkv").string());  // h264 here is 8-bit only
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(command_output("ffprobe -v error -show_streams '" + (dir / "h264.mkv").string() + "'")
                .find("pix_fmt=yuv420p\n"),
            std::string::npos);
}

TEST(ExportDepth, ProResIsProRes422Hq) {
  const fs::path dir = test_dir();
  const fs::path png = gradient_png(dir);
  write_text(dir / "s.vdfx.json", kPlusOneStop);
  const fs::path out = dir / "master.mov";
  const testing::CommandResult r =
      run_vdfx("export " + png.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --baked " + out.string() + " --codec prores");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string probe = command_output("ffprobe -v error -show_streams '" + out.string() + "'");
  EXPECT_NE(probe.find("codec_name=prores"), std::string::npos) << probe;
  EXPECT_NE(probe.find("profile=HQ"), std::string::npos) << probe;
  EXPECT_NE(probe.find("pix_fmt=yuv422p10le"), std::string::npos) << probe;
  EXPECT_GT(luma_levels(out), 600u);
}

/// A 16-bit PNG equirect, 2048 x 1024, grey rising from 0 at azimuth -45 to 0.45 at azimuth 45
/// (constant outside): the 90-degree view straight ahead sees the whole ramp across its width.
fs::path view_gradient_png(const fs::path& dir) {
  cv::Mat m(1024, 2048, CV_16UC3);
  for (int x = 0; x < m.cols; ++x) {
    const double u = (x + 0.5) / m.cols, t = std::clamp((u - 0.375) / 0.25, 0.0, 1.0);
    m.col(x).setTo(cv::Scalar::all(std::lround(t * 0.45 * 65535.0)));
  }
  const fs::path p = dir / "view_gradient.png";
  cv::imwrite(p.string(), m);
  return p;
}

/// A recording whose head looks straight ahead (azimuth 0, altitude 0) for a second.
fs::path straight_ahead(const fs::path& dir) {
  const fs::path p = dir / "ahead.vdrec.jsonl";
  io::RecordingWriter w(p, io::RecordingHeader{});
  for (std::int64_t t : {0LL, 1'000'000'000LL}) {
    const glm::dquat q = xr::look_rotation(0.0, 0.0);
    io::RecordedSample s;
    s.t_ns = t;
    s.head.q = {q.w, q.x, q.y, q.z};
    s.head.p = {0.0, 1.6, 0.0};
    w.write(s);
  }
  return p;
}

TEST(ExportDepth, ThePathAtTenBitsKeepsTheGradientsLevels) {
  const fs::path dir = test_dir();
  const fs::path png = view_gradient_png(dir);
  write_text(dir / "s.vdfx.json", kPlusOneStop);
  const std::string base = "export " + png.string() + " --sidecar " +
                           (dir / "s.vdfx.json").string() + " --path " +
                           straight_ahead(dir).string() + " --fov 90 --size 1024x64 --out ";
  expect_ten_bits_keep_the_levels(dir, base);
}

TEST(ExportDepth, ThePathFromATenBitSourceToProResNeverPassesThroughEightBits) {
  const fs::path dir = test_dir();
  const fs::path png = view_gradient_png(dir);
  const fs::path source = dir / "main10.mkv";  // a lossless 10-bit HEVC source of the ramp
  const std::string make = "ffmpeg -v error -y -i '" + png.string() +
                           "' -c:v libx265 -pix_fmt yuv420p10le -preset ultrafast "
                           "-x265-params lossless=1:log-level=error '" +
                           source.string() + "'";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  std::string sidecar = kPlusOneStop;
  sidecar.replace(sidecar.find("gradient.png"), 12, "main10.mkv");
  write_text(dir / "s.vdfx.json", sidecar);
  const fs::path out = dir / "path.mov";
  const testing::CommandResult r =
      run_vdfx("export " + source.string() + " --sidecar " + (dir / "s.vdfx.json").string() +
               " --path " + straight_ahead(dir).string() + " --fov 90 --size 1024x64 --out " +
               out.string() + " --codec prores");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string probe = command_output("ffprobe -v error -show_streams '" + out.string() + "'");
  EXPECT_NE(probe.find("profile=HQ"), std::string::npos) << probe;
  EXPECT_NE(probe.find("pix_fmt=yuv422p10le"), std::string::npos) << probe;
  // The source holds about 0.45 x 876 = 394 codes along the ramp, +1 stop spreads them over
  // twice the range and the view's bilinear taps fill in between (733 codes when written; an
  // 8-bit step after the render left 231).
  EXPECT_GT(luma_levels(out), 600u);
}

TEST(ExportDepth, CombinationsThatCannotWorkAreUsageErrors) {
  const fs::path dir = test_dir();
  const fs::path png = gradient_png(dir);
  write_text(dir / "s.vdfx.json", kPlusOneStop);
  const std::string base =
      "export " + png.string() + " --sidecar " + (dir / "s.vdfx.json").string() + " ";
  const struct {
    std::string args, want;
  } rows[] = {
      {"--baked " + (dir / "a.mp4").string() + " --depth 10", "--depth 10: needs --codec h265"},
      {"--baked " + (dir / "a.mp4").string() + " --codec prores", "--codec prores: write a .mov"},
      {"--baked " + (dir / "a.mov").string() + " --codec prores --depth 8",
       "ProRes 422 HQ is 10-bit"},
      {"--baked " + (dir / "a.mp4").string() + " --depth 12", "--depth"},
  };
  for (const auto& row : rows) {
    SCOPED_TRACE(row.args);
    const testing::CommandResult r = run_vdfx(base + row.args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(row.want), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace vdfx::app
