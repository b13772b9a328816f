/// @file
/// @brief Markdown, CSV and JSON forms of a bench report.
#include "app/bench/output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vdfx::app::bench {

std::string format_number(double v, int digits, const char* missing) {
  if (!std::isfinite(v)) return missing;
  char b[32];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string setting_number(double v) {
  return format_number(v, 6);
}
std::string setting_degrees(double v) {
  return setting_number(v) + " deg";
}

std::string format_time(double s) {
  if (!std::isfinite(s)) return "-";
  const char* unit = "s";
  double v = s;
  if (s < 1e-6) {
    v = s * 1e9;
    unit = "ns";
  } else if (s < 1e-3) {
    v = s * 1e6;
    unit = "us";
  } else if (s < 1.0) {
    v = s * 1e3;
    unit = "ms";
  }
  char b[32];
  std::snprintf(b, sizeof b, "%.3g %s", v, unit);
  return b;
}

namespace {

std::string load_text(const double l[3]) {
  return format_number(l[0]) + " / " + format_number(l[1]) + " / " + format_number(l[2]);
}

std::string extras_text(const Row& r) {
  std::string s;
  for (const auto& [name, value] : r.extra)
    s += (s.empty() ? "" : ", ") + name + " " + format_number(value);
  if (!r.note.empty()) s += (s.empty() ? "" : "; ") + r.note;
  return s;
}

/// CSV field: quoted when it holds a separator, a quote or a line break.
std::string csv(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv(double v) {
  return format_number(v, 6, "");
}

nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json time_json(const TimeStats& t) {
  return {{"median_s", number_or_null(t.median_s)},
          {"p90_s", number_or_null(t.p90_s)},
          {"samples", t.samples}};
}

}  // namespace

void write_markdown(std::ostream& out, const Report& rep) {
  const Machine& m = rep.machine;
  out << "# vdfx bench: speed against error\n\n"
      << "- command: `" << rep.command << "`"
      << (rep.quick ? " (quick: fewer settings, smaller images)" : "") << "\n- machine: " << m.cpu
      << ", " << m.physical_cores << " cores (" << m.logical_cpus
      << " logical CPUs); GL: " << m.gl_renderer
      << (m.gl_version.empty() ? "" : ", " + m.gl_version) << "\n- build: " << m.build
      << "; CPU rows single-threaded (OpenCV too), GL rows on the driver's own threads, video "
         "rows on the decoder's, the export's and x264's"
      << "\n- started " << m.date_utc << ", took " << format_time(rep.wall_s)
      << "; load average (1 / 5 / 15 min) " << load_text(m.load_start) << " at the start, "
      << load_text(m.load_end) << " at the end\n";
  // A load above the CPU count means other work shared the machine: say so where it is read.
  const double peak_load = std::max(m.load_start[0], m.load_end[0]);
  if (m.logical_cpus > 0 && peak_load > m.logical_cpus)
    out << "- **shared machine**: the 1-minute load (up to " << format_number(peak_load)
        << ") exceeded the " << m.logical_cpus
        << " logical CPUs, so other work ran beside this one: absolute times are inflated and "
           "noisy, the ratios to the interleaved peers are what to compare\n";
  out << "\n"
      << "Times are medians (and 90th percentiles) of wall-clock samples per unit of work; each\n"
         "setting is timed interleaved with its peer, so the ratio holds even on a busy machine.\n"
         "Rows marked * are on the knob's Pareto front (no other setting of the same series, e.g.\n"
         "the same sigma, is both faster and more accurate); knobs whose settings are sizes or\n"
         "different jobs (N, one effect each) have none. docs/bench.md explains every knob, "
         "column\n"
         "and the JSON schema.\n";
  for (const Knob& k : rep.knobs) {
    out << "\n## " << k.id << ": " << k.title << "\n\n"
        << "Time per " << k.per << "; error in " << k.error_unit << " against " << k.reference
        << "; peer: " << k.peer << ".\n\n"
        << "| setting | median | p90 | peer median | ratio | max error | RMS error | notes |\n"
        << "|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rep.rows) {
      if (r.knob != k.id) continue;
      out << "| " << r.setting << (r.pareto ? " *" : "");
      if (r.status != RowStatus::Ok) {
        out << " | " << to_string(r.status) << ": " << r.reason << " | | | | | | |\n";
        continue;
      }
      std::string notes = extras_text(r);
      if (r.peer != k.peer) notes = "peer: " + r.peer + (notes.empty() ? "" : "; " + notes);
      if (r.reference != k.reference)
        notes = "reference: " + r.reference + (notes.empty() ? "" : "; " + notes);
      out << " | " << format_time(r.time.median_s) << " | " << format_time(r.time.p90_s) << " | "
          << format_time(r.peer_time.median_s) << " | " << format_number(r.ratio()) << " | "
          << format_number(r.error.max) << " | " << format_number(r.error.rms) << " | " << notes
          << " |\n";
    }
    if (const auto it = rep.plot_links.find(k.id); it != rep.plot_links.end())
      out << "\n![" << k.id << ": time against error](" << it->second << ")\n";
  }
}

void write_csv(std::ostream& out, const Report& rep) {
  out << "knob,setting,series,status,per,median_s,p90_s,samples,peer,peer_median_s,peer_p90_s,"
         "ratio,"
         "error_max,error_rms,error_unit,reference,pareto,load1,extra,note,reason\n";
  for (const Row& r : rep.rows) {
    const Knob* k = nullptr;
    for (const Knob& kk : rep.knobs)
      if (kk.id == r.knob) k = &kk;
    std::string extra;
    for (const auto& [name, value] : r.extra)
      extra += (extra.empty() ? "" : ";") + name + "=" + csv(value);
    out << csv(r.knob) << "," << csv(r.setting) << "," << csv(r.series) << ","
        << to_string(r.status) << "," << csv(k ? k->per : "") << "," << csv(r.time.median_s) << ","
        << csv(r.time.p90_s) << "," << r.time.samples << "," << csv(r.peer) << ","
        << csv(r.peer_time.median_s) << "," << csv(r.peer_time.p90_s) << "," << csv(r.ratio())
        << "," << csv(r.error.max) << "," << csv(r.error.rms) << "," << csv(k ? k->error_unit : "")
        << "," << csv(r.reference) << "," << (r.pareto ? "true" : "false") << "," << csv(r.load1)
        << "," << csv(extra) << "," << csv(r.note) << "," << csv(r.reason) << "\n";
  }
}

nlohmann::ordered_json to_json(const Report& rep) {
  const Machine& m = rep.machine;
  nlohmann::ordered_json j;
  j["format"] = "vdfx.bench";
  j["version"] = 1;
  j["command"] = rep.command;
  j["quick"] = rep.quick;
  j["wall_s"] = rep.wall_s;
  j["machine"] = {{"cpu", m.cpu},
                  {"logical_cpus", m.logical_cpus},
                  {"physical_cores", m.physical_cores},
                  {"gl_renderer", m.gl_renderer},
                  {"gl_version", m.gl_version},
                  {"build", m.build},
                  {"date_utc", m.date_utc},
                  {"load_start",
                   {number_or_null(m.load_start[0]), number_or_null(m.load_start[1]),
                    number_or_null(m.load_start[2])}},
                  {"load_end",
                   {number_or_null(m.load_end[0]), number_or_null(m.load_end[1]),
                    number_or_null(m.load_end[2])}}};
  nlohmann::ordered_json knobs = nlohmann::ordered_json::array();
  for (const Knob& k : rep.knobs)
    knobs.push_back({{"id", k.id},
                     {"title", k.title},
                     {"per", k.per},
                     {"error_unit", k.error_unit},
                     {"reference", k.reference},
                     {"peer", k.peer},
                     {"plot_error", k.plot_error == PlotError::Rms ? "rms" : "max"},
                     {"needs_gl", k.needs_gl},
                     {"alternatives", k.alternatives}});
  j["knobs"] = std::move(knobs);
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const Row& r : rep.rows) {
    nlohmann::ordered_json extra = nlohmann::ordered_json::object();
    for (const auto& [name, value] : r.extra) extra[name] = number_or_null(value);
    rows.push_back({{"knob", r.knob},
                    {"setting", r.setting},
                    {"series", r.series},
                    {"status", to_string(r.status)},
                    {"reason", r.reason.empty() ? nlohmann::ordered_json(nullptr)
                                                : nlohmann::ordered_json(r.reason)},
                    {"time", time_json(r.time)},
                    {"peer",
                     {{"name", r.peer},
                      {"median_s", number_or_null(r.peer_time.median_s)},
                      {"p90_s", number_or_null(r.peer_time.p90_s)},
                      {"samples", r.peer_time.samples}}},
                    {"ratio", number_or_null(r.ratio())},
                    {"error",
                     {{"max", number_or_null(r.error.max)},
                      {"rms", number_or_null(r.error.rms)},
                      {"reference", r.reference}}},
                    {"extra", std::move(extra)},
                    {"note", r.note},
                    {"pareto", r.pareto},
                    {"load1", number_or_null(r.load1)}});
  }
  j["rows"] = std::move(rows);
  return j;
}

}  // namespace vdfx::app::bench
