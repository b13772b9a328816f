/// @file
/// @brief Shared by the export tests: a small equirect clip with an audio track made in the test
/// and a sidecar whose effects depend visibly on the direction.
#pragma once

#include <algorithm>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>

#include "command_test_util.h"
#include "io/frame_decoder.h"
#include "io/recording.h"
#include "tests/media_clips.h"
#include "xr/input/actions.h"

namespace vdfx::app::testing {

inline constexpr int kW = 128, kH = 64, kFrames = 12;

/// Exposure +1 stop looking at azimuth 0, -1 stop behind; a little saturation change; a blur
/// towards azimuth 90 (sharp elsewhere).
inline const char* kSidecar = R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "clip.mp4", "fps": 24.0, "frames": 12, "width": 128, "height": 64},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "exposure", "keyframes": [
      {"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": 1.0}},
      {"azimuth_deg": 180.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": -1.0}}]},
    {"type": "saturation", "keyframes": [
      {"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"amount": 1.3}},
      {"azimuth_deg": 180.0, "altitude_deg": 0.0, "frame": 0, "params": {"amount": 0.7}}]},
    {"type": "blur", "keyframes": [
      {"azimuth_deg": 90.0, "altitude_deg": 0.0, "frame": 0, "params": {"sigma_deg": 6.0}},
      {"azimuth_deg": -90.0, "altitude_deg": 0.0, "frame": 0, "params": {"sigma_deg": 0.0}}]}
  ]})";

/// A 128x64 equirect clip, 12 frames at 24 fps (H.264 with B-frames), with an AAC track.
struct Fixture {
  std::filesystem::path dir, clip, sidecar;
};

inline Fixture make_fixture(int width = kW, int height = kH, int frames = kFrames) {
  Fixture f;
  f.dir = test_dir();
  const std::filesystem::path tone = test_media::write_tone(f.dir / "tone.m4a", 1.0);
  test_media::ClipSpec c;
  c.width = width;
  c.height = height;
  c.frames = frames;
  c.options = {{"qp", "4"}};
  c.audio_from = tone;
  c.frame = [=](int i) { return test_media::smooth_frame(i, width, height); };
  f.clip = test_media::write_clip(f.dir / "clip.mp4", c);
  f.sidecar = f.dir / "clip.vdfx.json";
  write_text(f.sidecar, kSidecar);
  return f;
}

/// Frame k of a decoder as RGB 8-bit.
inline cv::Mat decoded_rgb8(io::FrameDecoder& d, std::int64_t k) {
  d.seek(k);
  cv::Mat m;
  EXPECT_EQ(d.read(m), io::DecodeStatus::Ok) << k;
  return m;
}

/// A recording: looking at (30, 10) for 0.25 s, turning to (-60, -5) by 0.6 s, then still to 1 s.
inline std::filesystem::path write_path_recording(const std::filesystem::path& dir) {
  const std::filesystem::path p = dir / "path.vdrec.jsonl";
  io::RecordingWriter w(p, io::RecordingHeader{});
  for (std::int64_t t = 0; t <= 1'000'000'000; t += 11'111'111) {
    const double f = std::clamp((static_cast<double>(t) / 1e9 - 0.25) / 0.35, 0.0, 1.0);
    const glm::dquat q = xr::look_rotation(30.0 - 90.0 * f, 10.0 - 15.0 * f);
    io::RecordedSample s;
    s.t_ns = 5'000'000'000 + t;
    s.head.q = {q.w, q.x, q.y, q.z};
    s.head.p = {0.0, 1.6, 0.0};
    w.write(s);
  }
  return p;
}

}  // namespace vdfx::app::testing
