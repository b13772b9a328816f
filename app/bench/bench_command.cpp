/// @file
/// @brief `vdfx bench [--quick] [--filter REGEX] [--json F] [--csv F] [--plot DIR] [--markdown F]`:
/// every knob of numerics.md measured in one process and one run, each setting timed beside a
/// peer and compared with an exact reference; the report as markdown on stdout (docs/performance.md
/// explains every column and the JSON schema).
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <opencv2/core.hpp>
#include <regex>
#include <sstream>

#include "app/bench/gl_rows.h"
#include "app/bench/machine.h"
#include "app/bench/output.h"
#include "app/bench/plot.h"
#include "app/bench/registry.h"
#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "xr/gl_context.h"

namespace vdfx::app {
namespace {

using namespace bench;

struct Selected {
  const KnobCases* knob;
  const Case* c;
};

std::string command_line(const Args& args) {
  std::string s = "vdfx bench";
  for (const std::string& a : args)
    s += " " + (a.find_first_of(" '\"|()*") == std::string::npos ? a : "'" + a + "'");
  return s;
}

/// The GL context the GL rows share, created at the first GL row; without a display its error
/// becomes every GL row's reason for being skipped.
struct GlState {
  std::unique_ptr<xr::GlContext> context;
  std::string error;
  bool tried = false;

  bool ready(Machine& m) {
    if (!tried) {
      tried = true;
      try {
        context = xr::GlContext::create();
        m.gl_renderer = context->renderer();
        m.gl_version = context->version();
      } catch (const std::exception& e) {
        error = e.what();
        m.gl_renderer = "none (" + error + ")";
      }
    }
    return context != nullptr;
  }
  ~GlState() {
    if (context) {
      context->make_current();
      release_gl_caches();
    }
  }
};

/// A folder that will hold an output file must exist before an hour of measuring starts.
void check_output(const std::string& path, const char* option) {
  if (path.empty()) return;
  const auto parent = std::filesystem::absolute(path).parent_path();
  if (!std::filesystem::is_directory(parent))
    throw io::InputError(std::string(option) + " " + path + ": the folder " + parent.string() +
                         " does not exist");
}

/// The end of a row's progress line (its start, knob and setting, is printed before it runs).
std::string progress_text(const Row& r) {
  std::ostringstream s;
  if (r.status != RowStatus::Ok) {
    s << to_string(r.status) << " (" << r.reason << ")";
  } else {
    s << format_time(r.time.median_s) << " (peer " << format_time(r.peer_time.median_s)
      << ", ratio " << format_number(r.ratio()) << "), max error " << format_number(r.error.max);
  }
  return s.str();
}

}  // namespace

int cmd_bench(const Args& args) {
  CLI::App cli{
      "Measures every speed/accuracy knob of vdfx in one run: each setting's time (median and\n"
      "90th percentile) beside a peer timed in the same loop, and its error against an exact\n"
      "reference. Prints a markdown report; GL rows need a display (xvfb-run -a on a headless\n"
      "machine) and are listed as skipped without one. docs/performance.md describes the fields.",
      "vdfx bench"};
  bool quick = false, list = false;
  std::string filter, json_path, csv_path, md_path, plot_dir, plot_size = "720x480";
  cli.add_flag("--quick", quick, "fewer settings and smaller images (about 2 minutes on 2 cores)");
  cli.add_option("--filter", filter,
                 "only rows whose KNOB/SETTING matches this regular expression");
  cli.add_flag("--list", list, "list the knobs and settings (after --quick and --filter) and exit");
  cli.add_option("--json", json_path, "also write the report as JSON (docs/bench.schema.json)");
  cli.add_option("--csv", csv_path, "also write the rows as CSV");
  cli.add_option("--markdown", md_path, "also write the markdown report to this file");
  cli.add_option("--plot", plot_dir,
                 "write one PNG per knob (time against error) into this folder");
  cli.add_option("--plot-size", plot_size, "size of each PNG, WxH pixels (default 720x480)");
  if (auto code = parse_cli(cli, args)) return *code;

  std::regex pattern;
  ImageSize png{};
  try {
    pattern = std::regex(filter.empty() ? std::string(".") : filter, std::regex::ECMAScript);
    png = parse_size(plot_size);
  } catch (const std::regex_error& e) {
    std::cerr << "vdfx bench: --filter '" << filter << "' is not a regular expression: " << e.what()
              << "\n";
    return kExitUsage;
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx bench: --plot-size " << e.what() << "\n";
    return kExitUsage;
  }

  const Registry registry = build_registry(quick);
  std::vector<Selected> selected;
  for (const KnobCases& k : registry.knobs())
    for (const Case& c : k.cases)
      if (std::regex_search(k.knob.id + "/" + c.setting, pattern)) selected.push_back({&k, &c});
  if (list) {
    for (const Selected& s : selected)
      std::cout << s.knob->knob.id << "/" << s.c->setting << (s.c->gl ? "  (GL)" : "") << "\n";
    return kExitOk;
  }
  if (selected.empty()) {
    std::cerr << "vdfx bench: no knob/setting matches --filter '" << filter
              << "' (vdfx bench --list shows them all)\n";
    return kExitUsage;
  }
  if (!plot_dir.empty()) {
    if (const std::string problem = gnuplot_problem(); !problem.empty()) {
      std::cerr << "vdfx bench: --plot needs gnuplot: " << problem << "\n";
      return kExitUsage;
    }
  }
  check_output(json_path, "--json");
  check_output(csv_path, "--csv");
  check_output(md_path, "--markdown");
  if (!plot_dir.empty()) {  // before the run: a folder that cannot be made is the user's (exit 1)
    std::error_code ec;
    std::filesystem::create_directories(plot_dir, ec);
    if (ec || !std::filesystem::is_directory(plot_dir))
      throw io::InputError("--plot " + plot_dir + ": cannot create the folder" +
                           (ec ? " (" + ec.message() + ")" : " (a file of that name exists)"));
  }

  Report report;
  report.command = command_line(args);
  report.quick = quick;
  report.machine = describe_machine();
  report.machine.gl_renderer = "not used (no GL row selected)";
  const Context ctx{quick, quick ? quick_budget() : full_budget()};
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);  // ratios compare algorithms, not how many cores each one got
  const double t0 = now_s();
  {
    GlState gl;
    for (std::size_t i = 0; i < selected.size(); ++i) {
      const Knob& knob = selected[i].knob->knob;
      Row row;
      row.knob = knob.id;
      row.setting = selected[i].c->setting;
      row.peer = knob.peer;
      row.reference = knob.reference;
      if (terminal) {
        std::cerr << "[" << i + 1 << "/" << selected.size() << "] " << row.knob << " "
                  << row.setting << ": ";
        std::cerr.flush();
      }
      if (selected[i].c->gl && !gl.ready(report.machine)) {
        row.status = RowStatus::Skipped;
        row.reason = "needs GL: " + gl.error;
      } else {
        try {
          if (gl.context) gl.context->make_current();
          selected[i].c->run(row, ctx);
        } catch (const std::exception& e) {
          row.status = RowStatus::Failed;
          row.reason = e.what();
        }
      }
      double load[3];
      read_load(load);
      row.load1 = load[0];
      if (terminal) std::cerr << progress_text(row) << std::endl;
      if (report.knobs.empty() || report.knobs.back().id != knob.id) report.knobs.push_back(knob);
      report.rows.push_back(std::move(row));
    }
  }
  cv::setNumThreads(threads);
  report.wall_s = now_s() - t0;
  read_load(report.machine.load_end);
  mark_pareto_fronts(report);

