/// @file
/// @brief The hand-over of one background job's result to the editor's thread (the suggestion
/// and tracking workers): the job puts it once, the editor polls take() each frame, and tests wait
/// for it.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace vdfx::app {

template <class Outcome>
class WorkerResult {
 public:
  /// Called once by the job's thread when it ends (done, cancelled or failed).
  void put(Outcome outcome) {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = std::move(outcome);
    finished_ = true;
  }

  /// The outcome once, then nothing.
  std::optional<Outcome> take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::optional<Outcome> out = std::move(done_);
    done_.reset();
    return out;
  }

  /// Waits up to `timeout` for the job to end; true when it has.
  bool wait(std::chrono::milliseconds timeout) const {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      if (finished()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return finished();
  }

 private:
  bool finished() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return finished_;
  }

  mutable std::mutex mutex_;
  std::optional<Outcome> done_;
  bool finished_ = false;
};

}  // namespace vdfx::app
