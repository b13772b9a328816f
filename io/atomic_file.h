/// @file
/// @brief Writing a whole file atomically: readers see the old bytes or the new, never a mix.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "io/output_path.h"

namespace vdfx::io {

/// Replaces `path` with `bytes` atomically (POSIX): writes a temporary file `.NAME.tmp-PID-N` in
/// the same folder, flushes and fsyncs it, renames it over `path`, then fsyncs the folder so the
/// rename itself survives a crash. On any failure before the rename the old file is untouched,
/// the temporary file is removed and io::InputError is thrown naming `path` and the reason (the
/// path is the user's choice, so a failure is reported like bad input); a failing fsync of the
/// folder after the rename is reported as such ("written, but not yet durable").
///
/// A symbolic link is written through: the file it names is replaced and the link kept. A
/// folder, device, named pipe or socket is refused (io/output_path.h), never replaced. Temporary
/// files of this name left by a writer that was killed (its PID no longer exists) are removed.
/// A new file gets mode 0666 minus the umask; an existing file keeps its mode. A file whose lock
/// (io/file_lock.h) another live process holds is refused (io::InputError naming the owner).
/// `name` says whether the user named this file (links followed) or vdfx made the name up (links
/// refused), io/output_path.h.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       OutputName name = OutputName::Given);

/// Removes what killed writers left in `dir`: files named `prefix` PID `suffix` (with `numbered`:
/// `prefix` PID-N `suffix`), exactly that form, and only when no process PID exists on this
/// machine (a live writer's file, this process's included, is never touched). Best effort: a
/// file that cannot be removed is left.
void remove_stale_temps(const std::filesystem::path& dir, const std::string& prefix,
                        const std::string& suffix, bool numbered);

}  // namespace vdfx::io
