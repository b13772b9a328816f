/// @file
/// @brief Progress of a long command (export, suggest, track): on a terminal one bar redrawn in
/// place (items done, items/s, ETA); into a file or pipe plain lines every few seconds. Time is
/// passed in (seconds since the start).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

namespace vdfx::app {

class ProgressReporter {
 public:
  /// `terminal`: redraw a bar with '\r'; otherwise a line at most every `line_interval_s`,
  /// starting "PREFIX: ". `unit` names what is counted ("frames", "keyframes").
  ProgressReporter(std::ostream& out, bool terminal, std::int64_t total,
                   double line_interval_s = 5.0, std::string prefix = "export",
                   std::string unit = "frames");
  void update(std::int64_t done, double elapsed_s);
  /// The last state, and a newline after the bar.
  void finish(std::int64_t done, double elapsed_s);

  /// "[#####     ]  50%  12/24 frames  3.1 frames/s  ETA 0:04" (the bar's text, width 20).
  static std::string bar_text(std::int64_t done, std::int64_t total, double elapsed_s,
                              const std::string& unit = "frames");
  /// "12/24 frames (50%), 3.1 frames/s, ETA 0:04".
  static std::string line_text(std::int64_t done, std::int64_t total, double elapsed_s,
                               const std::string& unit = "frames");

 private:
  std::ostream& out_;
  bool terminal_;
  std::int64_t total_;
  double interval_;
  std::string prefix_, unit_;
  double last_ = -1e9;
  std::int64_t last_done_ = -1;
};

}  // namespace vdfx::app
