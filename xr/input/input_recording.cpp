/// @file
/// @brief RecordingInputBackend: a decorator that writes what any backend returns.
#include <utility>

#include "io/recording.h"
#include "xr/input/input_backend.h"
#include "xr/input/input_state_io.h"

namespace vdfx::xr {

namespace {

class RecordingInputBackend final : public InputBackend {
 public:
  RecordingInputBackend(std::unique_ptr<InputBackend> inner, const std::filesystem::path& file,
                        const io::RecordingHeader& header)
      : inner_(std::move(inner)), writer_(file, header) {}

  InputState poll_state(std::int64_t t_ns) override {
    InputState s = inner_->poll(t_ns);
    pending_ = inner_->drain_raw_reports();
    // A repeated or earlier poll time would break the file's strictly increasing samples; the
    // state it returns is still handed on, it is just not recorded twice.
    if (last_t_ && t_ns <= *last_t_) return s;
    for (const io::RecordedHid& h : pending_) writer_.write(h);
    writer_.write(to_recorded_sample(s));
    last_t_ = t_ns;
    return s;
  }
  void push_event(const DesktopEvent& event) override { inner_->push_event(event); }
  std::string status() const override { return inner_->status(); }
  std::vector<std::int64_t> timeline() const override { return inner_->timeline(); }
  std::vector<io::RecordedHid> drain_raw_reports() override { return std::exchange(pending_, {}); }

 private:
  std::unique_ptr<InputBackend> inner_;
  io::RecordingWriter writer_;
  std::vector<io::RecordedHid> pending_;
  std::optional<std::int64_t> last_t_;
};

}  // namespace

std::unique_ptr<InputBackend> create_recording_backend(std::unique_ptr<InputBackend> inner,
                                                       const std::filesystem::path& file,
                                                       const io::RecordingHeader& header) {
  return std::make_unique<RecordingInputBackend>(std::move(inner), file, header);
}

}  // namespace vdfx::xr
