// SPDX-License-Identifier: Apache-2.0
// The report's charts (strielad-bench report): each writes its data (.dat) and gnuplot
// script (.gp) next to the PNG, so a reader can re-plot it, and runs gnuplot
// (bench/gnuplot_run.h). Returns "written" or why not; never throws for a failed plot.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace strielad::bench {

struct ChartAxes {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
};

// One bar per label.
std::string bar_chart(const std::filesystem::path& png, const ChartAxes& axes,
                      const std::vector<std::string>& labels, const std::vector<double>& values);

struct ChartSeries {
  std::string name;
  std::vector<double> x, y;
};

// One line per series, with a mark at every point when `points` (dense curves leave
// them out).
std::string line_chart(const std::filesystem::path& png, const ChartAxes& axes,
                       const std::vector<ChartSeries>& series, bool points = true);

// A chart title broken into lines of at most `width` characters at spaces (a longer word
// stays whole), joined with '\n'.
std::string wrap_title(const std::string& title, std::size_t width);

}  // namespace strielad::bench
