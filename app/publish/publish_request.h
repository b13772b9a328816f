/// @file
/// @brief The work of `vdfx publish` as a library call: the command parses its options into a
/// PublishRequest and calls run_publish (tests call it without the command line).
/// docs/publish.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "effects/stereo_layout.h"
#include "io/video_layout.h"

namespace vdfx::app {

/// What `--transcode` re-encodes a video into when browsers cannot play its codec.
enum class Transcode { None, H264, Vp9 };

struct PublishRequest {
  std::filesystem::path video;    //!< the equirect video
  std::filesystem::path sidecar;  //!< the effects (.vdfx.json)
  std::filesystem::path out;      //!< the folder to write (replaced whole when it exists)
  std::string title;              //!< the page's title; empty: the video's file name
  Transcode transcode = Transcode::None;
  io::LayoutOverride layout;  //!< --layout / --coverage (docs/stereo.md)
};

struct PublishResult {
  std::filesystem::path out;          //!< as named in the request
  std::vector<std::string> files;     //!< what the folder holds, relative, sorted
  std::string video_codec;            //!< the published video's codec ("h264", "vp9")
  bool transcoded = false;            //!< the video was re-encoded
  std::vector<std::string> left_out;  //!< effects of the sidecar the page does not draw
  effects::StereoLayout layout;       //!< what the page shows (player.json's video.layout)
  /// Set when the folder is in place but the fsync of its parent's entry failed (not yet
  /// durable); the command prints it and still succeeds.
  std::string warning;
};

/// The codecs every WebGL2 browser plays in the containers publish accepts (docs/publish.md).
bool browser_plays(const std::string& codec);

/// Checks the inputs before anything is written (io::InputError, exit 1: a sidecar that fails
/// validation with validate's own message, a video in a codec browsers do not play without
/// --transcode, naming the codec and the option; a stereo layout that does not divide the frame
/// or that contradicts the stream's tags, as io::resolve_video_layout reports it; an OUT that
/// is an input, a file, or a folder vdfx publish did not write), then builds the folder in a
/// temporary sibling and puts it in place with one atomic exchange: OUT holds the old folder or the
/// new one, never a mix.
PublishResult run_publish(const PublishRequest& request);

}  // namespace vdfx::app
