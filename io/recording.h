/// @file
/// @brief Reader and writer of recorded input sessions (contract: "Recording file, format 1").
///
/// A recording is JSON Lines: a header line, then one line per input sample (head and hand poses,
/// triggers, sticks, buttons) or per raw HID report. The types here are plain data with no math
/// library, so io/ stays free of xr/; xr/input/input_state_io.h converts them to actions.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace vdfx::io {

struct RecordedPose {
  std::array<double, 4> q{1.0, 0.0, 0.0, 0.0};  //!< unit quaternion [w, x, y, z]
  std::array<double, 3> p{0.0, 0.0, 0.0};       //!< metres, OpenXR axes
};

/// One hand. The buttons are named by hand in the file: left has x, y, menu, stick; right has
/// a, b, stick. `primary` is a (right) or x (left), `secondary` is b or y.
struct RecordedHand {
  RecordedPose aim;
  double trigger = 0.0;                   //!< [0, 1]
  double squeeze = 0.0;                   //!< [0, 1]
  std::array<double, 2> stick{0.0, 0.0};  //!< each [-1, 1], +x right, +y up
  bool primary = false;
  bool secondary = false;
  bool menu = false;  //!< left hand only (written and read for the left hand only)
  bool stick_click = false;
};

struct RecordedSample {
  std::int64_t t_ns = 0;
  RecordedPose head;
  std::optional<RecordedHand> left;   //!< absent: not tracked
  std::optional<RecordedHand> right;  //!< absent: not tracked
};

/// A raw HID input report, replayed through the same parser as a live device. An empty report
/// records that the device was lost (unplugged); `is_descriptor` marks a line that carries the
/// device's report descriptor (key "descriptor" instead of "report"), which generic gamepads need
/// before their first report.
struct RecordedHid {
  std::int64_t t_ns = 0;
  std::string device;               //!< "vvvv:pppp" (hex vendor:product), optional "#n" suffix
  std::vector<std::uint8_t> bytes;  //!< the report including its report ID byte, if any
  bool is_descriptor = false;
};

/// vdfx extension of the header (docs/input.md): the desktop view a sim session was recorded
/// in, so a replay lays out the editor's panels and aims the cursor rays as they were.
struct RecordedDesktopView {
  int width = 1280;  //!< window pixels, 1..16384
  int height = 720;
  double hfov_deg = 100.0;  //!< horizontal FOV, (0, 180)
  bool operator==(const RecordedDesktopView&) const = default;
};

struct RecordingHeader {
  std::string hmd = "sim";
  std::optional<std::string> video;  //!< null in the file when absent
  std::string note;
  std::optional<RecordedDesktopView> desktop{};  //!< "desktop": {...}, absent when not recorded
};

struct RecordingLine {
  int line_number = 0;  //!< 1-based line in the file
  std::variant<RecordedSample, RecordedHid> value;
};

struct Recording {
  std::string name;  //!< file name used in messages
  RecordingHeader header;
  std::vector<RecordingLine> lines;
  std::vector<std::string> warnings;  //!< e.g. a truncated last line that was dropped
};

/// Quaternions whose norm differs from 1 by more than this are rejected.
inline constexpr double kRecordingUnitTolerance = 1e-3;

/// The longest line a recording may have (a sample line is about 500 bytes, a generic gamepad's
/// descriptor line at most about 8 KiB) and the largest recording file: about 5 hours of samples
/// at 90 Hz. Both are read with their limit, never past it (docs/reliability.md).
inline constexpr std::size_t kMaxRecordingLineBytes = std::size_t{1} << 20;
inline constexpr std::uintmax_t kMaxRecordingBytes = std::uintmax_t{1} << 30;

/// Reads and validates a recording; throws InputError naming the file and line of the first
/// problem (bad JSON, header, version, types, ranges, NaN/infinity, non-unit quaternion, time
/// order: samples strictly increasing, every line not before the one above it). A truncated last
/// line is dropped with a warning.
Recording read_recording(const std::filesystem::path& path);
Recording parse_recording(std::istream& in, const std::string& name);

/// Lower-case hex without separators, and back (throws std::invalid_argument on bad input).
std::string to_hex(const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> from_hex(const std::string& hex);

/// Writes a recording line by line, each straight to the file (no buffer in the process), so a
/// crash loses at most the line being written, which the reader then tolerates as a truncated
/// last line. A write that fails (full disk) cuts the file back to its last whole line and throws
/// io::InputError naming the file; the writer then stays failed. The file is always one the
/// reader takes: a header and whole lines.
class RecordingWriter {
 public:
  RecordingWriter(const std::filesystem::path& path, const RecordingHeader& header);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;
  void write(const RecordedSample& sample);
  void write(const RecordedHid& hid);
  const std::filesystem::path& path() const { return path_; }

 private:
  void write_line(const std::string& line);
  std::filesystem::path path_;
  int fd_ = -1;              //!< -1 once failed
  std::uint64_t whole_ = 0;  //!< bytes of whole lines written
  int lines_ = 0;
};

/// One line of JSON for a sample or a HID report, exactly as written to the file (no newline).
std::string format_sample_line(const RecordedSample& sample);
std::string format_hid_line(const RecordedHid& hid);
std::string format_header_line(const RecordingHeader& header);

}  // namespace vdfx::io
