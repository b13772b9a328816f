/// @file
/// @brief Writing a whole file atomically: readers see the old bytes or the new, never a mix.
#pragma once

#include <filesystem>
#include <string_view>

namespace vdfx::io {

/// Replaces `path` with `bytes` atomically (POSIX): writes a temporary file in the same folder,
/// flushes and fsyncs it, renames it over `path`, then fsyncs the folder so the rename itself
/// survives a crash. On any failure the old file is untouched, the temporary file is removed and
/// io::InputError is thrown naming `path` and the reason (the path is the user's choice, so a
/// failure is reported like bad input). A new file gets mode 0666 minus the umask; an existing
/// file keeps its mode.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace vdfx::io
