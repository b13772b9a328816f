/// @file
/// @brief The output of an export: written to a temporary file beside the target and renamed
/// over it only when complete, so Ctrl-C, a kill or a crash leaves the previous file untouched;
/// and the SIGINT/SIGTERM handling that lets an export stop cleanly.
#pragma once

#include <atomic>
#include <filesystem>

namespace vdfx::app {

class PendingOutput {
 public:
  /// Reserves ".NAME.tmp-PID.EXT" beside `target` (same folder: the rename is atomic; the
  /// extension kept so tools can tell the format). Throws io::InputError naming `target` when
  /// its folder is missing, it is a folder, or another live process holds its lock
  /// (io/file_lock.h).
  explicit PendingOutput(std::filesystem::path target);
  ~PendingOutput();  //!< removes the temporary file unless committed
  PendingOutput(const PendingOutput&) = delete;
  PendingOutput& operator=(const PendingOutput&) = delete;

  const std::filesystem::path& temp() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }
  /// fsync, rename over the target (keeping an existing target's mode), fsync the folder.
  void commit();

 private:
  std::filesystem::path target_, temp_;
  bool committed_ = false;
};

/// While alive, SIGINT and SIGTERM only set a flag (the pipeline polls it and stops); the
/// destructor restores the previous handlers and, when a signal came, re-raises it so that the
/// process ends the way the shell expects (after the caller has cleaned up).
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  const std::atomic<bool>& interrupted() const;
  /// The signal that arrived (0: none).
  int signal() const;
};

}  // namespace vdfx::app
