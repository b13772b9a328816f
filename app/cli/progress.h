/// @file
/// @brief Progress of a long command (export, track): on a terminal one bar redrawn in place
/// (frames, frames/s, ETA); into a file or pipe plain lines every few seconds. Time is passed in
/// (seconds since the start).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

namespace vdfx::app {

class ProgressReporter {
 public:
  /// `terminal`: redraw a bar with '\r'; otherwise a line at most every `line_interval_s`,
  /// starting "LABEL: ".
  ProgressReporter(std::ostream& out, bool terminal, std::int64_t total,
                   double line_interval_s = 5.0, std::string label = "export");
  void update(std::int64_t done, double elapsed_s);
  /// The last state, and a newline after the bar.
  void finish(std::int64_t done, double elapsed_s);

  /// "[#####     ]  50%  12/24 frames  3.1 frames/s  ETA 0:04" (the bar's text, width 20).
  static std::string bar_text(std::int64_t done, std::int64_t total, double elapsed_s);
  /// "12/24 frames (50%), 3.1 frames/s, ETA 0:04".
  static std::string line_text(std::int64_t done, std::int64_t total, double elapsed_s);

 private:
  std::ostream& out_;
  bool terminal_;
  std::int64_t total_;
  double interval_;
  std::string label_;
  double last_ = -1e9;
  std::int64_t last_done_ = -1;
};

}  // namespace vdfx::app
