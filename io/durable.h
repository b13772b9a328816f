/// @file
/// @brief Making what vdfx wrote durable (fsync) without touching anything it did not write: a
/// folder's own entry list, a file vdfx wrote, a folder tree vdfx wrote itself. Nothing here
/// follows a symbolic link or opens anything but a regular file or a folder, so a named pipe
/// (which would block an open for ever) or a device is never opened (docs/reliability.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace vdfx::io {

/// fsync of the folder `dir` itself (its list of names: what makes a rename or a new name
/// survive a crash), opened with O_DIRECTORY; never its contents. 0 when synced, else the errno
/// (EINVAL: the file system cannot sync a folder; callers take that as synced).
int fsync_folder_entry(const std::filesystem::path& dir);

/// fsync of the regular file `path` (a file vdfx wrote), opened without following a link and
/// without blocking; 0 when synced, else the errno (ENOTSUP for anything but a regular file, which
/// is not synced).
int fsync_written_file(const std::filesystem::path& path);

/// The first failure of fsync_written_tree: the path and the errno.
struct SyncFailure {
  std::filesystem::path path;
  int error = 0;
  std::string describe() const;  //!< "PATH: Input/output error"
};

/// fsync of every regular file and folder of `dir`, a folder tree vdfx wrote itself (a staging
/// folder, never one of the user's: the walk is for vdfx's own folders only), deepest first, then
/// `dir` itself. Symbolic links are not followed and anything but regular files and folders is
/// left alone. Folders the file system cannot sync (EINVAL) count as synced. Returns the first
/// failure, or nothing when everything was synced.
std::optional<SyncFailure> fsync_written_tree(const std::filesystem::path& dir);

}  // namespace vdfx::io
