/// @file
/// @brief MinimapWorker: one thread, one queued job (latest wins), one finished result.
#include "app/editor/minimap_worker.h"

#include "app/editor/visualizations.h"

namespace vdfx::app {

MinimapWorker::MinimapWorker(Compute compute) : compute_(std::move(compute)) {
  if (!compute_)
    compute_ = [](const MinimapJob& j, const std::atomic<bool>& cancel) {
      return effect_minimap(j.rbf.get(), j.type, j.frame, j.width, j.height, &cancel, j.anchor);
    };
  thread_ = std::thread([this] { run(); });
}

MinimapWorker::~MinimapWorker() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
    queued_.reset();
  }
  cancel_ = true;
  cv_.notify_all();
  thread_.join();
}

std::uint64_t MinimapWorker::request(MinimapJob job) {
  std::uint64_t serial = 0;
  {
    std::lock_guard lock(mu_);
    if (queued_) ++coalesced_;
    serial = next_serial_++;
    queued_.emplace(serial, std::move(job));
  }
  cv_.notify_one();
  return serial;
}

std::optional<MinimapResult> MinimapWorker::take() {
  std::lock_guard lock(mu_);
  std::optional<MinimapResult> r = std::move(done_);
  done_.reset();
  return r;
}

bool MinimapWorker::wait_idle(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mu_);
  return idle_cv_.wait_for(lock, timeout, [&] { return !queued_ && !busy_; });
}

std::uint64_t MinimapWorker::computed() const {
  std::lock_guard lock(mu_);
  return computed_;
}

std::uint64_t MinimapWorker::coalesced() const {
  std::lock_guard lock(mu_);
  return coalesced_;
}

void MinimapWorker::run() {
  for (;;) {
    std::pair<std::uint64_t, MinimapJob> job;
    {
      std::unique_lock lock(mu_);
      cv_.wait(lock, [&] { return stop_ || queued_.has_value(); });
      if (stop_) return;
      job = std::move(*queued_);
      queued_.reset();
      busy_ = true;
    }
    cv::Mat field = compute_(job.second, cancel_);
    {
      std::lock_guard lock(mu_);
      busy_ = false;
      // Serials grow, so a finished field always supersedes the one not yet taken.
      if (!field.empty() && !stop_) {
        done_ = MinimapResult{job.first, job.second.key, std::move(field)};
        ++computed_;
      }
    }
    idle_cv_.notify_all();
  }
}

}  // namespace vdfx::app
