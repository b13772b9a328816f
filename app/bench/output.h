/// @file
/// @brief The bench report as markdown (stdout, --markdown), CSV (--csv) and JSON (--json; the
/// schema is docs/bench.schema.json, described in docs/performance.md).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "app/bench/report.h"

namespace vdfx::app::bench {

void write_markdown(std::ostream& out, const Report& report);
void write_csv(std::ostream& out, const Report& report);
nlohmann::ordered_json to_json(const Report& report);

/// A time in seconds with a unit that keeps 3 significant digits readable: "3.58 us", "38.7 ms".
std::string format_time(double seconds);
/// A number with `digits` significant digits ("0.0123", "1.2e-09"); `missing` for NaN.
std::string format_number(double v, int digits = 3, const char* missing = "-");
/// A setting's number as short as it reads: "0.25", "1375".
std::string setting_number(double v);
/// "0.5 deg".
std::string setting_degrees(double v);

}  // namespace vdfx::app::bench
