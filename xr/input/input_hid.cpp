/// @file
/// @brief The hid backend: gamepads and SpaceMice through hidapi, read on worker threads.
///
/// Each device has an io::HidReader (worker thread, queue, reopen after unplug). poll(t) drains the
/// queues, feeds the reports at time t to the HidInputMapper (the same one replay uses) and keeps
/// them as raw lines for a recording. A lost device's controls go neutral and status() says so.
#include <deque>
#include <sstream>
#include <utility>

#include "io/input_error.h"
#include "xr/input/input_backend.h"

namespace vdfx::xr {

namespace {

struct Selector {
  std::string device_id;  //!< vendor:product, or empty with a path
  std::string path;
};

class HidInputBackend final : public InputBackend {
 public:
  HidInputBackend(const std::vector<std::string>& selectors, const InputBackendOptions& options)
      : mapper_(options.hid_mapping) {
    system_ = options.hid_system.enumerate ? options.hid_system : io::default_hid_system();
    const auto devices = system_.enumerate();
    std::vector<Selector> chosen;
    if (selectors.empty()) {
      for (const auto& d : devices) {
        if (classify_device(d.vendor_id, d.product_id, d.usage_page, d.usage) ==
            HidDeviceKind::Unknown)
          continue;
        const std::string id = io::format_device_id(d.vendor_id, d.product_id);
        bool dup = false;
        for (const auto& c : chosen) dup = dup || c.device_id == id;
        if (!dup) chosen.push_back({id, ""});
      }
      if (chosen.empty()) {
        throw io::InputError(io::hid_available()
                                 ? "hid: no supported HID device found (`vdfx devices` lists them)"
                                 : "hid: this build has no hidapi support");
      }
    }
    for (const std::string& sel : selectors) {
      if (!sel.empty() && sel[0] == '/') {
        std::string id;
        for (const auto& d : devices) {
          if (d.path == sel) id = io::format_device_id(d.vendor_id, d.product_id);
        }
        if (id.empty()) throw io::InputError("hid: no HID device at " + sel);
        chosen.push_back({id, sel});
      } else if (parse_device_id(sel)) {
        chosen.push_back({sel, ""});
      } else {
        throw io::InputError("hid: '" + sel +
                             "' is neither vendor:product (hex, e.g. 054c:05c4) nor a path");
      }
    }
    for (const Selector& s : chosen) {
      const auto ids = parse_device_id(s.device_id);
      auto opener = [system = system_, s, ids]() -> std::unique_ptr<io::HidDevice> {
        if (!s.path.empty()) return system.open(s.path);
        // Re-enumerate on every attempt: a replugged device may get a new path.
        for (const auto& d : system.enumerate()) {
          if (d.vendor_id != ids->first || d.product_id != ids->second) continue;
          if (classify_device(d.vendor_id, d.product_id, d.usage_page, d.usage) ==
              HidDeviceKind::Unknown)
            continue;
          if (auto dev = system.open(d.path)) return dev;
        }
        return nullptr;
      };
      sources_.push_back({s.device_id,
                          std::make_unique<io::HidReader>(s.device_id, opener, options.hid_reader),
                          {}});
    }
  }

  InputState poll_state(std::int64_t t_ns) override {
    raw_.clear();
    for (std::size_t i = 0; i < sources_.size(); ++i)
      for (io::HidReaderEvent& ev : sources_[i].reader->drain())
        pending_.push_back({i, std::move(ev)});
    // No lost taps (as the sim): events apply in order until one would change a control an
    // earlier event of this poll changed; it and the rest wait for the next poll.
    ControlSet down = controls_down(mapper_.state(t_ns), last_down_);
    std::uint32_t changed = 0;
    while (!pending_.empty()) {
      HidInputMapper before = mapper_;
      const std::size_t raw_before = raw_.size();
      apply(t_ns, sources_[pending_.front().source], pending_.front().event);
      const ControlSet after = controls_down(mapper_.state(t_ns), down);
      const std::uint32_t diff = after.bits ^ down.bits;
      if (diff & changed) {
        mapper_ = std::move(before);
        raw_.resize(raw_before);
        break;
      }
      changed |= diff;
      down = after;
      pending_.pop_front();
    }
    last_down_ = down;
    return mapper_.state(t_ns);
  }

  std::string status() const override {
    std::ostringstream out;
    for (std::size_t i = 0; i < sources_.size(); ++i) {
      if (i) out << "; ";
      out << (sources_[i].problem.empty() ? sources_[i].reader->status() : sources_[i].problem);
    }
    return out.str();
  }

  std::vector<io::RecordedHid> drain_raw_reports() override { return std::exchange(raw_, {}); }

 private:
  struct Source;
  /// Feeds one reader event to the mapper at the poll's time and keeps it as a raw line.
  void apply(std::int64_t t_ns, Source& src, const io::HidReaderEvent& ev) {
    switch (ev.kind) {
      case io::HidReaderEvent::Kind::Connected: {
        const auto ids = parse_device_id(src.id);
        const bool known =
            ids && known_device_kind(ids->first, ids->second) != HidDeviceKind::Unknown;
        if (!known &&
            !ev.bytes.empty()) {  // generic gamepads need their descriptor, also in replay
          try {
            mapper_.on_descriptor(src.id, ev.bytes);
            raw_.push_back({t_ns, src.id, ev.bytes, true});
          } catch (const HidDescriptorError& e) {
            src.problem = src.id + ": " + e.what();
          }
        }
        break;
      }
      case io::HidReaderEvent::Kind::Report:
        mapper_.on_report(t_ns, src.id, ev.bytes);
        raw_.push_back({t_ns, src.id, ev.bytes, false});
        break;
      case io::HidReaderEvent::Kind::Disconnected:
        mapper_.on_disconnect(t_ns, src.id);
        raw_.push_back({t_ns, src.id, {}, false});
        break;
    }
  }

  struct Source {
    std::string id;
    std::unique_ptr<io::HidReader> reader;
    std::string problem;
  };
  io::HidSystem system_;
  HidInputMapper mapper_;
  std::vector<Source> sources_;
  std::vector<io::RecordedHid> raw_;
  struct Pending {
    std::size_t source;
    io::HidReaderEvent event;
  };
  std::deque<Pending> pending_;  //!< drained but not applied yet (a second change of a control)
  ControlSet last_down_;
};

}  // namespace

std::unique_ptr<InputBackend> create_hid_backend(const std::vector<std::string>& selectors,
                                                 const InputBackendOptions& options) {
  return std::make_unique<HidInputBackend>(selectors, options);
}

}  // namespace vdfx::xr
