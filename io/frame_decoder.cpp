/// @file
/// @brief open_frame_decoder: picks the still or the video backend by file name.
#include "io/frame_decoder.h"

#include "io/image_source.h"
#include "io/input_error.h"

namespace vdfx::io {

std::unique_ptr<FrameDecoder> open_frame_decoder(const std::filesystem::path& path,
                                                 const DecoderOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path.string() + ": is a folder, not a video or image");
  if (is_still_image_path(path)) return create_still_decoder(path, options);
  return create_libav_decoder(path, options);
}

}  // namespace vdfx::io
