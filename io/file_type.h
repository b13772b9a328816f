/// @file
/// @brief Names of the kinds of file a path can be, for messages that refuse anything but a
/// regular file (a folder, a device, a named pipe, a socket).
#pragma once

#include <sys/types.h>

namespace vdfx::io {

/// "a folder", "a character device", "a block device", "a named pipe (FIFO)", "a socket",
/// "a symbolic link", or "a regular file", from a stat() mode.
const char* file_type_name(mode_t mode);

}  // namespace vdfx::io
