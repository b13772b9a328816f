/// @file
/// @brief Shared pieces of the player and frame-loop tests: a generated video (fake decoder, with
/// an optional gate that holds decoding back), in-memory recordings and sidecars.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <vector>

#include "app/window/frame_loop.h"
#include "effects/keyframe.h"
#include "io/frame_decoder.h"
#include "io/recording.h"
#include "io/sidecar.h"
#include "xr/headset/hmd_profile.h"
#include "xr/input/actions.h"

namespace vdfx::app::test {

/// Holds back decoding of frames >= `from` until open() (a decoder slower than any loop).
struct DecodeGate {
  std::int64_t from = 1;
  std::mutex m;
  std::condition_variable cv;
  bool opened = false;
  void open() {
    {
      std::lock_guard lock(m);
      opened = true;
    }
    cv.notify_all();
  }
};

/// A generated video: every frame uniform grey `grey` (RGB 8-bit), `frames` at 30 fps.
class FakeDecoder : public io::FrameDecoder {
 public:
  FakeDecoder(std::int64_t frames, int width, int height, double grey,
              std::shared_ptr<DecodeGate> gate = nullptr)
      : grey_(grey), gate_(std::move(gate)) {
    props_.path = "generated";
    props_.fps = {30, 1};
    props_.frames = frames;
    props_.width = width;
    props_.height = height;
    props_.backend = "fake";
  }
  const io::VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return next_; }
  void seek(std::int64_t index) override { next_ = index; }
  io::DecodeStatus read(cv::Mat& out) override {
    if (next_ >= props_.frames) return io::DecodeStatus::End;
    if (gate_ && next_ >= gate_->from) {
      std::unique_lock lock(gate_->m);
      gate_->cv.wait(lock, [&] { return gate_->opened; });
    }
    const auto v = static_cast<std::uint8_t>(grey_ * 255.0 + 0.5);
    out = cv::Mat(props_.height, props_.width, CV_8UC3, cv::Scalar(v, v, v));
    ++next_;
    return io::DecodeStatus::Ok;
  }

 private:
  io::VideoProperties props_;
  double grey_;
  std::shared_ptr<DecodeGate> gate_;
  std::int64_t next_ = 0;
};

/// A recording with the head looking at (azimuth, altitude) at each of `times`, hands absent.
inline io::Recording still_head_recording(const std::vector<std::int64_t>& times,
                                          double azimuth_deg = 0.0, double altitude_deg = 0.0) {
  io::Recording r;
  r.name = "test.vdrec.jsonl";
  const glm::dquat q = xr::look_rotation(azimuth_deg, altitude_deg);
  int line = 2;
  for (std::int64_t t : times) {
    io::RecordedSample s;
    s.t_ns = t;
    s.head.q = {q.w, q.x, q.y, q.z};
    s.head.p = {0.0, xr::kDefaultEyeHeight, 0.0};
    r.lines.push_back({line++, s});
  }
  return r;
}

/// A sidecar with one effect's keyframes, each (azimuth, altitude, frame 0, values).
struct Kf {
  double azimuth_deg, altitude_deg;
  std::vector<double> values;
};
inline io::Sidecar one_effect_sidecar(effects::EffectType type, const std::vector<Kf>& kfs) {
  io::Sidecar s;
  s.video = {"generated", 30.0, 1000, 64, 32};
  effects::EffectTrack track;
  track.type = type;
  for (const Kf& k : kfs) {
    effects::Keyframe kf;
    kf.direction = {k.azimuth_deg, k.altitude_deg};
    kf.frame = 0;
    kf.params = k.values;
    track.keyframes.push_back(kf);
  }
  s.effects.push_back(track);
  return s;
}

/// The frame loop of the layer tests (flare, grain): generic90 eyes at a tenth of their size in a
/// hidden 160 x 90 window, each frame's video waited for (so the frames are deterministic).
inline FrameLoopOptions small_hidden_loop() {
  FrameLoopOptions o;
  o.profile = xr::load_hmd_profile("generic90");
  o.eye_scale = 0.1;
  o.window_width = 160;
  o.window_height = 90;
  o.visible = false;
  o.mirror = xr::MirrorMode::PreDistorted;  // both eyes are rendered (the tests read them)
  o.decode_timeout = std::chrono::seconds(5);
  return o;
}

}  // namespace vdfx::app::test
