/// @file
/// @brief Runs the real vdfx executable from tests and captures its output and exit code, and
/// writes small inputs (a synthetic equirect image, sidecars) into a per-test folder.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "tests/support/test_paths.h"
#include "tests/test_files.h"

namespace vdfx::app::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  //!< stdout and stderr together
};

/// Runs a shell command line; its standard output (and what the line redirects into it).
inline CommandResult run_command(const std::string& cmd) {
  CommandResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// Runs `vdfx ARGS`; `env_prefix` (e.g. "env -u DISPLAY ") goes before the executable.
inline CommandResult run_vdfx(const std::string& args, const std::string& env_prefix = "") {
  return run_command(env_prefix + std::string(VDFX_BINARY) + " " + args + " 2>&1");
}

/// Standard output of a shell command (ffprobe's, say).
inline std::string command_output(const std::string& cmd) {
  return run_command(cmd).output;
}

/// `vdfx ARGS` without a display (nothing may open a window) and under a time limit: a command
/// that would block (on a pipe, say) fails with exit 124 instead of hanging the test.
inline CommandResult run_vdfx_headless(const std::string& args) {
  return run_vdfx(args, "env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 ");
}

/// A fresh folder under the build tree, named after the running test.
inline std::filesystem::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return test_files::fresh_dir(std::filesystem::path("app") /
                               (std::string(info->test_suite_name()) + "." + info->name()));
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

/// A 256x128 equirect PNG with smooth colour gradients and a grid (so blur, tint and distortion
/// all change it visibly).
inline std::filesystem::path write_test_panorama(const std::filesystem::path& dir, int grid = 32) {
  cv::Mat img(128, 256, CV_8UC3);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const bool line = (x % grid == 0) || (y % grid == 0);
      img.at<cv::Vec3b>(y, x) =
          line ? cv::Vec3b(20, 20, 20)
               : cv::Vec3b(static_cast<uchar>(60 + y), 128, static_cast<uchar>(40 + x * 0.7));
    }
  const auto path = dir / "pano.png";
  cv::imwrite(path.string(), img);
  return path;
}

/// A sidecar for a 256x128 still with exposure +1 stop at azimuth 90 and -1 at azimuth -90.
inline std::string exposure_sidecar(const std::string& extra_effects = "") {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "pano.png", "fps": 30.0, "frames": 1, "width": 256, "height": 128},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure", "keyframes": [
      {"azimuth_deg": 90.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": 1.0}},
      {"azimuth_deg": -90.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": -1.0}}]})" +
         extra_effects + "]}";
}

/// Largest absolute difference over all pixels and channels of two same-size images.
inline double max_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return mx;
}

/// Mean absolute difference over all pixels and channels.
inline double mean_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return cv::mean(d.reshape(1))[0];
}

/// `vdfx render DIR/pano.png --sidecar DIR/s.vdfx.json ARGS --out DIR/OUT`, expected to succeed;
/// returns the written image (BGR).
inline cv::Mat render(const std::filesystem::path& dir, const std::string& args,
                      const std::string& out) {
  const CommandResult r =
      run_vdfx("render " + (dir / "pano.png").string() + " --sidecar " +
               (dir / "s.vdfx.json").string() + " " + args + " --out " + (dir / out).string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return cv::imread((dir / out).string(), cv::IMREAD_COLOR);
}

/// A two-line recording at `path`: the header and first sample of a committed one.
inline void write_short_recording(const std::filesystem::path& path) {
  std::ifstream in(test_files::recordings_dir() / "sim_look_and_place.vdrec.jsonl");
  std::string header, sample;
  std::getline(in, header);
  std::getline(in, sample);
  write_text(path, header + "\n" + sample + "\n");
}

/// pano.png (write_test_panorama) and s.vdfx.json (exposure_sidecar) in a fresh test folder.
inline std::filesystem::path panorama_and_sidecar() {
  const std::filesystem::path dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  return dir;
}

}  // namespace vdfx::app::testing
