/// @file
/// @brief write_file_atomic: temporary file, fsync, rename, fsync of the folder.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <string>

#include "io/durable.h"
#include "io/file_lock.h"
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

std::string temp_prefix(const std::filesystem::path& path) {
  return "." + path.filename().string() + ".tmp-";
}

std::filesystem::path temp_name(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  // Hidden, in the same folder (rename is only atomic within one file system), unique per
  // process and call; O_EXCL below guards against anything left by another process.
  return path.parent_path() /
         (temp_prefix(path) + std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

}  // namespace

void remove_stale_temps(const std::filesystem::path& dir, const std::string& prefix,
                        const std::string& suffix, bool numbered) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + suffix.size() ||
        name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const char* p = name.data() + prefix.size();
    const char* last = name.data() + name.size() - suffix.size();
    long pid = 0;
    const auto a = std::from_chars(p, last, pid);
    if (a.ec != std::errc() || pid <= 0) continue;
    if (numbered) {
      unsigned long n = 0;
      if (a.ptr == last || *a.ptr != '-') continue;
      const auto b = std::from_chars(a.ptr + 1, last, n);
      if (b.ec != std::errc() || b.ptr != last) continue;
    } else if (a.ptr != last) {
      continue;
    }
    if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    std::filesystem::remove(it->path(), ignored);
  }
}

void write_file_atomic(const std::filesystem::path& user_path, std::string_view bytes,
                       OutputName name) {
  if (user_path.filename().empty())
    throw InputError("cannot write " + user_path.string() + ": not a file name");
  // Through a symbolic link to the file it names (the link stays a link); devices, pipes and
  // folders are refused rather than replaced by a regular file.
  const std::filesystem::path path = resolve_output_path(user_path, name);
  // A file another editor has open (its lock beside it) is that author's: never replaced.
  check_not_locked_by_another(user_path);
  if (path != user_path) check_not_locked_by_another(path);
  const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();

  struct stat old {};
  const bool existed = ::stat(path.c_str(), &old) == 0;
  remove_stale_temps(dir, temp_prefix(path), "", true);

  const std::filesystem::path tmp_path = temp_name(path);
  const int fd = ::open(tmp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(user_path, "cannot create temporary file " + tmp_path.string(), errno);
  TempFile tmp(tmp_path, fd);

  if (existed && ::fchmod(tmp.fd(), old.st_mode & 07777) != 0)
    fail(user_path, "cannot keep the file's mode", errno);

  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(tmp.fd(), p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(user_path, "write failed", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(tmp.fd()) != 0) fail(user_path, "fsync failed", errno);
  if (tmp.close() != 0) fail(user_path, "close failed", errno);
  if (::rename(tmp.path().c_str(), path.c_str()) != 0) fail(user_path, "rename failed", errno);
  tmp.release();

  // The new name is only durable once the folder's entry is on disk too. The file is already
  // replaced here, so a failure says so instead of "cannot write". File systems that cannot sync
  // a folder at all (EINVAL) are taken as synced.
  const int err = fsync_folder_entry(dir);
  if (err != 0 && err != EINVAL)
    throw InputError(user_path.string() +
                     ": written, but not yet durable: the fsync of its folder " + dir.string() +
                     " failed (" + std::strerror(err) +
                     "); a power cut now could still lose the new contents");
}

}  // namespace vdfx::io
