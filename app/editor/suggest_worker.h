/// @file
/// @brief The editor's "Suggest" (docs/suggest.md, "In the editor"): one suggestion
/// (app/suggest/suggest.h) run off the frame thread on a copy of the document's sidecar, with
/// its progress and a cancel. The editor takes the result when it is done and adds its keyframes
/// as one undo step; a cancelled or failed suggestion leaves the document untouched.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/editor/edit_target.h"
#include "app/editor/worker_result.h"
#include "app/suggest/suggest.h"
#include "io/sidecar.h"

namespace vdfx::app {

/// What a finished suggestion left: the sidecar with the suggestion added, or why there is none.
struct SuggestOutcome {
  std::optional<io::Sidecar> sidecar;  //!< the copy with the suggested keyframes
  suggest::SuggestReport report;
  std::string problem;     //!< why there is no sidecar ("" when there is one)
  bool cancelled = false;  //!< stopped by cancel()
};

/// What "Suggest" proposes for an effect: exposure: exposure adaptation (metering); saturation:
/// gaze guidance toward the view centre; vignette: the comfort vignette from the camera's motion;
/// nullopt for the others.
std::optional<suggest::Kind> suggestion_for(EditTarget target);
/// The button's words: "Suggest exposure", "Suggest guidance", "Suggest comfort".
std::string suggestion_title(suggest::Kind kind);

class SuggestWorker {
 public:
  /// Starts the suggestion on `sidecar` (a copy) on a thread of its own; `async` false runs it
  /// here, before the constructor returns (replays are exact).
  SuggestWorker(suggest::SuggestRequest request, io::Sidecar sidecar, bool async = true);
  /// Cancels and joins.
  ~SuggestWorker();
  SuggestWorker(const SuggestWorker&) = delete;
  SuggestWorker& operator=(const SuggestWorker&) = delete;

  const suggest::SuggestRequest& request() const { return request_; }
  /// 0..1, as the suggestion reports it.
  double fraction() const { return progress_.fraction.load(); }
  /// Asks the suggestion to stop; it then ends cancelled (unless it had already finished).
  void cancel() { progress_.cancel.store(true); }
  /// The outcome once the suggestion has ended (then once only); nullopt before and after.
  std::optional<SuggestOutcome> take();
  /// Blocks until the suggestion has ended (tests); false on timeout.
  bool wait(std::chrono::milliseconds timeout);

 private:
  void run(io::Sidecar sidecar);

  suggest::SuggestRequest request_;
  suggest::Progress progress_;
  WorkerResult<SuggestOutcome> result_;
  std::thread thread_;
};

}  // namespace vdfx::app
