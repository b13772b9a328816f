/// @file
/// @brief The replay backend: a recording drives the actions; time comes from the recording.
///
/// Samples: poll(t) returns the last sample at or before t (step, no interpolation: a replay at
/// the recorded times reproduces the session exactly); before the first sample nothing is
/// tracked. HID lines, when the recording has any: they go through the same parsers and mapper as
/// live devices, and those drive the actions (sample lines are then only a record of the result).
#include <algorithm>

#include "io/excerpt.h"
#include "io/input_error.h"
#include "xr/input/input_backend.h"
#include "xr/input/input_state_io.h"

namespace vdfx::xr {

namespace {

class ReplayInputBackend final : public InputBackend {
 public:
  ReplayInputBackend(io::Recording rec, const InputBackendOptions& options)
      : name_(rec.name), mapping_(options.hid_mapping), mapper_(mapping_) {
    for (auto& line : rec.lines) {
      if (auto* s = std::get_if<io::RecordedSample>(&line.value))
        samples_.push_back(std::move(*s));
      else
        hids_.push_back({line.line_number, std::get<io::RecordedHid>(std::move(line.value))});
    }
    check_hid_lines();
  }

  InputState poll_state(std::int64_t t_ns) override {
    if (!hids_.empty()) return poll_hid(t_ns);
    auto it =
        std::upper_bound(samples_.begin(), samples_.end(), t_ns,
                         [](std::int64_t t, const io::RecordedSample& s) { return t < s.t_ns; });
    if (it == samples_.begin()) {
      InputState none = neutral_input_state(t_ns);
      return none;
    }
    InputState s = from_recorded_sample(*std::prev(it));
    s.t_ns = t_ns;
    return s;
  }

  std::vector<std::int64_t> timeline() const override {
    std::vector<std::int64_t> t;
    for (const auto& s : samples_) t.push_back(s.t_ns);
    if (t.empty()) {
      for (const auto& h : hids_) {
        if (t.empty() || t.back() != h.hid.t_ns) t.push_back(h.hid.t_ns);
      }
    }
    return t;
  }

  std::string status() const override { return "replaying " + name_; }

 private:
  struct HidLine {
    int line;
    io::RecordedHid hid;
  };

  // Fails at load time, naming the line, rather than silently ignoring reports during replay.
  void check_hid_lines() {
    HidInputMapper probe(mapping_);
    for (const HidLine& h : hids_) {
      const std::string where = name_ + ":" + std::to_string(h.line) + ": /hid: ";
      if (h.hid.is_descriptor) {
        try {
          (void)parse_report_descriptor(h.hid.bytes);
          probe.on_descriptor(h.hid.device, h.hid.bytes);
        } catch (const HidDescriptorError& e) {
          throw io::InputError(where + e.what());
        }
      } else if (!probe.knows(h.hid.device)) {
        throw io::InputError(
            where + "device \"" + io::excerpt(h.hid.device) +
            "\" is not a known vendor:product and has no descriptor line before it");
      }
    }
  }

  InputState poll_hid(std::int64_t t_ns) {
    if (last_poll_ && t_ns < *last_poll_) {  // went back in time: start over
      mapper_ = HidInputMapper(mapping_);
      next_ = 0;
    }
    last_poll_ = t_ns;
    for (; next_ < hids_.size() && hids_[next_].hid.t_ns <= t_ns; ++next_) {
      const io::RecordedHid& h = hids_[next_].hid;
      if (h.is_descriptor)
        mapper_.on_descriptor(h.device, h.bytes);
      else
        mapper_.on_report(h.t_ns, h.device, h.bytes);
    }
    return mapper_.state(t_ns);
  }

  std::string name_;
  HidMappingConfig mapping_;
  HidInputMapper mapper_;
  std::vector<io::RecordedSample> samples_;
  std::vector<HidLine> hids_;
  std::size_t next_ = 0;
  std::optional<std::int64_t> last_poll_;
};

}  // namespace

std::unique_ptr<InputBackend> create_replay_backend(io::Recording recording,
                                                    const InputBackendOptions& options) {
  return std::make_unique<ReplayInputBackend>(std::move(recording), options);
}

std::unique_ptr<InputBackend> create_replay_backend(const std::filesystem::path& file,
                                                    const InputBackendOptions& options) {
  return create_replay_backend(io::read_recording(file), options);
}

}  // namespace vdfx::xr
