// SPDX-License-Identifier: Apache-2.0
// The charts of the benchmark report (strielad-bench report), drawn from each suite's
// JSON: throughput against peers, the cut's arrival curves, error against run time, scene
// economy and scaling. A suite whose JSON lacks a chart's data gives no chart.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace strielad::bench {

struct SuiteChart {
  std::filesystem::path png;
  std::string caption;
  std::string status;  // "written" or why not (bench/report_plots.h)
};

// The charts of `suite` ("io", "latency", ...) from its JSON report, written into `dir`.
std::vector<SuiteChart> suite_charts(const std::string& suite, const nlohmann::json& report,
                                     const std::filesystem::path& dir);

// The empirical distribution of arrival times pooled over rounds: for every answer, in
// time order, x = seconds after the request and y = the % of all rounds' cut nodes
// answered by then (the mean over rounds of each round's arrival curve), thinned evenly
// to at most `max_points` points (the first and last kept).
struct ArrivalCurve {
  std::vector<double> seconds, percent;
};
ArrivalCurve pooled_arrival_curve(const std::vector<std::vector<double>>& rounds,
                                  const std::vector<std::size_t>& cut_sizes,
                                  std::size_t max_points = 400);

}  // namespace strielad::bench
