/// @file
/// @brief ProgressReporter.
#include "app/cli/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <utility>

namespace vdfx::app {
namespace {

std::string clock_text(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  const long t = std::lround(s);
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
  return buf;
}

struct Rates {
  double fps, eta_s;
  int percent;
};

Rates rates(std::int64_t done, std::int64_t total, double elapsed_s) {
  const double fps = elapsed_s > 0 && done > 0 ? static_cast<double>(done) / elapsed_s : 0.0;
  const double eta = fps > 0 ? static_cast<double>(total - done) / fps : -1.0;
  const int pct = total > 0 ? static_cast<int>(100 * done / total) : 100;
  return {fps, eta, pct};
}

}  // namespace

ProgressReporter::ProgressReporter(std::ostream& out, bool terminal, std::int64_t total,
                                   double interval, std::string prefix, std::string unit)
    : out_(out),
      terminal_(terminal),
      total_(total),
      interval_(interval),
      prefix_(std::move(prefix)),
      unit_(std::move(unit)) {}

std::string ProgressReporter::bar_text(std::int64_t done, std::int64_t total, double elapsed_s,
                                       const std::string& unit) {
  const Rates r = rates(done, total, elapsed_s);
  const int filled = std::clamp(r.percent / 5, 0, 20);
  char buf[160];
  std::snprintf(buf, sizeof buf, "[%s%s] %3d%%  %lld/%lld %s  %.1f %s/s  ETA %s",
                std::string(static_cast<std::size_t>(filled), '#').c_str(),
                std::string(static_cast<std::size_t>(20 - filled), ' ').c_str(), r.percent,
                static_cast<long long>(done), static_cast<long long>(total), unit.c_str(), r.fps,
                unit.c_str(), clock_text(r.eta_s).c_str());
  return buf;
}

std::string ProgressReporter::line_text(std::int64_t done, std::int64_t total, double elapsed_s,
                                        const std::string& unit) {
  const Rates r = rates(done, total, elapsed_s);
  char buf[160];
  std::snprintf(buf, sizeof buf, "%lld/%lld %s (%d%%), %.1f %s/s, ETA %s",
                static_cast<long long>(done), static_cast<long long>(total), unit.c_str(),
                r.percent, r.fps, unit.c_str(), clock_text(r.eta_s).c_str());
  return buf;
}

void ProgressReporter::update(std::int64_t done, double elapsed_s) {
  // A terminal bar is cheap to redraw (10 per second at most); lines are for logs.
  const double gap = terminal_ ? 0.1 : interval_;
  if (elapsed_s - last_ < gap && done < total_) return;
  last_ = elapsed_s;
  last_done_ = done;
  if (terminal_)
    out_ << "\r" << bar_text(done, total_, elapsed_s, unit_) << std::flush;
  else
    out_ << prefix_ << ": " << line_text(done, total_, elapsed_s, unit_) << "\n" << std::flush;
}

void ProgressReporter::finish(std::int64_t done, double elapsed_s) {
  if (!terminal_ && done == last_done_) return;  // that line is out already
  if (terminal_)
    out_ << "\r" << bar_text(done, total_, elapsed_s, unit_) << "\n" << std::flush;
  else
    out_ << prefix_ << ": " << line_text(done, total_, elapsed_s, unit_) << "\n" << std::flush;
}

}  // namespace vdfx::app
