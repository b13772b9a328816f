/// @file
/// @brief write_file_atomic: temporary file, fsync, rename, fsync of the folder.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "io/input_error.h"

namespace vdfx::io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
  throw InputError("cannot write " + path.string() + ": " + what + ": " + std::strerror(err));
}

/// Closes the descriptor and removes the temporary file unless released (the success path).
class TempFile {
 public:
  TempFile(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!released_) ::unlink(path_.c_str());
  }
  int fd() const { return fd_; }
  const std::filesystem::path& path() const { return path_; }
  /// Closes explicitly so that a failing close (NFS reports late write errors there) is seen.
  int close() {
    const int r = ::close(fd_);
    fd_ = -1;
    return r;
  }
  void release() { released_ = true; }

 private:
  std::filesystem::path path_;
  int fd_;
  bool released_ = false;
};

std::filesystem::path temp_name(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  // Hidden, in the same folder (rename is only atomic within one file system), unique per
  // process and call; O_EXCL below guards against anything left by another process.
  return path.parent_path() / ("." + path.filename().string() + ".tmp-" +
                               std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
  if (path.filename().empty()) throw InputError("cannot write " + path.string() + ": not a file name");
  const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();

  struct stat old {};
  const bool existed = ::stat(path.c_str(), &old) == 0;
  if (existed && S_ISDIR(old.st_mode)) fail(path, "it is a folder", EISDIR);

  const std::filesystem::path tmp_path = temp_name(path);
  const int fd = ::open(tmp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, "cannot create temporary file " + tmp_path.string(), errno);
  TempFile tmp(tmp_path, fd);

  if (existed && ::fchmod(tmp.fd(), old.st_mode & 07777) != 0)
    fail(path, "cannot keep the file's mode", errno);

  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(tmp.fd(), p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, "write failed", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(tmp.fd()) != 0) fail(path, "fsync failed", errno);
  if (tmp.close() != 0) fail(path, "close failed", errno);
  if (::rename(tmp.path().c_str(), path.c_str()) != 0) fail(path, "rename failed", errno);
  tmp.release();

  // The new name is only durable once the folder's entry is on disk too.
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd < 0) fail(path, "cannot open folder to fsync", errno);
  const int r = ::fsync(dfd);
  const int err = errno;
  ::close(dfd);
  if (r != 0) fail(path, "fsync of folder failed", err);
}

}  // namespace vdfx::io
