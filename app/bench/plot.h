/// @file
/// @brief `vdfx bench --plot DIR`: one PNG per knob of time against error, each setting labelled,
/// the Pareto front drawn as a line, the peer's time as a dashed line when all settings share
/// one, log axes when the values span more than a factor of 20. Drawn by gnuplot (Debian
/// gnuplot-nox), run as a separate program, so nothing of it loads with vdfx.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/report.h"

namespace vdfx::app::bench {

struct PlotOptions {
  std::filesystem::path dir;
  int width = 720;  //!< PNG size in pixels
  int height = 480;
};

/// Empty when gnuplot with its pngcairo terminal can be run; otherwise what is missing.
std::string gnuplot_problem();

/// Writes DIR/<knob id>.png for each knob with at least one measured row and returns their paths.
/// Throws std::runtime_error naming the knob when gnuplot fails.
std::vector<std::filesystem::path> write_plots(const Report& report, const PlotOptions& options);

}  // namespace vdfx::app::bench
