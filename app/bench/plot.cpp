/// @file
/// @brief gnuplot scripts for the bench plots, and running gnuplot on them.
#include "app/bench/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/temp_folder.h"

extern char** environ;

namespace vdfx::app::bench {
namespace {

/// Runs gnuplot with `args`, its output into `log`; returns the exit status (-1: not started).
int run_gnuplot(const std::vector<std::string>& args, const std::filesystem::path& log) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  std::vector<std::string> all{"gnuplot"};
  all.insert(all.end(), args.begin(), args.end());
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "gnuplot", &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

/// A file of gnuplot's work folder that could not be written (its disk full, say) ends the run as
/// the user's problem (exit 1), naming the file and the system's reason; was a "gnuplot failed"
/// internal error on an empty script.
void check_written(const std::ofstream& f, const std::filesystem::path& p) {
  const int err = errno;
  if (f) return;
  throw io::InputError("cannot write " + p.string() +
                       " (the plot's work file): " + (err ? std::strerror(err) : "write failed"));
}

void write_work_file(const std::filesystem::path& p, const std::string& text) {
  errno = 0;
  std::ofstream f(p, std::ios::binary);
  f << text;
  f.close();
  check_written(f, p);
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A string inside a gnuplot single-quoted literal ('' is a quote there).
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

struct Axis {
  bool log = false;
  double scale = 1.0;  //!< multiplies the values (time unit)
  std::string unit;
};

/// A time unit that keeps the values between about 0.1 and 1000.
Axis time_axis(const std::vector<double>& t) {
  const double lo = *std::min_element(t.begin(), t.end()),
               hi = *std::max_element(t.begin(), t.end());
  Axis a;
  const double ref = std::sqrt(lo * hi);
  if (ref < 1e-6)
    a = {false, 1e9, "ns"};
  else if (ref < 1e-3)
    a = {false, 1e6, "us"};
  else if (ref < 1.0)
    a = {false, 1e3, "ms"};
  else
    a = {false, 1.0, "s"};
  a.log = lo > 0 && hi / lo > 20.0;
  return a;
}

struct Point {
  double t, e;
  std::string label;
  bool pareto;
  std::string series;
};

/// Position of a value on an axis in [0, 1] (log or linear), for spotting crowded labels.
double axis_pos(double v, double lo, double hi, bool log) {
  if (log) return (std::log(v) - std::log(lo)) / std::max(std::log(hi) - std::log(lo), 1e-12);
  return (v - lo) / std::max(hi - lo, 1e-300);
}

/// Wraps `text` at spaces into lines of at most `width` characters.
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines{""};
  std::istringstream in(text);
  for (std::string w; in >> w;) {
    if (!lines.back().empty() && lines.back().size() + 1 + w.size() > width) lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + w;
  }
  return lines;
}

/// What one knob's plot shows: its points in the axes' units, the axes' ranges and the shared
/// peer's time.
struct PlotData {
  std::vector<Point> pts;
  Axis x;
  double t_lo = 0.0, t_hi = 0.0;  //!< time range, scaled
  bool ylog = false;
  bool zeros = false;   //!< some error is 0 (drawn at the bottom of a log axis)
  double pos_hi = 0.0;  //!< the largest positive error (0: none)
  double e_lo = 0.0, e_hi = 0.0;
  bool shared_peer = true;  //!< every setting has the same peer (and one series)
  double peer_s = NAN;      //!< that peer's median time, unscaled
};

/// The peer's time as a dashed line when every setting has the same peer (and one series: a
/// peer at another sigma is another time): the median of its times.
void find_shared_peer(const std::vector<const Row*>& rows, PlotData& p) {
  std::vector<double> peer_t;
  for (const Row* r : rows) {
    p.shared_peer = p.shared_peer && r->peer == rows.front()->peer &&
                    r->series == rows.front()->series && std::isfinite(r->peer_time.median_s);
    peer_t.push_back(r->peer_time.median_s);
  }
  if (!p.shared_peer) return;
  std::sort(peer_t.begin(), peer_t.end());
  p.peer_s = peer_t[peer_t.size() / 2];
}

/// The error axis: logarithmic when the positive errors span more than a factor 20, a zero error
/// then drawn a decade below the smallest.
void error_axis(const std::vector<double>& es, PlotData& p) {
  double pos_lo = INFINITY;
  for (double e : es) {
    if (e > 0) {
      pos_lo = std::min(pos_lo, e);
      p.pos_hi = std::max(p.pos_hi, e);
    } else {
      p.zeros = true;
    }
  }
  p.ylog = p.pos_hi > 0 && p.pos_hi / pos_lo > 20.0;
  p.e_lo = p.ylog ? pos_lo / 10.0 : 0.0;
  p.e_hi = std::max(p.pos_hi, 1e-300);
}

PlotData plot_data(const Knob& k, const std::vector<const Row*>& rows) {
  PlotData p;
  std::vector<double> ts, es;
  for (const Row* r : rows) {
    ts.push_back(r->time.median_s);
    es.push_back(plotted_error(*r, k));
  }
  find_shared_peer(rows, p);
  std::vector<double> all_t = ts;
  if (p.shared_peer) all_t.push_back(p.peer_s);
  p.x = time_axis(all_t);
  p.t_lo = *std::min_element(all_t.begin(), all_t.end()) * p.x.scale;
  p.t_hi = *std::max_element(all_t.begin(), all_t.end()) * p.x.scale;
  error_axis(es, p);
  const double floor_e = p.ylog ? p.e_lo : 0.0;  // where a zero error is drawn on a log axis
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::string label = rows[i]->setting;
    std::replace(label.begin(), label.end(), '"', '\'');
    const bool zero = !(es[i] > 0);
    p.pts.push_back({ts[i] * p.x.scale, zero ? floor_e : es[i],
                     label + (zero && p.ylog ? " (0)" : ""), rows[i]->pareto, rows[i]->series});
  }
  return p;
}

/// A label goes to the first of four places (above right, below right, above left, below left)
/// that no earlier label near its point took.
std::vector<int> label_places(const PlotData& p) {
  const double e_lo = p.e_lo > 0 ? p.e_lo : 1e-300;
  std::vector<int> place(p.pts.size(), 0);
  for (std::size_t i = 0; i < p.pts.size(); ++i) {
    std::array<bool, 4> taken{};
    for (std::size_t j = 0; j < i; ++j) {
      const double dx = axis_pos(p.pts[i].t, p.t_lo, p.t_hi, p.x.log) -
                        axis_pos(p.pts[j].t, p.t_lo, p.t_hi, p.x.log);
      const double dy =
          axis_pos(p.pts[i].e, e_lo, p.e_hi, p.ylog) - axis_pos(p.pts[j].e, e_lo, p.e_hi, p.ylog);
      if (std::abs(dx) < 0.25 && std::abs(dy) < 0.08)
        taken[static_cast<std::size_t>(place[j])] = true;
    }
    while (place[i] < 3 && taken[static_cast<std::size_t>(place[i])]) ++place[i];
  }
  return place;
}

/// One front per series, each sorted by time; a single blank line breaks the line between them.
void write_fronts(std::ostream& d, const std::vector<Point>& pts) {
  std::vector<Point> front;
  for (const Point& p : pts)
    if (p.pareto) front.push_back(p);
  std::sort(front.begin(), front.end(), [](const Point& a, const Point& b) {
    return a.series != b.series ? a.series < b.series : a.t < b.t;
  });
  for (std::size_t i = 0; i < front.size(); ++i) {
    if (i > 0 && front[i].series != front[i - 1].series) d << "\n";
    d << front[i].t << " " << front[i].e << "\n";
  }
  if (front.empty()) d << "NaN NaN\n";  // keeps the block, and so the next blocks' indices
}

/// Data blocks: 0 every setting, 1 the fronts, 2 the shared peer's time, 3 to 6 the labels in
/// each of their four places.
void write_data(const PlotData& p, const std::filesystem::path& data) {
  std::ofstream d(data);
  d.precision(10);
  for (const Point& pt : p.pts) d << pt.t << " " << pt.e << "\n";
  d << "\n\n";
  write_fronts(d, p.pts);
  d << "\n\n";
  const double peer_t = p.peer_s * p.x.scale;
  if (p.shared_peer)
    d << peer_t << " " << p.e_lo << "\n" << peer_t << " " << p.e_hi << "\n";
  else
    d << "NaN NaN\n";
  d << "\n\n";
  const std::vector<int> place = label_places(p);
  for (int where = 0; where < 4; ++where) {
    bool any = false;
    for (std::size_t i = 0; i < p.pts.size(); ++i)
      if (place[i] == where) {
        d << p.pts[i].t << " " << p.pts[i].e << " \"" << p.pts[i].label << "\"\n";
        any = true;
      }
    if (!any) d << "NaN NaN \"\"\n";
    d << "\n\n";
  }
  d.close();
  check_written(d, data);
}

/// The terminal, title, axes' labels and scales.
void write_frame(std::ostream& s, const Knob& k, const PlotData& p,
                 const std::filesystem::path& png, const PlotOptions& o) {
  std::string title = k.id;
  for (const std::string& line : wrap(k.title, static_cast<std::size_t>(o.width / 7)))
    title += "\\n" + line;
  std::replace(title.begin(), title.end(), '"', '\'');
  s << "set terminal pngcairo size " << o.width << "," << o.height
    << " font 'DejaVu Sans,9' noenhanced\n"
    << "set output " << quoted(png.string()) << "\n"
    << "set title \"" << title << "\"\n"
    << "set xlabel " << quoted("median time per " + k.per + " (" + p.x.unit + ")") << "\n"
    << "set ylabel "
    << quoted(std::string(k.plot_error == PlotError::Rms ? "RMS" : "max") + " error (" +
              k.error_unit + ")")
    << "\n"
    << "set grid\nset key outside bottom center horizontal\n"
    << "set offsets graph 0.05, graph 0.3, graph 0.1, graph 0.1\n";
  if (p.x.log) s << "set logscale x\n";
  if (p.ylog) {
    s << "set logscale y\nset format y '%.0e'\n";
    if (p.zeros)
      s << "set label 1 'error 0 drawn at the bottom, marked (0)' at graph 0.01, graph 0.03 font "
           "',8'\n";
  } else if (p.pos_hi == 0.0) {
    s << "set yrange [-1:1]\n";
  }
}

std::string script_for(const Knob& k, const std::vector<const Row*>& rows,
                       const std::filesystem::path& data, const std::filesystem::path& png,
                       const PlotOptions& o) {
  const PlotData p = plot_data(k, rows);
  write_data(p, data);
  std::ostringstream s;
  write_frame(s, k, p, png, o);
  s << "plot " << quoted(data.string())
    << " index 0 using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'settings', \\\n"
    << "  '' index 3 using 1:2:3 with labels left offset char 0.7,0.6 font ',8' notitle, \\\n"
    << "  '' index 4 using 1:2:3 with labels left offset char 0.7,-0.7 font ',8' notitle, \\\n"
    << "  '' index 5 using 1:2:3 with labels right offset char -0.7,0.6 font ',8' notitle, \\\n"
    << "  '' index 6 using 1:2:3 with labels right offset char -0.7,-0.7 font ',8' notitle";
  if (k.alternatives)
    s << ", \\\n  '' index 1 using 1:2 with lines lw 2 lc rgb '#d62728' title "
      << quoted(std::string("Pareto front") +
                (rows.front()->series.empty() ? "" : " (per series)"));
  if (p.shared_peer)
    s << ", \\\n  '' index 2 using 1:2 with lines dt 2 lw 1.5 lc rgb '#555555' title "
      << quoted("peer: " + rows.front()->peer);
  s << "\n";
  return s.str();
}

}  // namespace

