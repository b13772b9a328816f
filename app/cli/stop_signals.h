/// @file
/// @brief How a long command stops on SIGINT (Ctrl-C), SIGTERM (a session manager, `timeout`, a
/// logout) and SIGHUP (its terminal closed): the one mechanism every long command shares
/// (docs/cli.md, "Stopping a command").
///
/// While a StopSignals lives, those signals do not end the process: an async-signal-safe handler
/// records the signal and sets a flag. The command's loops poll the flag (or take it where they
/// take a cancel flag), finish what they are doing (the frame, the row, the sample), close what
/// they write and leave through their ordinary way out, destructors included, so every lock is
/// released. When the command has returned, the media module ends the process by that same
/// signal (end_by_stop_signal), so a shell sees 128 + N and a script stops as it does for any
/// program killed by Ctrl-C.
///
/// A second stop signal within two seconds of the one before ends the process at once, from the
/// handler: it removes what io::EmergencyUnlink holds (locks, an export's temporary file), says so
/// on stderr and ends by the signal.
///
/// How a command hooks in:
///   - its cmd_ function makes a StopSignals before its work (they nest: an export inside a
///     publish shares the publish's);
///   - a loop polls stop_requested() (or StopSignals::flag(), passed where a cancel flag is taken:
///     the export pipeline, FrameLoopOptions::stop);
///   - a loop that already stops on a cancel flag of its own (suggest::Progress::cancel, and
///   track's
///     the same way) links it with CancelOnStop, and turns the cancellation into Stopped;
///   - what stopped throws Stopped (or returns, saying what it kept); run_guarded prints
///     "vdfx NAME: stopped by SIGINT: WHAT" for a Stopped.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

namespace vdfx::app {

class StopSignals {
 public:
  /// The outermost one clears the flag and installs the handler for SIGINT, SIGTERM and SIGHUP;
  /// inner ones share it. Made and destroyed on the main thread.
  StopSignals();
  /// The outermost one puts the previous handlers back and clears the flag (a signal that came
  /// stays recorded: stop_signal()).
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// The flag the handler sets: what long loops poll.
  static const std::atomic<bool>& flag();
};

/// Whether a stop signal came while the StopSignals live (the flag).
bool stop_requested();
/// The first stop signal since the outermost StopSignals was made (0: none); it stays after they
/// are gone.
int stop_signal();
/// "SIGINT", "SIGTERM", "SIGHUP" (else "signal N").
std::string signal_name(int sig);
/// "stopped by SIGINT" (the signal that came).
std::string stopped_by();

/// While alive, a stop signal also sets `flag` (a Progress::cancel the loop already polls). At
/// most kMaxCancelFlags at once; made on the main thread.
class CancelOnStop {
 public:
  static constexpr int kMaxCancelFlags = 8;
  explicit CancelOnStop(std::atomic<bool>& flag);
  ~CancelOnStop();
  CancelOnStop(const CancelOnStop&) = delete;
  CancelOnStop& operator=(const CancelOnStop&) = delete;

 private:
  int slot_ = -1;
};

/// Thrown by a command's work when a stop signal stopped it; the message says what was kept or
/// left as it was ("nothing written; out.vdfx.json left as it was"). run_guarded reports it as
/// "vdfx NAME: stopped by SIGINT: MESSAGE".
class Stopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Returns `code` when no stop signal came; else flushes stdout and stderr and ends the process by
/// that signal (its default action: the shell sees 128 + N).
int end_by_stop_signal(int code);

}  // namespace vdfx::app
