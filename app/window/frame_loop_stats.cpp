/// @file
/// @brief FrameLoopStats: medians of per-frame stage times.
#include "app/window/frame_loop_stats.h"

#include <algorithm>
#include <array>
#include <iomanip>
#include <sstream>

namespace vdfx::app {
namespace {
// GPU stages in pipeline order, then the CPU parts; anything else after them by name.
constexpr std::array<const char*, 8> kOrder{"gpu video",      "gpu effects", "gpu quads",
                                            "gpu distortion", "cpu frame",   "cpu upload",
                                            "cpu bake",       "cpu params"};
int rank(const std::string& s) {
  for (std::size_t i = 0; i < kOrder.size(); ++i)
    if (s == kOrder[i]) return static_cast<int>(i);
  return static_cast<int>(kOrder.size());
}
}  // namespace

void FrameLoopStats::add_gpu(const std::vector<xr::StageTime>& times) {
  std::map<std::string, double> frame;
  for (const auto& t : times) {
    const auto space = t.stage.find(' ');
    frame["gpu " + (space == std::string::npos ? t.stage : t.stage.substr(space + 1))] += t.ms;
  }
  for (const auto& [k, v] : frame) {
    window_[k].push_back(v);
    all_[k].push_back(v);
  }
}

void FrameLoopStats::add_cpu(const std::string& part, double ms) {
  window_["cpu " + part].push_back(ms);
  all_["cpu " + part].push_back(ms);
}

std::vector<StageMedian> FrameLoopStats::medians(const Series& s) {
  std::vector<StageMedian> out;
  for (auto [k, v] : s) {
    if (v.empty()) continue;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    double m = *mid;
    if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), mid));
    out.push_back({k, m});
  }
  std::stable_sort(out.begin(), out.end(), [](const StageMedian& a, const StageMedian& b) {
    return rank(a.stage) < rank(b.stage) || (rank(a.stage) == rank(b.stage) && a.stage < b.stage);
  });
  return out;
}

std::vector<StageMedian> FrameLoopStats::take_window() {
  auto m = medians(window_);
  window_.clear();
  return m;
}

std::vector<StageMedian> FrameLoopStats::total() const {
  return medians(all_);
}

std::string FrameLoopStats::format(const std::vector<StageMedian>& m) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2);
  for (std::size_t i = 0; i < m.size(); ++i)
    s << (i ? ", " : "") << m[i].stage << " " << m[i].ms << " ms";
  return s.str();
}

}  // namespace vdfx::app
