/// @file
/// @brief Which stereo layout and sphere coverage a video is shown with (docs/stereo.md): the
/// stream's own tags (Spherical Video V2 st3d/sv3d in MP4, Matroska StereoMode and Projection,
/// read through libavformat's AVStereo3D and AVSphericalMapping), the sidecar's record, and the
/// command line's --layout / --coverage, in that order of precedence reversed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "effects/stereo_layout.h"

struct AVStream;

namespace vdfx::io {

struct VideoProperties;
struct VideoInfo;

/// What a stream says about itself; each part empty when it says nothing.
struct StereoTags {
  std::optional<effects::StereoMode> mode;  //!< from AVStereo3D (2D: mono)
  std::optional<int> coverage_deg;          //!< from the equirect bounds (no bounds: 360)
  /// A tag vdfx does not show (a frame-sequential or checkerboard stereo, a cubemap): the
  /// reason, for a warning; the video is then shown as mono 360 unless overridden.
  std::string unsupported;
  bool operator==(const StereoTags&) const = default;
};

/// --layout and --coverage as given (empty: not given).
struct LayoutOverride {
  std::optional<effects::StereoMode> mode;
  std::optional<int> coverage_deg;
};

/// The stream's tags from its side data (libav). Throws io::InputError naming `file` for equirect
/// bounds that cover nothing; bounds other than a full or a centred half turn of azimuth over the
/// full altitude range are reported in `unsupported`.
StereoTags read_stereo_tags(const AVStream* stream, const std::string& file);

/// The layout of `video` for one command: each of mode and coverage from the command line when
/// given, else from the stream's tags, else from the sidecar's `video` section (`sidecar` may be
/// null), else mono 360. Throws io::InputError (exit 1) naming the file and the field when the
/// sidecar records a layout or coverage that the stream's tags contradict (a stereo sidecar over
/// a video tagged mono), or when the layout does not divide the frame. `hint` (may be null)
/// receives a one-line hint for an untagged frame whose shape suggests stereo shown as mono.
effects::StereoLayout resolve_video_layout(const VideoProperties& video, const LayoutOverride& cli,
                                           const VideoInfo* sidecar,
                                           const std::filesystem::path& sidecar_path,
                                           std::string* hint = nullptr);

/// Records `layout` in a sidecar's `video` section (what the editor shows, so that every player
/// shows the same: docs/stereo.md); a mono 360 layout where nothing was recorded leaves the
/// section as it was (old files stay byte for byte).
void record_layout(VideoInfo& video, const effects::StereoLayout& layout);

}  // namespace vdfx::io
