/// @file
/// @brief video_mismatch: the video against a sidecar's `video` section.
#include "io/video_match.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "io/frame_decoder.h"
#include "io/sidecar.h"

namespace vdfx::io {

namespace {

std::string fps_text(double fps) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", fps);
  return buf;
}

std::string size_text(int w, int h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

}  // namespace

std::string video_mismatch(const VideoProperties& video, const VideoInfo& sidecar,
                           const std::filesystem::path& sidecar_path) {
  std::vector<std::string> differences;
  if (video.frames != sidecar.frames) {
    std::string d = std::to_string(video.frames) + (video.frames == 1 ? " frame" : " frames") +
                    " where the sidecar has " + std::to_string(sidecar.frames);
    if (video.frames > sidecar.frames)
      d += " (its effects hold after frame " + std::to_string(sidecar.frames - 1) + ")";
    differences.push_back(d);
  }
  const double fps = video.fps.value();
  if (!video.is_still && std::abs(fps - sidecar.fps) > 1e-6 * sidecar.fps)
    differences.push_back(fps_text(fps) + " fps where the sidecar has " + fps_text(sidecar.fps) +
                          " (keyframes land at other times)");
  if (video.width != sidecar.width || video.height != sidecar.height)
    differences.push_back(size_text(video.width, video.height) + " where the sidecar has " +
                          size_text(sidecar.width, sidecar.height));
  if (differences.empty()) return "";
  std::string s = video.path.string() + " is not the video " + sidecar_path.string() +
                  " was made for (its video section): ";
  for (std::size_t i = 0; i < differences.size(); ++i) s += (i ? "; " : "") + differences[i];
  return s;
}

}  // namespace vdfx::io
