/// @file
/// @brief The output of an export: written to a temporary file beside the target and renamed
/// over it only when complete, so Ctrl-C, a kill or a crash leaves the previous file untouched.
/// (A stop signal is the command's: app/cli/stop_signals.h.)
#pragma once

#include <filesystem>

#include "io/emergency_unlink.h"

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
  io::EmergencyUnlink emergency_;  //!< a second Ctrl-C removes the temporary file too
  bool committed_ = false;
};

}  // namespace vdfx::app
