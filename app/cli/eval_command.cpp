/// @file
/// @brief `vdfx eval SIDECAR --at AZ,ALT,FRAME [--at ...]`: the interpolated parameters of every
/// effect, one JSON object per --at and per line (JSON Lines), for scripts.
#if defined(__linux__)
#include <fcntl.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <exception>
#include <future>
#include <iostream>
#include <optional>
#include <span>
#include <string>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/finite_params.h"
#include "effects/solve_threads.h"
#include "effects/stack_interpolator.h"
#include "io/input_error.h"
#include "io/params_text.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"

namespace vdfx::app {

namespace {

/// Views up to which eval stays on one thread.
constexpr std::size_t kParallelViews = 64;

/// One JSON object per view and line: "at", "effects" (io::append_stack_params_json), then the
/// flares' intensities and the grains' intensities and sizes, in file order.
struct EvalLines {
  const std::string& path;
  const effects::StackInterpolator& stack;
  const effects::FlareSet& flares;
  const effects::GrainSet& grains;

  /// The lines of `points` in one string, its size reserved after the first line (a string
  /// doubling its way to a megabyte touches and copies about three times the memory it ends with,
  /// in fresh pages).
  std::string write(std::span<const EvalPoint> points) const {
    std::string out;
    if (points.empty()) return out;
    write_one(points.front(), out);
    out.reserve(out.size() * points.size() * 5 / 4);
    for (const EvalPoint& p : points.subspan(1)) write_one(p, out);
    return out;
  }

  void write_one(const EvalPoint& p, std::string& out) const {
    const effects::StackParams params = stack.evaluate(p.direction, p.frame);
    require_finite(params, path, p.direction, p.frame);  // never print "null"
    const Eigen::Vector3d unit = effects::to_unit(p.direction);
    out += "{\"at\":{\"azimuth_deg\":";
    io::append_json_number(out, p.direction.azimuth_deg);
    out += ",\"altitude_deg\":";
    io::append_json_number(out, p.direction.altitude_deg);
    out += ",\"frame\":";
    io::append_json_integer(out, p.frame);
    out += "},\"effects\":";
    io::append_stack_params_json(out, stack, params);
    out += ",\"flares\":[";
    for (std::size_t k = 0; k < flares.size(); ++k) {
      out += k ? ",{\"intensity\":" : "{\"intensity\":";
      io::append_json_number(out, flares.intensity(k, unit, p.frame));
      out += '}';
    }
    out += "],\"grains\":[";
    for (std::size_t k = 0; k < grains.size(); ++k) {
      const effects::GrainParams g = grains.params(k, unit, p.frame);
      out += k ? ",{\"style\":" : "{\"style\":";
      io::append_json_name(out, effects::grain_style_name(grains.effect(k).style));
      out += ",\"intensity\":";
      io::append_json_number(out, g.intensity);
      out += ",\"size\":";
      io::append_json_number(out, g.size);
      out += '}';
    }
    out += "]}\n";
  }
};

/// Lets a pipe on standard output hold `bytes` (Linux, at most 1 MiB: the unprivileged maximum by
/// default). The lines for thousands of views are most of a megabyte, and through a 64 KiB pipe
/// eval waits for its reader after every 64 KiB; a file or a terminal is left as it is, and so
/// is the pipe where the system refuses.
void widen_stdout_pipe(std::size_t bytes) {
#if defined(__linux__)
  constexpr std::size_t kMost = std::size_t{1} << 20;
  (void)fcntl(STDOUT_FILENO, F_SETPIPE_SZ, static_cast<int>(std::min(bytes, kMost)));
#else
  (void)bytes;
#endif
}

}  // namespace

int cmd_eval(const Args& args) {
  CLI::App cli{
      "Prints the interpolated parameters of every effect at the given views as JSON, one\n"
      "object per --at and per line. Effects without keyframes print their neutral\n"
      "values with \"active\": false; flares print their intensity, grains their intensity\n"
      "and size, each in file order.",
      "vdfx eval"};
  std::string path;
  std::vector<std::string> at_texts;
  cli.add_option("SIDECAR", path, "the sidecar file")->required();
  cli.add_option("--at", at_texts, "a view: AZ,ALT,FRAME (degrees, degrees, frame index)")
      ->required()
      ->allow_extra_args(false);
  if (auto code = parse_cli(cli, args)) return *code;
  // Many views are read on a second thread while the sidecar is read here. A bad --at still wins
  // over a bad sidecar (a usage error, reported first).
  const auto read_points = [&at_texts] {
    std::vector<EvalPoint> points;
    points.reserve(at_texts.size());
    for (const auto& t : at_texts) points.push_back(parse_eval_point(t));
    return points;
  };
  std::future<std::vector<EvalPoint>> points_read;
  if (at_texts.size() >= kParallelViews) points_read = effects::async_beside(read_points);
  std::optional<io::Sidecar> read;
  std::exception_ptr read_error;
  try {
    read.emplace(io::read_sidecar(path));
  } catch (...) {
    read_error = std::current_exception();
  }
  std::vector<EvalPoint> points;
  try {
    points = points_read.valid() ? points_read.get() : read_points();
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx eval: " << e.what() << "\n";
    return kExitUsage;
  }
  if (read_error) std::rethrow_exception(read_error);
  const io::Sidecar& sidecar = *read;
  for (const EvalPoint& p : points) {
    if (p.frame >= sidecar.video.frames)
      throw io::InputError(path + ": --at frame " + std::to_string(p.frame) +
                           " is beyond the video's " + std::to_string(sidecar.video.frames) +
                           " frames (/video/frames)");
  }
  // Nothing else runs in this process: the solve's independent loops may use every core it is
  // allowed (two threads on one allowed core would take turns, spinning while they wait).
  effects::set_solve_threads(effects::usable_cpus());
  const effects::StackInterpolator stack = io::stack_of(sidecar);
  const effects::FlareSet flares = io::flare_set_of(sidecar);
  const effects::GrainSet grains = io::grain_set_of(sidecar);
  const EvalLines lines{path, stack, flares, grains};
  // Many views: the second half on a second thread (the interpolators are immutable). Nothing is
  // printed before every view has been evaluated (a view whose parameters are not finite is an
  // error, with no line printed before it), then the halves in the order of the --at options.
  const std::span<const EvalPoint> all(points);
  const std::size_t half = points.size() >= kParallelViews ? points.size() / 2 : points.size();
  std::future<std::string> rest;
  if (half < points.size())
    rest = effects::async_beside([&] { return lines.write(all.subspan(half)); });
  const std::string first = lines.write(all.first(half));
  const std::string second = rest.valid() ? rest.get() : std::string();
  if (!second.empty()) widen_stdout_pipe(first.size() + second.size());
  std::cout.write(first.data(), static_cast<std::streamsize>(first.size()));
  std::cout.write(second.data(), static_cast<std::streamsize>(second.size()));
  std::cout << std::flush;
  return kExitOk;
}

}  // namespace vdfx::app
