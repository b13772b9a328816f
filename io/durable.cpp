/// @file
/// @brief fsync of a folder's entry, of a written file, of a folder tree vdfx wrote.
#include "io/durable.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace vdfx::io {

namespace fs = std::filesystem;

namespace {

/// fsync of an open descriptor, closed after; 0 or the errno.
int sync_and_close(int fd) {
  const int r = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  return r == 0 ? 0 : err;
}

}  // namespace

std::string SyncFailure::describe() const {
  return path.string() + ": " + std::strerror(error);
}

int fsync_folder_entry(const fs::path& dir) {
  const fs::path d = dir.empty() ? fs::path(".") : dir;
  // O_DIRECTORY: should something else have taken the name, the open fails instead of opening
  // it (a named pipe would block here).
  const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno;
  return sync_and_close(fd);
}

int fsync_written_file(const fs::path& path) {
  // O_NONBLOCK and O_NOFOLLOW: a pipe or a link that took the file's place is not waited on or
  // followed; fstat then refuses anything but a regular file.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return errno;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return ENOTSUP;
  }
  return sync_and_close(fd);
}

std::optional<SyncFailure> fsync_written_tree(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> folders;
  // directory_options::none: a link to a folder is not entered.
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec)) {
    const fs::file_type type = it->symlink_status(ec).type();
    if (ec) return SyncFailure{it->path(), ec.value()};
    if (type == fs::file_type::directory) {
      folders.push_back(it->path());
    } else if (type == fs::file_type::regular) {
      if (const int err = fsync_written_file(it->path())) return SyncFailure{it->path(), err};
    }
  }
  if (ec) return SyncFailure{dir, ec.value()};
  folders.insert(folders.begin(), dir);
  for (auto f = folders.rbegin(); f != folders.rend(); ++f) {
    const int err = fsync_folder_entry(*f);
    if (err != 0 && err != EINVAL) return SyncFailure{*f, err};
  }
  return std::nullopt;
}

}  // namespace vdfx::io
