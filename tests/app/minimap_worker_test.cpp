/// @file
/// @brief MinimapWorker: fields equal effect_minimap; requests queued behind a busy worker
/// coalesce (latest wins); an older finished field is dropped for a newer one; shutdown while
/// busy cancels and joins; the editor with visuals.async shows the same fields as the
/// synchronous one once the worker caught up, and never blocks update() on it.
#include "app/editor/minimap_worker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using namespace std::chrono_literals;

bool same_field(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

MinimapJob job_at(std::int64_t frame,
                  std::shared_ptr<const effects::RbfInterpolator> rbf = nullptr) {
  MinimapJob j;
  j.key.frame = frame;
  j.key.effect = static_cast<int>(EffectType::Exposure);
  j.frame = frame;
  j.rbf = std::move(rbf);
  j.width = 16;
  j.height = 8;
  return j;
}

/// A compute function that records the frames it was asked for and, while `hold` is set, waits
/// (polling the cancel flag) before answering a field filled with the frame number.
struct Gate {
  std::mutex mu;
  std::vector<std::int64_t> started;
  std::atomic<bool> hold{true}, saw_cancel{false};
  MinimapWorker::Compute compute() {
    return [this](const MinimapJob& j, const std::atomic<bool>& cancel) {
      {
        std::lock_guard lock(mu);
        started.push_back(j.frame);
      }
      while (hold && !cancel) std::this_thread::sleep_for(1ms);
      if (cancel) {
        saw_cancel = true;
        return cv::Mat();
      }
      return cv::Mat(j.height, j.width, CV_32FC1, cv::Scalar(static_cast<double>(j.frame)));
    };
  }
  std::size_t started_count() {
    std::lock_guard lock(mu);
    return started.size();
  }
  void wait_started(std::size_t n) {
    for (int i = 0; i < 5000 && started_count() < n; ++i) std::this_thread::sleep_for(1ms);
    ASSERT_GE(started_count(), n);
  }
};

TEST(MinimapWorker, ComputesTheFieldOfItsRequestWithKeyAndSerial) {
  const auto rbf = std::make_shared<const effects::RbfInterpolator>(
      std::vector<effects::Keyframe>{{{30.0, 0.0}, 0, {2.0}}, {{-60.0, 20.0}, 10, {-1.0}}}, 1,
      effects::InterpolationSettings{}, 30.0);
  MinimapWorker w;
  EXPECT_FALSE(w.take());
  const auto serial = w.request(job_at(5, rbf));
  ASSERT_TRUE(w.wait_idle(10s));
  const auto r = w.take();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->serial, serial);
  EXPECT_EQ(r->key, job_at(5).key);
  EXPECT_TRUE(same_field(r->field, effect_minimap(rbf.get(), EffectType::Exposure, 5, 16, 8)));
  EXPECT_FALSE(w.take());  // handed over once
  EXPECT_EQ(w.computed(), 1u);
}

TEST(MinimapWorker, RequestsBehindABusyWorkerCoalesceAndTheNewestResultWins) {
  Gate gate;
  MinimapWorker w(gate.compute());
  const auto s1 = w.request(job_at(1));
  gate.wait_started(1);
  const auto s2 = w.request(job_at(2));  // queued
  const auto s3 = w.request(job_at(3));  // replaces 2, which never runs
  EXPECT_LT(s1, s2);
  EXPECT_LT(s2, s3);
  EXPECT_EQ(w.coalesced(), 1u);
  gate.hold = false;
  ASSERT_TRUE(w.wait_idle(10s));
  EXPECT_EQ(gate.started, (std::vector<std::int64_t>{1, 3}));
  // Field 1 finished first and was never taken: dropped for field 3.
  const auto r = w.take();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->serial, s3);
  EXPECT_EQ(r->key.frame, 3);
  EXPECT_EQ(r->field.at<float>(0, 0), 3.0f);
  EXPECT_FALSE(w.take());
  EXPECT_EQ(w.computed(), 2u);
}

TEST(MinimapWorker, ShutdownWhileBusyCancelsTheFieldAndDropsTheQueue) {
  Gate gate;
  {
    MinimapWorker w(gate.compute());
    w.request(job_at(1));
    gate.wait_started(1);
    w.request(job_at(2));
    EXPECT_FALSE(w.wait_idle(5ms));  // busy, and would stay so while held
  }                                  // the destructor must return although the computation is held
  EXPECT_TRUE(gate.saw_cancel);
  EXPECT_EQ(gate.started, (std::vector<std::int64_t>{1}));
}

TEST(MinimapWorker, DefaultComputeStopsOnCancel) {
  const auto rbf = std::make_shared<const effects::RbfInterpolator>(
      std::vector<effects::Keyframe>{{{0.0, 0.0}, 0, {1.0}}}, 1, effects::InterpolationSettings{},
      30.0);
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(effect_minimap(rbf.get(), EffectType::Exposure, 0, 16, 8, &cancel).empty());
  cancel = false;
  EXPECT_EQ(effect_minimap(rbf.get(), EffectType::Exposure, 0, 16, 8, &cancel).size(),
            cv::Size(16, 8));
}

TEST(EditorAsyncMinimap, CatchesUpWithTheSynchronousFieldsWhilePlaying) {
  io::Sidecar sc = test::empty_sidecar(30);
  sc.effects.push_back(
      {EffectType::Exposure,
       std::nullopt,
       {{{30.0, 0.0}, 0, {2.0}}, {{-100.0, 40.0}, 10, {-3.0}}, {{170.0, -20.0}, 20, {1.0}}}});
  EditorOptions async_opts;
  async_opts.visuals.async = true;
  Editor sync(sc, DocumentOptions{{.async = false}}, EditorOptions{});
  Editor async(sc, DocumentOptions{{.async = false}}, async_opts);
  std::int64_t t = 0;
  sync.set_playing(true);
  async.set_playing(true);
  for (int i = 0; i < 8; ++i) {
    t += 33'333'334;
    sync.update(test::looking(0.0, 0.0, t), t);
    async.update(test::looking(0.0, 0.0, t), t);  // never waits for the worker
    ASSERT_EQ(async.frame(), sync.frame());
    EXPECT_TRUE(sync.minimap_current());
  }
  ASSERT_TRUE(async.wait_for_visualizations(10s));
  EXPECT_TRUE(same_field(async.minimap_field(), sync.minimap_field()));
  EXPECT_EQ(async.ui().minimap().keyframes().size(), 3u);
  // An edit: the next field follows it.
  sync.set_playing(false);
  async.set_playing(false);
  for (Editor* e : {&sync, &async}) {
    e->document().add_keyframe(EffectType::Exposure, {{90.0, 0.0}, sync.frame(), {-2.0}});
    e->update(test::looking(0.0, 0.0, t + 1), t + 1);
  }
  ASSERT_TRUE(async.wait_for_visualizations(10s));
  EXPECT_TRUE(same_field(async.minimap_field(), sync.minimap_field()));
  // Another effect: its field, not a late one of the previous effect.
  for (Editor* e : {&sync, &async}) {
    e->select_effect(EffectType::Contrast);
    e->update(test::looking(0.0, 0.0, t + 2), t + 2);
  }
  ASSERT_TRUE(async.wait_for_visualizations(10s));
  EXPECT_TRUE(same_field(async.minimap_field(), sync.minimap_field()));
  EXPECT_EQ(async.minimap_field().at<float>(0, 0), 1.0f);  // contrast has no keyframes: neutral
}

}  // namespace
}  // namespace vdfx::app
