/// @file
/// @brief io::video_mismatch: a video against the sidecar's record of the video it was made for.
#include "io/video_match.h"

#include <gtest/gtest.h>

#include "io/frame_decoder.h"
#include "io/sidecar.h"

namespace vdfx::io {
namespace {

VideoProperties clip(std::int64_t frames, Rational fps, int w, int h, bool still = false) {
  VideoProperties p;
  p.path = "clip.mp4";
  p.frames = frames;
  p.fps = fps;
  p.width = w;
  p.height = h;
  p.is_still = still;
  return p;
}

TEST(VideoMatch, TheSameVideoSaysNothing) {
  // A sidecar stores 30000/1001 as the double it is.
  const VideoInfo recorded("clip.mp4", 30000.0 / 1001.0, 90, 1024, 512);
  EXPECT_EQ(video_mismatch(clip(90, {30000, 1001}, 1024, 512), recorded, "s.vdfx.json"), "");
}

TEST(VideoMatch, EachDifferenceIsNamedWithWhatItMeans) {
  const VideoInfo recorded("clip.mp4", 30.0, 90, 1024, 512);
  const std::string w = video_mismatch(clip(10000, {25, 1}, 64, 32), recorded, "s.vdfx.json");
  EXPECT_NE(w.find("clip.mp4 is not the video s.vdfx.json was made for"), std::string::npos) << w;
  EXPECT_NE(w.find("10000 frames where the sidecar has 90 (its effects hold after frame 89)"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("25 fps where the sidecar has 30"), std::string::npos) << w;
  EXPECT_NE(w.find("64x32 where the sidecar has 1024x512"), std::string::npos) << w;
  // Shorter: no hold to speak of, just the count.
  const std::string shorter = video_mismatch(clip(60, {30, 1}, 1024, 512), recorded, "s");
  EXPECT_NE(shorter.find("60 frames where the sidecar has 90"), std::string::npos) << shorter;
  EXPECT_EQ(shorter.find("hold"), std::string::npos) << shorter;
}

TEST(VideoMatch, AStillHasNoFrameRateToCompare) {
  const VideoInfo recorded("pano.png", 24.0, 1, 256, 128);
  EXPECT_EQ(video_mismatch(clip(1, {30, 1}, 256, 128, true), recorded, "s"), "");
  EXPECT_NE(video_mismatch(clip(1, {30, 1}, 512, 256, true), recorded, "s"), "");
}

}  // namespace
}  // namespace vdfx::io
