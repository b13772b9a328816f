/// @file
/// @brief Computes the editor's effect minimap (app/editor/visualizations.h) on a worker thread, so
/// the frame thread never waits for it (36 ms at N = 1000 keyframes, docs/editor.md).
///
/// Latest request wins: a request made while another waits replaces it (the replaced one is
/// never computed); the one being computed runs to its end. Every finished field is published
/// with the key and serial of its request; take() hands the newest one over once and drops
/// older ones. No clock is read: callers decide what a result is still good for by its key.
///
/// Threads: request(), take() and wait_idle() from one thread (the editor's frame thread); the
/// computation on the worker. The destructor cancels a computation in progress (the compute
/// function polls the flag it is given) and joins.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <thread>

#include "app/editor/edit_target.h"
#include "effects/anchor.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::app {

/// What a minimap field was computed for: the document revision, the solution version, the
/// effect and the frame, and (while a keyframe is held away from its place) which placement of
/// the held keyframe: the field is then the live preview's interpolant.
struct MinimapKey {
  std::uint64_t revision = ~0ull, solutions = 0;
  int effect = -1;
  std::int64_t frame = -1;
  std::uint64_t preview = 0;  //!< 0: the document's solution; else a serial of the held placement
  bool operator==(const MinimapKey&) const = default;
};

struct MinimapJob {
  MinimapKey key;
  std::shared_ptr<const effects::RbfInterpolator> rbf;  //!< null: neutral everywhere
  EditTarget type = effects::EffectType::Exposure;
  std::int64_t frame = 0;
  int width = 128, height = 64;
  effects::AnchorFrames anchor;  //!< the effect's: turns each cell's direction at `frame`
};

struct MinimapResult {
  std::uint64_t serial = 0;  //!< request() returned it: later requests have larger serials
  MinimapKey key;
  cv::Mat field;  //!< CV_32FC1, as effect_minimap
};

class MinimapWorker {
 public:
  /// Computes one field; returns an empty Mat when `cancel` became true (the result is dropped).
  using Compute = std::function<cv::Mat(const MinimapJob&, const std::atomic<bool>& cancel)>;
  /// `compute` defaults to effect_minimap (cancellable between rows); tests inject their own.
  explicit MinimapWorker(Compute compute = {});
  ~MinimapWorker();
  MinimapWorker(const MinimapWorker&) = delete;
  MinimapWorker& operator=(const MinimapWorker&) = delete;

  /// Queues `job`, replacing a queued one that has not started. Returns its serial.
  std::uint64_t request(MinimapJob job);
  /// The newest finished result not taken yet (older finished ones are dropped); never blocks.
  std::optional<MinimapResult> take();
  /// Blocks until nothing is queued or being computed; false on timeout (tests, replays).
  bool wait_idle(std::chrono::milliseconds timeout);

  /// Fields computed, and requests replaced before they started (coalesced).
  std::uint64_t computed() const;
  std::uint64_t coalesced() const;

 private:
  void run();

  Compute compute_;
  mutable std::mutex mu_;
  std::condition_variable cv_;       //!< wakes the worker: a job or stop
  std::condition_variable idle_cv_;  //!< wakes wait_idle
  std::optional<std::pair<std::uint64_t, MinimapJob>> queued_;
  bool busy_ = false, stop_ = false;
  std::atomic<bool> cancel_{false};
  std::optional<MinimapResult> done_;
  std::uint64_t next_serial_ = 1, computed_ = 0, coalesced_ = 0;
  std::thread thread_;  // last: starts after the members it uses exist
};

}  // namespace vdfx::app
