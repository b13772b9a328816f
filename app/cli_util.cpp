#include "app/cli_util.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <vector>

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
    std::cerr << cli.get_name() << ": " << e.what() << "\n(" << cli.get_name()
              << " --help lists the options)\n";
    return kExitUsage;
  }
  return std::nullopt;
}

namespace {

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
      throw CLI::ValidationError(what, "'" + text + "': '" + part + "' is not a finite number");
    values.push_back(v);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return values;
}

void check_direction(const effects::Direction& d, const std::string& text, const char* what) {
  if (d.altitude_deg < -90.0 || d.altitude_deg > 90.0)
    throw CLI::ValidationError(what, "'" + text + "': altitude must be in [-90, 90] degrees");
}

}  // namespace

ViewSpec parse_view(const std::string& text) {
  const auto v = split_numbers(text, ',', "--view");
  if (v.size() != 2 && v.size() != 3)
    throw CLI::ValidationError("--view", "'" + text + "': expected AZ,ALT or AZ,ALT,ROLL");
  ViewSpec s;
  s.direction = {effects::wrap_azimuth_deg(v[0]), v[1]};
  s.roll_deg = v.size() == 3 ? v[2] : 0.0;
  check_direction(s.direction, text, "--view");
  return s;
}

EvalPoint parse_eval_point(const std::string& text) {
  const auto v = split_numbers(text, ',', "--at");
  if (v.size() != 3)
    throw CLI::ValidationError("--at", "'" + text + "': expected AZ,ALT,FRAME");
  if (v[2] < 0 || v[2] != std::floor(v[2]) || v[2] > 9.0e15)
    throw CLI::ValidationError("--at", "'" + text + "': FRAME must be a whole number >= 0");
  EvalPoint p;
  p.direction = {effects::wrap_azimuth_deg(v[0]), v[1]};
  p.frame = static_cast<std::int64_t>(v[2]);
  check_direction(p.direction, text, "--at");
  return p;
}

ImageSize parse_size(const std::string& text, const char* option, const SizeLimit& limit) {
  const auto v = split_numbers(text, 'x', option);
  const std::string side = std::to_string(limit.max_side);
  if (v.size() != 2 || v[0] < 1 || v[1] < 1 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
    throw CLI::ValidationError(option, "'" + text + "': expected WxH, whole numbers 1.." + side);
  if (v[0] > limit.max_side || v[1] > limit.max_side)
    throw CLI::ValidationError(option, "'" + text + "': each side must be at most " + side);
  if (v[0] * v[1] > static_cast<double>(limit.max_pixels))
    throw CLI::ValidationError(option, "'" + text + "': " + std::to_string(std::llround(v[0] * v[1])) +
                                           " pixels, more than the " +
                                           std::to_string(limit.max_pixels) + " allowed (" +
                                           limit.example + ")");
  return {static_cast<int>(v[0]), static_cast<int>(v[1])};
}

}  // namespace vdfx::app
