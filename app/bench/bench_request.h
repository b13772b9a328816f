/// @file
/// @brief The work of `vdfx bench` as a library call: the command parses its options into a
/// BenchRequest and calls run_bench (tests call it without the command line). docs/bench.md.
#pragma once

#include <ostream>
#include <regex>
#include <string>
#include <vector>

#include "app/bench/registry.h"
#include "app/bench/report.h"

namespace vdfx::app::bench {

struct BenchRequest {
  bool quick = false;  //!< fewer settings and smaller images
  std::string filter;  //!< ECMAScript regular expression on KNOB/SETTING; empty: every row
  std::string json_path, csv_path, markdown_path;  //!< also write the report there (when given)
  std::string plot_dir;                            //!< one PNG per knob there (when given)
  int plot_width = 720, plot_height = 480;
  std::string command = "vdfx bench";  //!< the command line the report names
  bool progress = false;               //!< a line per row on stderr
};

/// One knob setting picked by the filter.
struct Selected {
  const KnobCases* knob;
  const Case* c;
};

/// The request's filter as a regular expression; throws app::UsageError when it is not one.
std::regex filter_pattern(const std::string& filter);

/// The registry's rows whose KNOB/SETTING matches the request's filter, in report order.
std::vector<Selected> select_rows(const Registry& registry, const BenchRequest& request);

/// Measures the selected rows (app::UsageError when the filter matches none or --plot has no
/// gnuplot; io::InputError for an output folder that is missing or cannot be made: both before
/// any row runs), writes the markdown report to `markdown` and every output file asked for, and
/// returns the report. A failed row (a bug) is in it with its reason. A stop signal
/// (app/cli/stop_signals.h) stops it between rows: app::Stopped, nothing written.
Report run_bench(const BenchRequest& request, std::ostream& markdown);

/// The rows that failed.
int failed_rows(const Report& report);

}  // namespace vdfx::app::bench
