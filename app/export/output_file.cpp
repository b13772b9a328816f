/// @file
/// @brief PendingOutput (temporary file + atomic rename) and InterruptGuard (SIGINT/SIGTERM).
#include "app/export/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <string>

#include "io/atomic_file.h"
#include "io/durable.h"
#include "io/file_lock.h"
#include "io/input_error.h"

namespace vdfx::app {
namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};

extern "C" void on_signal(int sig) {
  g_signal.store(sig);
  g_interrupted.store(true);
}

struct sigaction g_old_int {
}, g_old_term{};

}  // namespace

PendingOutput::PendingOutput(std::filesystem::path target) : target_(std::move(target)) {
  const std::filesystem::path dir = target_.parent_path().empty() ? "." : target_.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw io::InputError("cannot write " + target_.string() + ": folder " + dir.string() +
                         " does not exist");
  if (std::filesystem::is_directory(target_, ec))
    throw io::InputError("cannot write " + target_.string() + ": it is a folder");
  io::check_not_locked_by_another(target_);
  // An export killed by SIGKILL (or a crash) cannot remove its temporary file: the next export
  // to the same name does, once that process is gone.
  const std::string prefix = "." + target_.stem().string() + ".tmp-";
  io::remove_stale_temps(dir, prefix, target_.extension().string(), false);
  temp_ = dir / (prefix + std::to_string(::getpid()) + target_.extension().string());
}

PendingOutput::~PendingOutput() {
  if (!committed_) ::unlink(temp_.c_str());
}

void PendingOutput::commit() {
  struct stat old {};
  if (::stat(target_.c_str(), &old) == 0) ::chmod(temp_.c_str(), old.st_mode & 07777);
  // Best effort, as before the rename: the encoder has already closed the file.
  io::fsync_written_file(temp_);
  if (::rename(temp_.c_str(), target_.c_str()) != 0)
    throw io::InputError("cannot write " + target_.string() + ": rename from " + temp_.string() +
                         " failed: " + std::strerror(errno));
  committed_ = true;
  io::fsync_folder_entry(target_.parent_path());
}

InterruptGuard::InterruptGuard() {
  g_interrupted = false;
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  if (const int sig = g_signal.load()) std::raise(sig);
}

const std::atomic<bool>& InterruptGuard::interrupted() const {
  return g_interrupted;
}
int InterruptGuard::signal() const {
  return g_signal.load();
}

}  // namespace vdfx::app
