#include "app/cli/cli_util.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <vector>

#include "io/excerpt.h"

namespace vdfx::app {

std::optional<int> parse_cli(CLI::App& cli, const Args& args) {
  // CLI11 takes a vector in reverse order (it pops arguments from the back).
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    cli.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << cli.help();
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    // CLI11 quotes the option's value; an argument can be 128 KiB long.
    std::cerr << cli.get_name() << ": " << io::excerpt(e.what(), 300) << "\n(" << cli.get_name()
              << " --help lists the options)\n";
    return kExitUsage;
  }
  return std::nullopt;
}

namespace {

/// The text quoted in a message: at most 40 bytes of it, control bytes spelled out.
std::string cli_quote(const std::string& text) {
  return "'" + io::excerpt(text, 40) + "'";
}

std::vector<double> split_numbers(const std::string& text, char sep, const char* what) {
  std::vector<double> values;
  size_t start = 0;
  while (true) {
    const size_t end = text.find(sep, start);
    const std::string part = text.substr(start, end == std::string::npos ? end : end - start);
    double v = 0.0;
    const char* first = part.data();
    const char* last = part.data() + part.size();
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (part.empty() || ec != std::errc() || ptr != last || !std::isfinite(v))
      throw CLI::ValidationError(
          what, cli_quote(text) + ": " + cli_quote(part) + " is not a finite number");
    values.push_back(v);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return values;
}

void check_direction(const effects::Direction& d, const std::string& text, const char* what) {
  if (d.altitude_deg < -90.0 || d.altitude_deg > 90.0)
    throw CLI::ValidationError(what, cli_quote(text) + ": altitude must be in [-90, 90] degrees");
}

}  // namespace

namespace {

std::string bound_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

CLI::Validator finite_range(double lo, double hi) {
  const std::string range = "[" + bound_text(lo) + ", " + bound_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        double v = 0.0;
        const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() ||
            !std::isfinite(v))
          return cli_quote(text) + " is not a finite number";
        if (v < lo || v > hi) return cli_quote(text) + " is out of range " + range;
        return {};
      },
      "number in " + range);
}

CLI::Validator whole_range(std::int64_t lo, std::int64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::int64_t v = 0;
        const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc::result_out_of_range || (ec == std::errc() && (v < lo || v > hi)))
          return cli_quote(text) + " is out of range " + range;
        if (text.empty() || ec != std::errc() || ptr != text.data() + text.size())
          return cli_quote(text) + " is not a whole number";
        return {};
      },
      "whole number in " + range);
}

ViewSpec parse_view(const std::string& text) {
  const auto v = split_numbers(text, ',', "--view");
  if (v.size() != 2 && v.size() != 3)
    throw CLI::ValidationError("--view", cli_quote(text) + ": expected AZ,ALT or AZ,ALT,ROLL");
  ViewSpec s;
  s.direction = {effects::wrap_azimuth_deg(v[0]), v[1]};
  s.roll_deg = v.size() == 3 ? v[2] : 0.0;
  check_direction(s.direction, text, "--view");
  return s;
}

EvalPoint parse_eval_point(const std::string& text) {
  // FRAME is read as an integer, exactly: through a double, 9007199254740993 would round.
  const std::size_t last_comma = text.rfind(',');
  const std::string frame_text = last_comma == std::string::npos ? "" : text.substr(last_comma + 1);
  const auto v = split_numbers(
      text.substr(0, last_comma == std::string::npos ? text.size() : last_comma), ',', "--at");
  if (v.size() != 2 || last_comma == std::string::npos)
    throw CLI::ValidationError("--at", cli_quote(text) + ": expected AZ,ALT,FRAME");
  std::string frame_copy = frame_text;
  if (const std::string why = whole_range(0, std::numeric_limits<std::int64_t>::max())(frame_copy);
      !why.empty())
    throw CLI::ValidationError("--at", cli_quote(text) + ": FRAME " + why);
  EvalPoint p;
  p.direction = {effects::wrap_azimuth_deg(v[0]), v[1]};
  std::from_chars(frame_text.data(), frame_text.data() + frame_text.size(), p.frame);
  check_direction(p.direction, text, "--at");
  return p;
}

ImageSize parse_size(const std::string& text, const char* option, const SizeLimit& limit) {
  const auto v = split_numbers(text, 'x', option);
  const std::string side = std::to_string(limit.max_side);
  if (v.size() != 2 || v[0] < 1 || v[1] < 1 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
    throw CLI::ValidationError(option,
                               cli_quote(text) + ": expected WxH, whole numbers 1.." + side);
  if (v[0] > limit.max_side || v[1] > limit.max_side)
    throw CLI::ValidationError(option, cli_quote(text) + ": each side must be at most " + side);
  if (v[0] * v[1] > static_cast<double>(limit.max_pixels))
    throw CLI::ValidationError(
        option, cli_quote(text) + ": " + std::to_string(std::llround(v[0] * v[1])) +
                    " pixels, more than the " + std::to_string(limit.max_pixels) + " allowed (" +
                    limit.example + ")");
  return {static_cast<int>(v[0]), static_cast<int>(v[1])};
}

}  // namespace vdfx::app