  std::ostringstream md;
  write_markdown(md, report);
  std::cout << md.str();
  if (!json_path.empty()) io::write_file_atomic(json_path, to_json(report).dump(2) + "\n");
  if (!csv_path.empty()) {
    std::ostringstream c;
    write_csv(c, report);
    io::write_file_atomic(csv_path, c.str());
  }
  if (!plot_dir.empty()) write_plots(report, {plot_dir, png.width, png.height});
  if (!md_path.empty()) {
    if (!plot_dir.empty()) {  // the file shows the plots, linked relative to its own folder
      const auto md_dir = std::filesystem::absolute(md_path).parent_path();
      for (const Knob& k : report.knobs) {
        const auto png_path = std::filesystem::absolute(plot_dir) / (k.id + ".png");
        if (std::filesystem::exists(png_path))
          report.plot_links[k.id] = std::filesystem::relative(png_path, md_dir).generic_string();
      }
    }
    std::ostringstream file;
    write_markdown(file, report);
    io::write_file_atomic(md_path, file.str());
  }

  int failed = 0;
  for (const Row& r : report.rows) failed += r.status == RowStatus::Failed ? 1 : 0;
  if (failed) {
    std::cerr << "vdfx bench: " << failed
              << " row(s) failed (a bug; their reasons are in the report)\n";
    return kExitInternal;
  }
  return kExitOk;
}

}  // namespace vdfx::app
