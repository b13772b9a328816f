/// @file
/// @brief Row ratios and the Pareto fronts of a bench report.
#include "app/bench/report.h"

#include <cmath>
#include <map>

namespace vdfx::app::bench {

const char* to_string(RowStatus s) {
  switch (s) {
    case RowStatus::Ok: return "ok";
    case RowStatus::Skipped: return "skipped";
    case RowStatus::Failed: return "failed";
  }
  return "?";
}

double Row::ratio() const {
  if (!(time.median_s > 0.0) || !(peer_time.median_s > 0.0)) return kNaN;
  return time.median_s / peer_time.median_s;
}

double plotted_error(const Row& row, const Knob& knob) {
  return knob.plot_error == PlotError::Rms ? row.error.rms : row.error.max;
}

void mark_pareto_fronts(Report& report) {
  std::map<std::string, const Knob*> knob_of;
  for (const Knob& k : report.knobs) knob_of[k.id] = &k;
  const auto usable = [&](const Row& r) {
    const auto it = knob_of.find(r.knob);
    return r.status == RowStatus::Ok && it != knob_of.end() && std::isfinite(r.time.median_s) &&
           std::isfinite(plotted_error(r, *it->second));
  };
  for (Row& a : report.rows) {
    a.pareto = false;
    if (!usable(a) || !knob_of[a.knob]->alternatives) continue;
    const Knob& k = *knob_of[a.knob];
    const double ta = a.time.median_s, ea = plotted_error(a, k);
    bool dominated = false;
    for (const Row& b : report.rows) {
      if (&a == &b || b.knob != a.knob || b.series != a.series || !usable(b)) continue;
      const double tb = b.time.median_s, eb = plotted_error(b, k);
      if (tb <= ta && eb <= ea && (tb < ta || eb < ea)) {
        dominated = true;
        break;
      }
    }
    a.pareto = !dominated;
  }
}

}  // namespace vdfx::app::bench
