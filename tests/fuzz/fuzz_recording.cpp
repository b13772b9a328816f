/// @file
/// @brief Fuzz target: the recording reader (io::parse_recording). Properties: a bad recording is
/// io::InputError and nothing else; a good one has strictly increasing sample times, lines never
/// before the line above, finite values in their ranges, and writes back to lines that read the
/// same.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz_check.h"
#include "io/input_error.h"
#include "io/recording.h"

namespace {

void check_hand(const vdfx::io::RecordedHand& h) {
  VDFX_FUZZ_CHECK(h.trigger >= 0.0 && h.trigger <= 1.0 && h.squeeze >= 0.0 && h.squeeze <= 1.0);
  for (const double v : h.stick) VDFX_FUZZ_CHECK(v >= -1.0 && v <= 1.0);
  for (const double v : h.aim.q) VDFX_FUZZ_CHECK(std::isfinite(v));
  for (const double v : h.aim.p) VDFX_FUZZ_CHECK(std::isfinite(v));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vdfx::io;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Recording rec;
  try {
    rec = parse_recording(in, "fuzz.vdrec.jsonl");
  } catch (const InputError&) {
    return 0;
  }
  std::int64_t last = INT64_MIN, last_sample = INT64_MIN;
  std::ostringstream back;
  back << format_header_line(rec.header) << "\n";
  for (const RecordingLine& line : rec.lines) {
    if (const auto* s = std::get_if<RecordedSample>(&line.value)) {
      VDFX_FUZZ_CHECK(s->t_ns >= last && s->t_ns > last_sample);
      last = last_sample = s->t_ns;
      for (const double v : s->head.q) VDFX_FUZZ_CHECK(std::isfinite(v));
      if (s->left) check_hand(*s->left);
      if (s->right) check_hand(*s->right);
      back << format_sample_line(*s) << "\n";
    } else {
      const auto& h = std::get<RecordedHid>(line.value);
      VDFX_FUZZ_CHECK(h.t_ns >= last && !h.device.empty());
      last = h.t_ns;
      back << format_hid_line(h) << "\n";
    }
  }
  std::istringstream again_in(back.str());
  const Recording again = parse_recording(again_in, "again");  // must not throw
  VDFX_FUZZ_CHECK(again.lines.size() == rec.lines.size());
  return 0;
}
