/// @file
/// @brief A FrameDecoder that hands over one eye's image of a stereo video (docs/stereo.md):
/// for the analyses that see the video as one equirect sphere (`vdfx suggest`).
#pragma once

#include <memory>

#include "effects/stereo_layout.h"
#include "io/frame_decoder.h"

namespace vdfx::io {

/// `decoder` seen through `layout`: every frame is `eye`'s image (a copy, RGB as read()), the
/// properties' width and height are the eye's. Mono: `decoder` itself. The layout must divide
/// the frame (io::resolve_video_layout checks it).
std::unique_ptr<FrameDecoder> eye_decoder(std::unique_ptr<FrameDecoder> decoder,
                                          const effects::StereoLayout& layout,
                                          effects::EyeIndex eye);

}  // namespace vdfx::io
