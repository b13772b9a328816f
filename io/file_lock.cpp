/// @file
/// @brief FileLock: NAME.lock made complete in a temporary file and linked into place (link()
/// fails atomically when the lock exists, and a reader never sees half a lock).
#include "io/file_lock.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/input_error.h"
#include "io/input_file.h"

namespace vdfx::io {
namespace fs = std::filesystem;
namespace {

/// Lock files hold one short JSON object; anything larger is not one of vdfx's.
constexpr std::uintmax_t kMaxLockBytes = 64 * 1024;

std::string this_host() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0) return "localhost";
  return buf;
}

/// From /proc/PID/stat: the state (field 3: 'Z' a zombie, dead but not yet reaped) and when the
/// process started (field 22, clock ticks after boot). Start 0: unknown.
struct ProcessStat {
  char state = '?';
  unsigned long long start = 0;
};
ProcessStat process_stat(long pid) {
  ProcessStat st;
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return st;
  // The command name (field 2) is in parentheses and may hold spaces: count after the last ')'.
  const auto close = line.rfind(')');
  if (close == std::string::npos) return st;
  std::istringstream rest(line.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22; ++i) {
    if (!(rest >> field)) return st;
    if (i == 3) st.state = field.empty() ? '?' : field[0];
  }
  try {
    st.start = std::stoull(field);
  } catch (...) {
    st.start = 0;
  }
  return st;
}
unsigned long long process_start(long pid) {
  return process_stat(pid).start;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

/// The whole lock file, or nothing when it cannot be read (gone, or not a regular file).
std::optional<std::string> slurp(const fs::path& p) {
  std::string why;
  return try_read_input_file(p, kMaxLockBytes, "a lock file", why);
}

LockOwner parse_owner(const std::string& text) {
  LockOwner o;
  o.host = "unknown";
  const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || j.value("format", "") != "vdfx.lock") return o;
  try {
    o.pid = j.at("pid").get<long>();
    o.host = j.at("host").get<std::string>();
    o.started = j.value("started", "");
    o.command = j.value("command", "");
    o.process_start = j.value("process_start", 0ULL);
  } catch (const std::exception&) {
    o = LockOwner{};
    o.host = "unknown";
  }
  return o;
}

/// Writes all of `text` to a new file; false with errno set on failure (the file is removed).
bool write_new_file(const fs::path& p, const std::string& text) {
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      ::unlink(p.c_str());
      errno = err;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const int err = errno;
    ::unlink(p.c_str());
    errno = err;
    return false;
  }
  return true;
}

[[noreturn]] void cannot_lock(const fs::path& file, const fs::path& lock, int err) {
  throw InputError("cannot open " + file.string() + " for writing: cannot create its lock " +
                   lock.string() + " (" + std::strerror(err) + ")");
}

}  // namespace

std::string LockOwner::describe() const {
  if (pid <= 0) return "an unknown program (the lock file cannot be read)";
  return (command.empty() ? std::string("a program") : command) + " (process " +
         std::to_string(pid) + " on " + host + (started.empty() ? "" : ", since " + started) + ")";
}

fs::path lock_path(const fs::path& file) {
  fs::path p = file;
  p += ".lock";
  return p;
}

std::optional<LockOwner> read_lock(const fs::path& file) {
  const fs::path lock = lock_path(file);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(lock, ec))) return std::nullopt;
  const auto text = slurp(lock);
  if (!text) {
    LockOwner o;
    o.host = "unknown";
    return o;
  }
  return parse_owner(*text);
}

bool owner_alive(const LockOwner& owner) {
  if (owner.pid <= 0 || owner.host != this_host()) return true;  // cannot tell: held
  if (::kill(static_cast<pid_t>(owner.pid), 0) != 0 && errno == ESRCH) return false;
  // The id exists; it is the lock's process only if that started when the lock says, and it is
  // not a zombie (killed, its parent not yet waiting for it: a container's init may never).
  const ProcessStat st = process_stat(owner.pid);
  if (st.state == 'Z' || st.state == 'X') return false;
  if (owner.process_start != 0 && st.start != 0 && st.start != owner.process_start) return false;
  return true;
}

void check_not_locked_by_another(const fs::path& file, const std::string& role) {
  const auto owner = read_lock(file);
  if (!owner) return;
  if (owner->pid == ::getpid() && owner->host == this_host()) return;
  if (!owner_alive(*owner)) return;
  throw InputError("refusing to write " + (role.empty() ? "" : role + " ") + file.string() +
                   ": it is open in " + owner->describe() + ", lock " + lock_path(file).string() +
                   "; close that editor first (or remove the lock if no editor has it open)");
}

FileLock::Result FileLock::acquire(const fs::path& file, const std::string& command) {
  const fs::path lock = lock_path(file);
  nlohmann::json j = {{"format", "vdfx.lock"}, {"pid", static_cast<long>(::getpid())},
                      {"host", this_host()},   {"started", utc_now()},
                      {"command", command},    {"process_start", process_start(::getpid())}};
  const std::string text = j.dump() + "\n";
  fs::path tmp = lock;
  tmp += ".tmp-" + std::to_string(::getpid());
  Result result;
  for (int attempt = 0; attempt < 4; ++attempt) {
    ::unlink(tmp.c_str());
    if (!write_new_file(tmp, text)) cannot_lock(file, lock, errno);
    int r = ::link(tmp.c_str(), lock.c_str());
    int err = errno;
    ::unlink(tmp.c_str());
    if (r != 0 && err != EEXIST) {
      // A file system without hard links: an exclusive create, written in place.
      if (write_new_file(lock, text)) {
        r = 0;
      } else {
        err = errno;
        if (err != EEXIST) cannot_lock(file, lock, err);
      }
    }
    if (r == 0) {
      result.lock.emplace(FileLock(lock, text));
      return result;
    }
    const auto before = slurp(lock);
    if (!before) continue;  // removed meanwhile: try again
    const LockOwner owner = parse_owner(*before);
    if (owner_alive(owner) && !(owner.pid == ::getpid() && owner.host == this_host())) {
      result.held_by = owner;
      return result;
    }
    // Stale (or this process's own, left by an earlier lock of the same file): removed only if
    // it is still the same lock, so a lock another process just took is not removed.
    if (slurp(lock) == before) {
      ::unlink(lock.c_str());
      if (owner.pid != ::getpid()) result.took_over = owner;
    }
  }
  cannot_lock(file, lock, EEXIST);
}

FileLock::FileLock(FileLock&& other) noexcept
    : lock_(std::move(other.lock_)), emergency_(std::move(other.emergency_)) {
  other.lock_.clear();
}

FileLock& FileLock::operator=(FileLock&& other) noexcept {
  if (this != &other) {
    release();
    lock_ = std::move(other.lock_);
    emergency_ = std::move(other.emergency_);
    other.lock_.clear();
  }
  return *this;
}

FileLock::~FileLock() {
  release();
}

void FileLock::release() noexcept {
  emergency_.reset();
  if (lock_.empty()) return;
  const auto text = slurp(lock_);
  if (!text) return;
  const LockOwner o = parse_owner(*text);
  if (o.pid == ::getpid() && o.host == this_host()) ::unlink(lock_.c_str());
  lock_.clear();
}

}  // namespace vdfx::io
