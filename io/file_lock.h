/// @file
/// @brief One writer per file: a lock file beside it (NAME.lock) that says which process has the
/// file open for writing: process id, host, when it started and what it is ("vdfx edit"), the
/// convention of editors and office suites (docs/reliability.md, "One author per file").
///
/// The lock is advisory: vdfx's own writers look for it (io::write_file_atomic refuses to
/// replace a file another live process holds), other programs do not. A lock whose process is
/// gone (same host, no such process, or the id now belongs to a process started later) is stale
/// (or a zombie) and may be taken over; a lock from another host cannot be checked and counts as
/// held.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "io/emergency_unlink.h"

namespace vdfx::io {

/// Who holds a lock, as its file says.
struct LockOwner {
  long pid = 0;
  std::string host;
  std::string started;                   //!< UTC, ISO 8601 ("2026-12-02T14:05:09Z")
  std::string command;                   //!< "vdfx edit"
  unsigned long long process_start = 0;  //!< the process's start time (/proc/PID/stat), 0: unknown

  /// "vdfx edit (process 4242 on host, since 2026-12-02T14:05:09Z)".
  std::string describe() const;
};

/// NAME.lock beside `file`.
std::filesystem::path lock_path(const std::filesystem::path& file);

/// The lock of `file`, if there is one and it can be read (an unreadable or malformed lock file
/// gives an owner with pid 0 and host "unknown": held, by someone vdfx cannot name).
std::optional<LockOwner> read_lock(const std::filesystem::path& file);

/// Whether the owner's process still exists: false only when it is on this host and its process
/// id is free, a zombie (killed and not yet reaped) or taken by a process started after the lock
/// was (a reused id).
bool owner_alive(const LockOwner& owner);

/// Throws io::InputError naming `file`, its lock and the owner when another live process holds
/// `file`'s lock (this process's own lock, a stale lock and no lock all pass). `role` names the
/// output in the message ("--sidecar-out").
void check_not_locked_by_another(const std::filesystem::path& file, const std::string& role = "");

/// A held lock: created by acquire(), removed by the destructor (only while the lock file is
/// still this process's), or at a hard stop by io::emergency_unlink_all (only while it still
/// holds what this process wrote).
class FileLock {
 public:
  struct Result;
  /// Tries to take `file`'s lock for `command`. A stale lock is taken over (Result::took_over
  /// names its owner); a lock held by a live process is left alone (Result::held_by). Throws
  /// io::InputError when the lock file cannot be written (a read-only folder, say).
  static Result acquire(const std::filesystem::path& file, const std::string& command);

  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&& other) noexcept;  //!< releases this one's lock first
  FileLock(const FileLock&) = delete;
  ~FileLock();
  const std::filesystem::path& path() const { return lock_; }

 private:
  FileLock(std::filesystem::path lock, std::string_view text)
      : lock_(std::move(lock)), emergency_(lock_, text) {}
  void release() noexcept;
  std::filesystem::path lock_;
  EmergencyUnlink emergency_;  //!< the lock in the table a second Ctrl-C empties
};

struct FileLock::Result {
  std::optional<FileLock> lock;        //!< set when taken
  std::optional<LockOwner> held_by;    //!< set when another live process holds it
  std::optional<LockOwner> took_over;  //!< a stale lock that was replaced
};

}  // namespace vdfx::io
