/// @file
/// @brief `vdfx bench [--quick] [--filter REGEX] [--json F] [--csv F] [--plot DIR] [--markdown F]`:
/// every knob of numerics.md measured in one process and one run, each setting timed beside a
/// peer and compared with an exact reference; the report as markdown on stdout (docs/performance.md
/// explains every column and the JSON schema).
/// The command parses; app/bench/bench_request.h measures.
#include <unistd.h>

#include <iostream>

#include "app/bench/bench_request.h"
#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/stop_signals.h"

namespace vdfx::app {
namespace {

std::string command_line(const Args& args) {
  std::string s = "vdfx bench";
  for (const std::string& a : args)
    s += " " + (a.find_first_of(" '\"|()*") == std::string::npos ? a : "'" + a + "'");
  return s;
}

}  // namespace

int cmd_bench(const Args& args) {
  CLI::App cli{
      "Measures every speed/accuracy knob of vdfx in one run: each setting's time (median and\n"
      "90th percentile) beside a peer timed in the same loop, and its error against an exact\n"
      "reference. Prints a markdown report; GL rows need a display (xvfb-run -a on a headless\n"
      "machine) and are listed as skipped without one. docs/performance.md describes the fields.",
      "vdfx bench"};
  bench::BenchRequest req;
  bool list = false;
  std::string plot_size = "720x480";
  cli.add_flag("--quick", req.quick,
               "fewer settings and smaller images (about 2 minutes on 2 cores)");
  cli.add_option("--filter", req.filter,
                 "only rows whose KNOB/SETTING matches this regular expression");
  cli.add_flag("--list", list, "list the knobs and settings (after --quick and --filter) and exit");
  cli.add_option("--json", req.json_path, "also write the report as JSON (docs/bench.schema.json)");
  cli.add_option("--csv", req.csv_path, "also write the rows as CSV");
  cli.add_option("--markdown", req.markdown_path, "also write the markdown report to this file");
  cli.add_option("--plot", req.plot_dir,
                 "write one PNG per knob (time against error) into this folder");
  cli.add_option("--plot-size", plot_size, "size of each PNG, WxH pixels (default 720x480)");
  if (auto code = parse_cli(cli, args)) return *code;
  bench::filter_pattern(req.filter);  // a usage error before --plot-size's
  try {
    const ImageSize png = parse_size(plot_size);
    req.plot_width = png.width;
    req.plot_height = png.height;
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx bench: --plot-size " << e.what() << "\n";
    return kExitUsage;
  }
  req.command = command_line(args);
  req.progress = isatty(STDERR_FILENO) != 0;
  if (list) {
    const bench::Registry registry = bench::build_registry(req.quick);
    for (const bench::Selected& s : bench::select_rows(registry, req))
      std::cout << s.knob->knob.id << "/" << s.c->setting << (s.c->gl ? "  (GL)" : "") << "\n";
    return kExitOk;
  }
  const StopSignals stop;  // checked between rows (run_bench)
  const bench::Report report = bench::run_bench(req, std::cout);
  if (const int failed = bench::failed_rows(report)) {
    std::cerr << "vdfx bench: " << failed
              << " row(s) failed (a bug; their reasons are in the report)\n";
    return kExitInternal;
  }
  return kExitOk;
}

}  // namespace vdfx::app
