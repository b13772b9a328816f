/// @file
/// @brief run_bench: rows selected, outputs checked, every row measured beside its peer (GL rows
/// on one shared context), Pareto fronts marked, the report written.
#include "app/bench/bench_request.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <opencv2/core.hpp>
#include <sstream>

#include "app/bench/gl_rows.h"
#include "app/bench/machine.h"
#include "app/bench/output.h"
#include "app/bench/plot.h"
#include "app/cli/command_registry.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "xr/render/gl_context.h"

namespace vdfx::app::bench {
namespace {

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

/// Every output is checked (and the plot folder made) before the run.
void prepare_outputs(const BenchRequest& req) {
  if (!req.plot_dir.empty()) {
    if (const std::string problem = gnuplot_problem(); !problem.empty())
      throw UsageError("--plot needs gnuplot: " + problem);
  }
  check_output(req.json_path, "--json");
  check_output(req.csv_path, "--csv");
  check_output(req.markdown_path, "--markdown");
  if (!req.plot_dir.empty()) {  // a folder that cannot be made is the user's (exit 1)
    std::error_code ec;
    std::filesystem::create_directories(req.plot_dir, ec);
    if (ec || !std::filesystem::is_directory(req.plot_dir))
      throw io::InputError("--plot " + req.plot_dir + ": cannot create the folder" +
                           (ec ? " (" + ec.message() + ")" : " (a file of that name exists)"));
  }
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

/// Runs one row: skipped without GL when it needs it, failed (with the reason) when it throws.
Row run_row(const Selected& s, const Context& ctx, GlState& gl, Machine& machine) {
  const Knob& knob = s.knob->knob;
  Row row;
  row.knob = knob.id;
  row.setting = s.c->setting;
  row.peer = knob.peer;
  row.reference = knob.reference;
  if (s.c->gl && !gl.ready(machine)) {
    row.status = RowStatus::Skipped;
    row.reason = "needs GL: " + gl.error;
    return row;
  }
  try {
    if (gl.context) gl.context->make_current();
    s.c->run(row, ctx);
  } catch (const std::exception& e) {
    row.status = RowStatus::Failed;
    row.reason = e.what();
  }
  return row;
}

/// Every selected row, one core each (ratios compare algorithms, not how many cores each got).
Report measure(const std::vector<Selected>& selected, const BenchRequest& req) {
  Report report;
  report.command = req.command;
  report.quick = req.quick;
  report.machine = describe_machine();
  report.machine.gl_renderer = "not used (no GL row selected)";
  const Context ctx{req.quick, req.quick ? quick_budget() : full_budget()};
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const double t0 = now_s();
  {
    GlState gl;
    for (std::size_t i = 0; i < selected.size(); ++i) {
      if (req.progress) {
        std::cerr << "[" << i + 1 << "/" << selected.size() << "] " << selected[i].knob->knob.id
                  << " " << selected[i].c->setting << ": ";
        std::cerr.flush();
      }
      Row row = run_row(selected[i], ctx, gl, report.machine);
      double load[3];
      read_load(load);
      row.load1 = load[0];
      if (req.progress) std::cerr << progress_text(row) << std::endl;
      const Knob& knob = selected[i].knob->knob;
      if (report.knobs.empty() || report.knobs.back().id != knob.id) report.knobs.push_back(knob);
      report.rows.push_back(std::move(row));
    }
  }
  cv::setNumThreads(threads);
  report.wall_s = now_s() - t0;
  read_load(report.machine.load_end);
  mark_pareto_fronts(report);
  return report;
}

/// The markdown file shows the plots, linked relative to its own folder.
void link_plots(Report& report, const BenchRequest& req) {
  const auto md_dir = std::filesystem::absolute(req.markdown_path).parent_path();
  for (const Knob& k : report.knobs) {
    const auto png = std::filesystem::absolute(req.plot_dir) / (k.id + ".png");
    if (std::filesystem::exists(png))
      report.plot_links[k.id] = std::filesystem::relative(png, md_dir).generic_string();
  }
}

void write_outputs(Report& report, const BenchRequest& req) {
  if (!req.json_path.empty()) io::write_file_atomic(req.json_path, to_json(report).dump(2) + "\n");
  if (!req.csv_path.empty()) {
    std::ostringstream c;
    write_csv(c, report);
    io::write_file_atomic(req.csv_path, c.str());
  }
  if (!req.plot_dir.empty()) write_plots(report, {req.plot_dir, req.plot_width, req.plot_height});
  if (!req.markdown_path.empty()) {
    if (!req.plot_dir.empty()) link_plots(report, req);
    std::ostringstream file;
    write_markdown(file, report);
    io::write_file_atomic(req.markdown_path, file.str());
  }
}

}  // namespace

std::regex filter_pattern(const std::string& filter) {
  try {
    return std::regex(filter.empty() ? std::string(".") : filter, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw UsageError("--filter '" + filter + "' is not a regular expression: " + e.what());
  }
}

std::vector<Selected> select_rows(const Registry& registry, const BenchRequest& request) {
  const std::regex pattern = filter_pattern(request.filter);
  std::vector<Selected> selected;
  for (const KnobCases& k : registry.knobs())
    for (const Case& c : k.cases)
      if (std::regex_search(k.knob.id + "/" + c.setting, pattern)) selected.push_back({&k, &c});
  return selected;
}

Report run_bench(const BenchRequest& req, std::ostream& markdown) {
  const Registry registry = build_registry(req.quick);
  const std::vector<Selected> selected = select_rows(registry, req);
  if (selected.empty())
    throw UsageError("no knob/setting matches --filter '" + req.filter +
                     "' (vdfx bench --list shows them all)");
  prepare_outputs(req);
  Report report = measure(selected, req);
  std::ostringstream md;
  write_markdown(md, report);
  markdown << md.str();
  write_outputs(report, req);
  return report;
}

int failed_rows(const Report& report) {
  int failed = 0;
  for (const Row& r : report.rows) failed += r.status == RowStatus::Failed ? 1 : 0;
  return failed;
}

}  // namespace vdfx::app::bench
