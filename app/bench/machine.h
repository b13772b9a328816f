/// @file
/// @brief The machine a bench report was made on: CPU model and counts, load, build, date.
#pragma once

#include "app/bench/report.h"

namespace vdfx::app::bench {

/// CPU model, logical CPUs and physical cores (/proc/cpuinfo), build type and instruction-set
/// floor, the date now (UTC) and the load now as load_start. GL fields are left empty.
Machine describe_machine();

/// /proc/loadavg's 1, 5 and 15 minute averages (NaN where unreadable).
void read_load(double out[3]);

}  // namespace vdfx::app::bench
