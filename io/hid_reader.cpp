/// @file
/// @brief HidReader's worker loop: open, read, on error close and retry later.
#include "io/hid_reader.h"

#include <chrono>

namespace vdfx::io {

HidReader::HidReader(std::string name, Opener opener, HidReaderOptions options)
    : name_(std::move(name)), opener_(std::move(opener)), options_(options) {
  status_ = name_ + ": waiting for the device";
  worker_ = std::thread([this] { run(); });
}

HidReader::~HidReader() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  stop_cv_.notify_all();
  worker_.join();
}

std::vector<HidReaderEvent> HidReader::drain() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<HidReaderEvent> out(std::make_move_iterator(queue_.begin()),
                                  std::make_move_iterator(queue_.end()));
  queue_.clear();
  return out;
}

std::string HidReader::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

void HidReader::push(HidReaderEvent event) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (queue_.size() >= options_.max_queue) {
    // Drop the oldest report, never a connect/disconnect, so state changes are not lost.
    for (auto it = queue_.begin(); it != queue_.end(); ++it) {
      if (it->kind == HidReaderEvent::Kind::Report) {
        queue_.erase(it);
        break;
      }
    }
  }
  queue_.push_back(std::move(event));
}

void HidReader::set_status(std::string status) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_ = std::move(status);
}

bool HidReader::wait_or_stop(int ms) {
  std::unique_lock<std::mutex> lock(mutex_);
  return stop_cv_.wait_for(lock, std::chrono::milliseconds(ms), [this] { return stop_.load(); });
}

void HidReader::run() {
  std::unique_ptr<HidDevice> device;
  std::vector<std::uint8_t> buffer(options_.report_size);
  const std::string retry =
      " (retrying every " + std::to_string(options_.reopen_interval_ms) + " ms)";
  std::string waiting = name_ + ": not found" + retry;  // keeps why it was lost
  while (!stop_) {
    if (!device) {
      device = opener_ ? opener_() : nullptr;
      if (!device) {
        set_status(waiting);
        if (wait_or_stop(options_.reopen_interval_ms)) break;
        continue;
      }
      HidReaderEvent ev;
      ev.kind = HidReaderEvent::Kind::Connected;
      ev.bytes = device->report_descriptor();
      ev.message = name_ + ": connected";
      connected_ = true;
      set_status(ev.message);
      push(std::move(ev));
    }
    const int n = device->read(buffer, options_.read_timeout_ms);
    if (n > 0) {
      HidReaderEvent ev;
      ev.bytes.assign(buffer.begin(), buffer.begin() + n);
      push(std::move(ev));
    } else if (n < 0) {
      HidReaderEvent ev;
      ev.kind = HidReaderEvent::Kind::Disconnected;
      ev.message = name_ + ": lost (" + device->last_error() + ")" + retry;
      device->close();
      device.reset();
      connected_ = false;
      waiting = ev.message;
      set_status(ev.message);
      push(std::move(ev));
      if (wait_or_stop(options_.reopen_interval_ms)) break;
    }
  }
  if (device) device->close();
}

}  // namespace vdfx::io
