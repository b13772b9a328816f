/// @file
/// @brief Whether a video is the one a sidecar was made for (its `video` section: size, frame
/// count, frame rate), for the warning every command that takes both prints (docs/cli.md).
#pragma once

#include <filesystem>
#include <string>

namespace vdfx::io {

struct VideoProperties;
struct VideoInfo;

/// "" when `video` matches what `sidecar` records; otherwise one line naming both files and
/// each property that differs, with what it means for the keyframes ("clip.mp4 is not the video
/// s.vdfx.json was made for: 10000 frames where it has 90 (keyframes hold after frame 89), ...").
/// A still's frame rate is not compared (a still has none). Frame rates agree within 1e-6
/// relative (a sidecar stores 29.97002997 for 30000/1001).
std::string video_mismatch(const VideoProperties& video, const VideoInfo& sidecar,
                           const std::filesystem::path& sidecar_path);

}  // namespace vdfx::io
