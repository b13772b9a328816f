/// @file
/// @brief open_frame_decoder: picks the still or the video backend by file name.
#include "io/frame_decoder.h"

#include <limits>

#include "io/image_source.h"
#include "io/input_error.h"
#include "io/input_file.h"

namespace vdfx::io {

std::unique_ptr<FrameDecoder> open_frame_decoder(const std::filesystem::path& path,
                                                 const DecoderOptions& options) {
  // A regular file only: a named pipe with no writer would block the backends forever.
  check_input_file(path, std::numeric_limits<std::uintmax_t>::max(), "a video or image");
  if (is_still_image_path(path)) return create_still_decoder(path, options);
  return create_libav_decoder(path, options);
}

}  // namespace vdfx::io
