/// @file
/// @brief --layout and --coverage, the options of every command that reads a video (contract,
/// "Command line"; docs/stereo.md): they override the stream's stereo and spherical tags.
#pragma once

#include <CLI/CLI.hpp>

#include "io/video_layout.h"

namespace vdfx::app {

/// Adds --layout mono|top-bottom|left-right|right-left and --coverage 360|180 to `cli`, parsed
/// into `out` (which must outlive the parse).
void add_layout_options(CLI::App& cli, io::LayoutOverride& out);

}  // namespace vdfx::app
