/// @file
/// @brief Shared command-line plumbing: CLI11 parsing with the contract's exit codes and the
/// value syntaxes of the contract (AZ,ALT[,ROLL], AZ,ALT,FRAME, WxH).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "app/cli/command_registry.h"
#include "app/cli/size_limits.h"
#include "effects/coords.h"

namespace vdfx::app {

/// Parses args into cli. Returns std::nullopt to go on, or the exit code to return at once
/// (0 after --help, kExitUsage after a usage error, whose message goes to stderr).
std::optional<int> parse_cli(CLI::App& cli, const Args& args);

/// Runs `parse` (what turns a command's parsed options into its request) and returns its
/// result; a CLI::ValidationError it throws becomes an app::UsageError with the same text, which
/// the command registry reports as "vdfx NAME: TEXT", exit 2.
template <class Parse>
auto parse_request(Parse&& parse) -> decltype(parse()) {
  try {
    return parse();
  } catch (const CLI::ValidationError& e) {
    throw UsageError(e.what());
  }
}

struct ViewSpec {
  effects::Direction direction;
  double roll_deg = 0.0;
};

struct EvalPoint {
  effects::Direction direction;
  std::int64_t frame = 0;
};

struct ImageSize {
  int width = 0;
  int height = 0;
};

/// Validators for numeric options. CLI11's own let NaN through (CLI::Range compares, and every
/// comparison with NaN is false), saturate an int64 that overflows (2^63 read as 2^63 - 1) and
/// print their bounds with 309 digits; these parse the text themselves.
/// A finite number in [lo, hi].
CLI::Validator finite_range(double lo, double hi);
/// A whole number in [lo, hi], exactly as written (no rounding, no saturation).
CLI::Validator whole_range(std::int64_t lo, std::int64_t hi);

/// Each throws CLI::ValidationError (a usage error) with the offending text.
ViewSpec parse_view(const std::string& text);         //!< "AZ,ALT" or "AZ,ALT,ROLL"
EvalPoint parse_eval_point(const std::string& text);  //!< "AZ,ALT,FRAME"
/// "WxH" within `limit`; `option` names it in the message.
ImageSize parse_size(const std::string& text, const char* option = "--size",
                     const SizeLimit& limit = kOutputSizeLimit);

}  // namespace vdfx::app
