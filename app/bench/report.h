/// @file
/// @brief What `vdfx bench` measures and reports: one row per knob setting (time and its peer's
/// time measured beside it, error against an exact reference), the knobs' descriptions, the
/// machine, and the Pareto front of each knob (docs/performance.md documents the fields).
#pragma once

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vdfx::app::bench {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Robust summary of repeated timings of one thing, seconds per unit (see Knob::per).
struct TimeStats {
  double median_s = kNaN;
  double p90_s = kNaN;
  int samples = 0;
};

/// Error of a setting against its reference, in the knob's unit. NaN where not measured.
struct ErrorStats {
  double max = kNaN;
  double rms = kNaN;
};

enum class RowStatus { Ok, Skipped, Failed };
const char* to_string(RowStatus s);

/// One measured setting of a knob.
struct Row {
  std::string knob;     //!< Knob::id
  std::string setting;  //!< e.g. "N=1000", "mesh 65", "pyramid 2 deg"
  std::string series;   //!< settings of one series are alternatives to each other (e.g. one sigma)
  RowStatus status = RowStatus::Ok;
  std::string reason;  //!< why a row was skipped or failed
  TimeStats time;
  std::string peer;  //!< what was timed beside it (the knob's peer unless a row says else)
  TimeStats peer_time;
  ErrorStats error;
  std::string reference;  //!< what the error is measured against (the knob's unless overridden)
  std::string note;       //!< anything else a reader needs (solver method, input used)
  std::vector<std::pair<std::string, double>> extra;  //!< more figures: condition, mean error...
  bool pareto = false;  //!< on its knob's (series') time / error Pareto front
  double load1 = kNaN;  //!< 1-minute load average when the row finished

  /// time.median / peer_time.median (NaN when either is missing).
  double ratio() const;
  void add(const std::string& name, double value) { extra.emplace_back(name, value); }
};

/// Which error the plot and the Pareto front use.
enum class PlotError { Max, Rms };

/// A knob of numerics.md: what is varied, what one timed unit is, and in which unit it errs.
struct Knob {
  std::string id;          //!< "rbf.solve": group.name, used by --filter and as the plot name
  std::string title;       //!< one line: what is varied and what is measured
  std::string per;         //!< what one timed unit is: "solve", "view", "point", "eye"
  std::string error_unit;  //!< "px", "8-bit steps", "stops", "parameter units"
  std::string reference;   //!< the exact reference of the errors
  std::string peer;        //!< what each setting is timed beside
  PlotError plot_error = PlotError::Max;
  bool needs_gl = false;
  //! true: the settings are alternatives for one job (a Pareto front per series is marked);
  //! false: they are problem sizes or different jobs (N, one effect each), no front.
  bool alternatives = true;  //!< every row needs a GL context (skipped with the reason without one)
};

/// The machine the report was made on.
struct Machine {
  std::string cpu;  //!< /proc/cpuinfo model name
  int logical_cpus = 0;
  int physical_cores = 0;
  std::string gl_renderer;  //!< GL_RENDERER, or why there is none
  std::string gl_version;
  std::string build;                          //!< build type and instruction-set floor
  std::string date_utc;                       //!< ISO 8601, when the run started
  double load_start[3] = {kNaN, kNaN, kNaN};  //!< /proc/loadavg 1, 5, 15 minutes
  double load_end[3] = {kNaN, kNaN, kNaN};
};

struct Report {
  std::string command;  //!< the command line that made it
  bool quick = false;
  Machine machine;
  std::vector<Knob> knobs;  //!< those with at least one row, in run order
  std::vector<Row> rows;
  double wall_s = 0.0;  //!< the whole run
  //! Knob id -> its plot, relative to where the markdown is written (images in --markdown).
  std::map<std::string, std::string> plot_links;
};

/// Marks the rows of knobs with alternatives that no other ok row of the same knob and series
/// beats in both time and error (the knob's PlotError); rows without a time or an error, and
/// rows of knobs without alternatives, are never on a front.
void mark_pareto_fronts(Report& report);

/// The error of a row the knob plots (max or RMS).
double plotted_error(const Row& row, const Knob& knob);

}  // namespace vdfx::app::bench
