/// @file
/// @brief run_export_pipeline: decode thread -> render workers -> ordered sink.
#include "app/export/pipeline.h"

#include <malloc.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "io/input_error.h"

namespace vdfx::app {
namespace {

struct Job {
  std::int64_t frame;
  io::Picture source;
};

/// Shared state, all under one mutex (frames take milliseconds: contention is negligible).
struct State {
  std::mutex m;
  std::condition_variable changed;
  std::deque<Job> jobs;                      //!< decoded, waiting for a worker
  std::map<std::int64_t, io::Picture> done;  //!< rendered, waiting for their turn
  std::int64_t next_to_sink = 0;
  std::int64_t decoded_end = -1;  //!< set when decoding stopped: one past the last frame
  bool stop = false;
  std::exception_ptr error;

  void fail(std::exception_ptr e) {
    std::lock_guard lock(m);
    if (!error) error = e;
    stop = true;
    changed.notify_all();
  }
};

/// The decode thread: frames in order into `jobs`, at most `in_flight` ahead of the sink.
void decode_frames(io::FrameDecoder& decoder, const PipelineSettings& s, std::int64_t in_flight,
                   State& st) {
  try {
    const std::string name = decoder.properties().path.string();
    decoder.seek(s.first);
    for (std::int64_t k = s.first; k <= s.last; ++k) {
      {
        std::unique_lock lock(st.m);
        st.changed.wait(lock, [&] { return st.stop || k - st.next_to_sink < in_flight; });
        if (st.stop) break;
      }
      if (s.cancel && s.cancel->load()) break;
      io::Picture pic;
      const io::DecodeStatus status = decoder.read_picture(pic);
      if (status == io::DecodeStatus::End) {
        std::lock_guard lock(st.m);
        st.decoded_end = k;
        st.changed.notify_all();
        return;
      }
      if (status == io::DecodeStatus::Error)
        throw io::InputError(name + ": frame " + std::to_string(k) +
                             " could not be decoded (damaged file?)");
      std::lock_guard lock(st.m);
      st.jobs.push_back({k, std::move(pic)});
      st.changed.notify_all();
    }
    std::lock_guard lock(st.m);
    if (st.decoded_end < 0) st.decoded_end = s.last + 1;
    st.changed.notify_all();
  } catch (...) {
    st.fail(std::current_exception());
  }
}

/// A render worker: takes decoded frames until decoding finished and none is left.
void render_frames(const FrameRenderer& render, State& st) {
  while (true) {
    std::optional<Job> job;
    {
      std::unique_lock lock(st.m);
      st.changed.wait(lock, [&] { return st.stop || !st.jobs.empty() || st.decoded_end >= 0; });
      if (st.stop) return;
      if (st.jobs.empty()) return;  // decoding finished and nothing is left
      job = std::move(st.jobs.front());
      st.jobs.pop_front();
    }
    try {
      io::Picture out = render(job->source, job->frame);
      job->source = io::Picture{};  // release the decoder's buffer now
      std::lock_guard lock(st.m);
      st.done.emplace(job->frame, std::move(out));
      st.changed.notify_all();
    } catch (...) {
      st.fail(std::current_exception());
      return;
    }
  }
}

/// The next frame for the sink, in order; none when the pipeline stopped, was cancelled or is
/// done.
std::optional<std::pair<std::int64_t, io::Picture>> next_rendered(const PipelineSettings& s,
                                                                  State& st,
                                                                  PipelineResult& result) {
  std::unique_lock lock(st.m);
  // Woken by every frame event; the cancel flag is set by a signal handler, which cannot
  // notify, so it is polled too.
  while (!st.changed.wait_for(lock, std::chrono::milliseconds(100), [&] {
    return st.stop || st.done.count(st.next_to_sink) ||
           (st.decoded_end >= 0 && st.next_to_sink >= st.decoded_end) ||
           (s.cancel && s.cancel->load());
  })) {
  }
  if (st.stop) return std::nullopt;
  if (s.cancel && s.cancel->load()) {
    result.cancelled = true;
    st.stop = true;
    st.changed.notify_all();
    return std::nullopt;
  }
  if (st.decoded_end >= 0 && st.next_to_sink >= st.decoded_end) return std::nullopt;
  const std::int64_t k = st.next_to_sink;
  std::pair<std::int64_t, io::Picture> next{k, std::move(st.done[k])};
  st.done.erase(k);
  return next;
}

/// The calling thread: frames to the sink in order.
void sink_frames(const FrameSink& sink, const PipelineSettings& s, State& st,
                 PipelineResult& result) {
  try {
    while (auto next = next_rendered(s, st, result)) {
      sink(next->second, next->first);
      ++result.encoded;
      {
        std::lock_guard lock(st.m);
        ++st.next_to_sink;
        st.changed.notify_all();
      }
      if (s.on_progress) s.on_progress(result.encoded);
    }
  } catch (...) {
    st.fail(std::current_exception());
  }
}

}  // namespace

PipelineResult run_export_pipeline(io::FrameDecoder& decoder, const FrameRenderer& render,
                                   const FrameSink& sink, const PipelineSettings& s) {
  // Every frame allocates a few full-size images on each worker; glibc would give them back to
  // the kernel and fault them in again, zeroed, for the next frame (a fifth of an export's CPU
  // time, measured with perf). Freed memory is kept for reuse instead (process-wide).
  mallopt(M_MMAP_THRESHOLD, 512 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  const int workers = s.workers > 0 ? s.workers : std::max(1u, std::thread::hardware_concurrency());
  const std::int64_t in_flight = s.max_in_flight > 0 ? s.max_in_flight : 2 * workers;
  State st;
  st.next_to_sink = s.first;
  PipelineResult result;
  std::thread decode([&] { decode_frames(decoder, s, in_flight, st); });
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w) pool.emplace_back([&] { render_frames(render, st); });
  sink_frames(sink, s, st, result);
  {
    std::lock_guard lock(st.m);
    st.stop = true;
    st.changed.notify_all();
  }
  decode.join();
  for (auto& t : pool) t.join();
  if (st.error) std::rethrow_exception(st.error);
  result.end = s.first + result.encoded;
  result.ended_early = !result.cancelled && st.decoded_end >= 0 && st.decoded_end <= s.last;
  return result;
}

}  // namespace vdfx::app
