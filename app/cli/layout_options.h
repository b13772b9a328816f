/// @file
/// @brief --layout and --coverage, the options of every command that reads a video (contract,
/// "Command line"; docs/stereo.md): they override the stream's stereo and spherical tags.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>

#include "io/video_layout.h"

namespace vdfx::app {

/// Adds --layout mono|top-bottom|left-right|right-left and --coverage 360|180 to `cli`, parsed
/// into `out` (which must outlive the parse).
void add_layout_options(CLI::App& cli, io::LayoutOverride& out);

/// The layout `video` is shown with (io::resolve_video_layout) by a command that also read the
/// sidecar at `sidecar_path` whose `video` section is `recorded` (null: no sidecar). Prints on
/// standard error the hint for an untagged frame shaped like stereo, and a warning when the
/// video is not the one the sidecar was made for (io::video_mismatch: size, frames, fps).
effects::StereoLayout shown_layout(const io::VideoProperties& video, const io::LayoutOverride& cli,
                                   const io::VideoInfo* recorded,
                                   const std::filesystem::path& sidecar_path);

}  // namespace vdfx::app
