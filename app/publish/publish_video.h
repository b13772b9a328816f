/// @file
/// @brief The published folder's video: the source copied, or re-encoded with no effects
/// through the export pipeline (`--transcode`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/publish/publish_request.h"
#include "effects/stereo_layout.h"
#include "io/picture.h"
#include "io/sidecar.h"

namespace vdfx::app {

/// The names the video and the sidecar have in the published folder, whatever their own: the
/// page builds URLs from them, and a name such as "take#2 50%.mp4" is not one a URL can hold as
/// it is. The original names are the page's title and player.json's `name`s.
inline constexpr const char* kPublishedVideoStem = "video";
inline constexpr const char* kPublishedSidecar = "sidecar.vdfx.json";

struct PublishedVideo {
  std::string file;   //!< its name inside the folder: kPublishedVideoStem and the extension
  std::string codec;  //!< "h264", "vp9", ... (the source's when copied)
  double fps = 0.0;
  std::int64_t frames = 0;
  int width = 0, height = 0;
  /// How its first frame's Y'CbCr code values are read (the stream's tags, io/ycbcr.h); none
  /// for an RGB codec.
  std::optional<io::YcbcrInfo> ycbcr;
  /// How the frame holds the eyes and how much of the sphere they cover (run_publish sets it
  /// from io::resolve_video_layout).
  effects::StereoLayout layout;
};

/// Copies `request.video` into `dir` as `video` with its extension (lower case), or with a
/// transcode writes `video.mp4` through run_export (baked, no effects: a sidecar of the same
/// video with none).
PublishedVideo publish_video(const PublishRequest& request, const io::Sidecar& sidecar,
                             const std::filesystem::path& dir);

}  // namespace vdfx::app