std::string gnuplot_problem() {
  const io::TempFolder work("vdfx-gnuplot-check");
  const auto log = work.path() / "check.txt";
  const int rc = run_gnuplot({"-e", "set terminal pngcairo"}, log);
  const std::string out = read_text(log);
  if (rc == -1) return "gnuplot is not installed (Debian package gnuplot-nox)";
  if (rc != 0) return "gnuplot has no pngcairo terminal: " + out;
  return {};
}

std::vector<std::filesystem::path> write_plots(const Report& report, const PlotOptions& o) {
  std::filesystem::create_directories(o.dir);
  // gnuplot's work folder: new, vdfx's own, removed with what is in it however this ends.
  const io::TempFolder temp("vdfx-bench-plot");
  const std::filesystem::path& work = temp.path();
  std::vector<std::filesystem::path> written;
  for (const Knob& k : report.knobs) {
    std::vector<const Row*> rows;
    for (const Row& r : report.rows)
      if (r.knob == k.id && r.status == RowStatus::Ok && std::isfinite(r.time.median_s) &&
          std::isfinite(plotted_error(r, k)))
        rows.push_back(&r);
    if (rows.empty()) continue;
    const auto png = o.dir / (k.id + ".png");
    // gnuplot draws into the work folder; the finished picture then replaces PNG atomically (a
    // killed run or a failing gnuplot never leaves a half-written plot, a link is written
    // through).
    const auto data = work / (k.id + ".dat"), script = work / (k.id + ".gp"),
               log = work / (k.id + ".log"), drawn = work / (k.id + ".png");
    write_work_file(script, script_for(k, rows, data, drawn, o));
    if (run_gnuplot({script.string()}, log) != 0 || !std::filesystem::exists(drawn)) {
      throw std::runtime_error("gnuplot failed on the plot of " + k.id + ": " + read_text(log));
    }
    io::write_file_atomic(png, read_text(drawn));
    written.push_back(png);
  }
  return written;
}

}  // namespace vdfx::app::bench
