/// @file
/// @brief The commands' work called as library functions, without the command line: a baked and
/// a viewer's-path export through run_export, a render through render_to_png, one cheap bench row
/// through run_bench. Each checks what the output shows, not only that it exists.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "app/bench/bench_request.h"
#include "app/cli/command_registry.h"
#include "app/export/export_request.h"
#include "app/export/view_render.h"
#include "export_test_util.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/sidecar.h"
#include "tests/media_clips.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::Fixture;
using testing::kFrames;
using testing::kH;
using testing::kW;
using testing::make_fixture;
using testing::write_path_recording;

/// Frame k of a video as RGB 8-bit.
cv::Mat frame_rgb8(const fs::path& video, std::int64_t k) {
  return testing::decoded_rgb8(*io::open_frame_decoder(video), k);
}

/// Mean of the green channel over columns [u0, u1) (fractions of the width) of an equirect
/// image, rows near the horizon (altitude within about 27 degrees).
double band_mean(const cv::Mat& rgb8, double u0, double u1) {
  const int x0 = static_cast<int>(u0 * rgb8.cols), x1 = static_cast<int>(u1 * rgb8.cols);
  const int y0 = rgb8.rows * 7 / 20, y1 = rgb8.rows * 13 / 20;
  return cv::mean(rgb8(cv::Rect(x0, y0, x1 - x0, y1 - y0)))[1];
}

TEST(LibraryCalls, BakedExportBrightensWhereTheSidecarSaysAndKeepsTheRest) {
  const Fixture f = make_fixture();
  ExportRequest req;
  req.video = f.clip;
  req.sidecar = f.sidecar;
  req.baked_out = f.dir / "baked.mp4";
  req.crf = 0;
  req.chroma_444 = true;
  req.frames = FrameRange{2, 5};
  req.threads = 2;
  const ExportResult r = run_export(req);
  EXPECT_EQ(r.output, req.baked_out);
  EXPECT_EQ(r.frames, 4);
  EXPECT_EQ(r.width, kW);
  EXPECT_EQ(r.height, kH);
  EXPECT_FALSE(r.cancelled);
  EXPECT_FALSE(r.ended_early);
  // Exported frame 0 is source frame 2. The sidecar's exposure is +1 stop at azimuth 0 (the
  // middle columns) and -1 stop behind (the outer columns): the middle brightens, the back darkens.
  const cv::Mat src = frame_rgb8(f.clip, 2), out = frame_rgb8(req.baked_out, 0);
  EXPECT_GT(band_mean(out, 0.45, 0.55), 1.3 * band_mean(src, 0.45, 0.55));
  EXPECT_LT(band_mean(out, 0.0, 0.05), 0.8 * band_mean(src, 0.0, 0.05));
}

TEST(LibraryCalls, PathExportFirstFrameIsTheRenderOfThePathsFirstView) {
  const Fixture f = make_fixture(kW, kH, 30);
  ExportRequest req;
  req.video = f.clip;
  req.sidecar = f.sidecar;
  req.path_recording = write_path_recording(f.dir);
  req.path_out = f.dir / "path.mkv";
  req.crf = 0;
  req.chroma_444 = true;
  req.hfov_deg = 80.0;
  req.width = 96;
  req.height = 64;
  const ExportResult r = run_export(req);
  EXPECT_EQ(r.frames, 24);  // the recording lasts 1 s at 24 fps: frames 0..23 of the 30
  EXPECT_EQ(r.width, 96);
  // The path starts looking at (30, 10), unrolled: the same view render_request draws.
  RenderRequest view;
  view.look = {30.0, 10.0};
  view.hfov_deg = 80.0;
  view.width = 96;
  view.height = 64;
  view.frame = 0;
  const cv::Mat want = render_request(f.clip, io::read_sidecar(f.sidecar), view);
  EXPECT_LE(test_media::max_abs_diff(frame_rgb8(req.path_out, 0), want), 2);
}

TEST(LibraryCalls, AnExportRequestThatContradictsItselfIsAUsageError) {
  ExportRequest req;
  req.video = "clip.mp4";
  req.sidecar = "clip.vdfx.json";
  EXPECT_THROW(check_export_request(req), UsageError);  // neither output
  req.baked_out = "out.mp4";
  req.path_recording = "path.vdrec.jsonl";
  EXPECT_THROW(check_export_request(req), UsageError);  // both
  req.path_recording.clear();
  req.baked_out = "out.avi";
  EXPECT_THROW(run_export(req), UsageError);  // before any input is opened
  req.baked_out = "out.mkv";
  EXPECT_NO_THROW(check_export_request(req));
}

TEST(LibraryCalls, RenderToPngDrawsTheSidecarsExposureAtTheView) {
  const Fixture f = make_fixture();
  const fs::path neutral = f.dir / "neutral.vdfx.json";
  io::Sidecar plain = io::read_sidecar(f.sidecar);
  plain.effects.clear();
  io::write_sidecar(neutral, plain);
  RenderRequest r;
  r.look = {0.0, 0.0};
  r.hfov_deg = 60.0;
  r.width = 64;
  r.height = 48;
  r.frame = 3;
  EXPECT_EQ(render_to_png(f.clip, f.sidecar, r, f.dir / "view.png"), cv::Size(64, 48));
  EXPECT_EQ(render_to_png(f.clip, neutral, r, f.dir / "plain.png"), cv::Size(64, 48));
  const cv::Mat view = cv::imread((f.dir / "view.png").string());
  const cv::Mat base = cv::imread((f.dir / "plain.png").string());
  ASSERT_EQ(view.size(), cv::Size(64, 48));
  // +1 stop at azimuth 0 (then clamped): clearly brighter than the same view without effects.
  EXPECT_GT(cv::mean(view)[1], 1.3 * cv::mean(base)[1]);
  // The output may not be an input.
  EXPECT_THROW(render_to_png(f.clip, f.sidecar, r, f.sidecar), io::InputError);
}

TEST(LibraryCalls, OneCheapBenchRowIsMeasuredBesideItsPeerAndReported) {
  bench::BenchRequest req;
  req.quick = true;
  req.filter = "^rbf\\.solve/N=10$";
  std::ostringstream markdown;
  const bench::Report report = bench::run_bench(req, markdown);
  ASSERT_EQ(report.rows.size(), 1u);
  const bench::Row& row = report.rows[0];
  EXPECT_EQ(row.knob, "rbf.solve");
  EXPECT_EQ(row.setting, "N=10");
  EXPECT_EQ(row.status, bench::RowStatus::Ok) << row.reason;
  EXPECT_GT(row.time.median_s, 0.0);
  EXPECT_GT(row.peer_time.median_s, 0.0);
  EXPECT_FALSE(row.peer.empty());
  // The solve reproduces its keyframes: the error against the exact reference is tiny.
  ASSERT_TRUE(std::isfinite(row.error.max));
  EXPECT_LT(row.error.max, 1e-6);
  EXPECT_EQ(bench::failed_rows(report), 0);
  EXPECT_NE(markdown.str().find("rbf.solve"), std::string::npos);
  // A filter that matches nothing or is no regular expression is a usage error.
  req.filter = "^no-such-knob$";
  EXPECT_THROW(bench::run_bench(req, markdown), UsageError);
  EXPECT_THROW(bench::filter_pattern("("), UsageError);
}

}  // namespace
}  // namespace vdfx::app
