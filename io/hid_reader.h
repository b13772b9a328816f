/// @file
/// @brief Reads one HID device on a worker thread into a queue, surviving unplug and replug.
///
/// The worker opens the device, reads reports, and on a read error closes it, queues a
/// Disconnected event with a status message and retries opening every reopen_interval. The
/// caller drains the queue once per frame; it never blocks on the device.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "io/hid_device.h"

namespace vdfx::io {

struct HidReaderEvent {
  enum class Kind { Connected, Report, Disconnected };
  Kind kind = Kind::Report;
  std::vector<std::uint8_t> bytes;  //!< the report, or the descriptor for Connected
  std::string message;              //!< for Connected / Disconnected
};

struct HidReaderOptions {
  int read_timeout_ms = 20;       //!< bounds how long stopping the reader takes
  int reopen_interval_ms = 1000;  //!< between attempts while the device is gone
  std::size_t max_queue = 1024;   //!< oldest reports are dropped beyond this (caller stalled)
  std::size_t report_size = 128;  //!< read buffer; larger than any report we parse
};

class HidReader {
 public:
  /// Returns the opened device or null; called again after every failure.
  using Opener = std::function<std::unique_ptr<HidDevice>()>;

  HidReader(std::string name, Opener opener, HidReaderOptions options = {});
  ~HidReader();
  HidReader(const HidReader&) = delete;
  HidReader& operator=(const HidReader&) = delete;

  /// Everything that happened since the last call, oldest first.
  std::vector<HidReaderEvent> drain();
  bool connected() const { return connected_.load(); }
  /// A human-readable line: connected / lost (why) / waiting for the device.
  std::string status() const;
  const std::string& name() const { return name_; }

 private:
  void run();
  void push(HidReaderEvent event);
  void set_status(std::string status);
  /// Sleeps up to ms, returning early (true) when asked to stop.
  bool wait_or_stop(int ms);

  std::string name_;
  Opener opener_;
  HidReaderOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable stop_cv_;
  std::deque<HidReaderEvent> queue_;
  std::string status_;
  std::atomic<bool> connected_{false};
  std::atomic<bool> stop_{false};
  std::thread worker_;
};

}  // namespace vdfx::io
