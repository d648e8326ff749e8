// SPDX-License-Identifier: Apache-2.0
#include "bench/report_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "bench/report_plots.h"

namespace strielad::bench {
namespace {

using nlohmann::json;
using Charts = std::vector<SuiteChart>;

const json* find_table(const json& suite, const std::string& name) {
  if (!suite.contains("tables")) return nullptr;
  const auto& t = suite["tables"];
  if (t.is_object()) return t.contains(name) ? &t[name] : nullptr;
  for (const auto& x : t) {
    if (x.value("name", "") == name) return &x;
  }
  return nullptr;
}

double number(const json& row, const std::string& column) {
  if (!row.contains(column) || !row[column].is_number()) return std::nan("");
  return row[column].get<double>();
}

std::string text(const json& row, const std::string& column) {
  if (!row.contains(column)) return "";
  return row[column].is_string() ? row[column].get<std::string>() : row[column].dump();
}

Charts io_charts(const json& s, const std::filesystem::path& dir) {
  Charts charts;
  if (const json* t = find_table(s, "conversion")) {
    std::vector<std::string> labels;
    std::vector<double> values;
    for (const auto& row : (*t)["rows"]) {
      labels.push_back(text(row, "contender"));
      values.push_back(number(row, "input MB/s"));
    }
    const auto png = dir / "io-conversion.png";
    charts.push_back({png, "Conversion throughput against nccopy and a plain read+copy",
                      bar_chart(png, {"Conversion throughput (input MB/s, median)", "", "input MB/s"},
                                labels, values)});
  }
  return charts;
}

Charts extract_charts(const json& s, const std::filesystem::path& dir) {
  Charts charts;
  for (const char* name : {"bricks_cloud", "bricks_dense", "bricks_three"}) {
    const json* t = find_table(s, name);
    if (!t) continue;
    std::vector<std::string> labels;
    std::vector<double> values;
    for (const auto& row : (*t)["rows"]) {
      labels.push_back(text(row, "B / contender"));
      values.push_back(number(row, "Mcells/s"));
    }
    const auto png = dir / fmt::format("extract-{}.png", name);
    charts.push_back({png, (*t).value("title", name),
                      bar_chart(png, {(*t).value("title", name), "", "Mcells/s per core", false, true},
                                labels, values)});
  }
  std::vector<ChartSeries> series;
  for (const char* name : {"levels_cloud", "levels_dense"}) {
    const json* t = find_table(s, name);
    if (!t) continue;
    ChartSeries volume{fmt::format("{}: volume error %", name), {}, {}};
    ChartSeries distance{fmt::format("{}: mean surface distance (cells)", name), {}, {}};
    for (const auto& row : (*t)["rows"]) {
      volume.x.push_back(number(row, "s 1 thread"));
      volume.y.push_back(std::abs(number(row, "volume error %")));
      distance.x.push_back(number(row, "s 1 thread"));
      distance.y.push_back(number(row, "mean dist"));
    }
    series.push_back(volume);
    series.push_back(distance);
  }
  if (!series.empty()) {
    const auto png = dir / "extract-error-vs-time.png";
    charts.push_back({png, "Error against run time over the octree levels (coarser = faster)",
                      line_chart(png, {"Error against run time, whole level", "seconds, one thread",
                                       "error", true, true},
                                 series)});
  }
  return charts;
}

// The cut's arrival curves from every round's raw arrival times; a report written before
// the suite kept them gives the curve through its quantiles.
Charts latency_charts(const json& s, const std::filesystem::path& dir) {
  std::vector<ChartSeries> series;
  std::string caption;
  if (s.contains("arrivals") && !s["arrivals"].empty()) {
    for (const auto& phase : s["arrivals"]) {
      std::vector<std::vector<double>> rounds;
      std::vector<std::size_t> cuts;
      for (const auto& r : phase["rounds"]) {
        rounds.push_back(r["seconds"].get<std::vector<double>>());
        cuts.push_back(r["cut"].get<std::size_t>());
      }
      const ArrivalCurve curve = pooled_arrival_curve(rounds, cuts);
      ChartSeries c{fmt::format("{}, prefetch {}", phase.value("phase", ""),
                                phase.value("prefetch", false) ? "on" : "off"),
                    {}, curve.percent};
      for (const double t : curve.seconds) c.x.push_back(1000 * t);
      series.push_back(std::move(c));
    }
    caption = "Share of the cut answered against time after the request: every answer of every "
              "round (the curves are the mean over rounds)";
  } else if (const json* t = find_table(s, "cut_latency")) {
    for (const auto& row : (*t)["rows"]) {
      ChartSeries c{fmt::format("{}, prefetch {}", text(row, "phase"), text(row, "prefetch")), {}, {}};
      c.x = {number(row, "first"), number(row, "50 %"), number(row, "90 %"), number(row, "100 %")};
      c.y = {0, 50, 90, 100};
      series.push_back(c);
    }
    caption = "Share of the cut answered against time after the request (first answer, 50, 90 "
              "and 100 %, medians of the rounds)";
  } else {
    return {};
  }
  const auto png = dir / "latency-cut-arrivals.png";
  return {{png, caption,
           line_chart(png, {"Cut arrivals after a change", "ms after the request", "% of the cut",
                            true, false},
                      series, false)}};
}

Charts scene_charts(const json& s, const std::filesystem::path& dir) {
  const json* t = find_table(s, "scene_economy");
  if (!t) return {};
  std::vector<std::string> labels;
  std::vector<double> values;
  for (const auto& row : (*t)["rows"]) {
    if (text(row, "view") == "whole step") continue;
    labels.push_back(text(row, "scene") + " / " + text(row, "view"));
    values.push_back(number(row, "read % step"));
  }
  const auto png = dir / "scene-economy.png";
  return {{png, "Bytes read per scene and view, % of the whole step",
           bar_chart(png, {"Bytes read, % of the whole time step", "", "% of the step", false, true},
                     labels, values)}};
}

Charts scaling_charts(const json& s, const std::filesystem::path& dir) {
  Charts charts;
  if (const json* t = find_table(s, "scaling_grid")) {
    ChartSeries convert{"conversion", {}, {}}, level{"whole level 0", {}, {}},
        cut{"overview cut", {}, {}};
    for (const auto& row : (*t)["rows"]) {
      const double cells = number(row, "M cells");
      convert.x.push_back(cells);
      convert.y.push_back(number(row, "convert s"));
      level.x.push_back(cells);
      level.y.push_back(number(row, "level 0 s"));
      cut.x.push_back(cells);
      cut.y.push_back(number(row, "cut s"));
    }
    const auto png = dir / "scaling-grid.png";
    charts.push_back({png, "Seconds against grid size (million cells of one time step)",
                      line_chart(png, {"Cost against grid size", "million cells", "seconds (median)",
                                       true, true},
                                 {convert, level, cut})});
  }
  if (const json* t = find_table(s, "scaling_subvolumes")) {
    ChartSeries seconds{"whole level 0", {}, {}};
    for (const auto& row : (*t)["rows"]) {
      seconds.x.push_back(number(row, "sub-volumes"));
      seconds.y.push_back(number(row, "median s"));
    }
    const auto png = dir / "scaling-subvolumes.png";
    charts.push_back({png, "Seconds against the number of sub-volumes in the scene",
                      line_chart(png, {"Cost against sub-volumes", "sub-volumes", "seconds (median)"},
                                 {seconds})});
  }
  if (const json* t = find_table(s, "scaling_ranks")) {
    std::vector<std::string> labels;
    std::vector<double> values;
    for (const auto& row : (*t)["rows"]) {
      const double ms = number(row, "100 % ms");
      if (!std::isfinite(ms)) continue;
      labels.push_back(fmt::format("{} rank(s) x {} thr", text(row, "ranks"), text(row, "threads/rank")));
      values.push_back(ms);
    }
    const auto png = dir / "scaling-ranks.png";
    charts.push_back({png, "A cold cut complete (ms, median) on the threaded server and on MPI ranks",
                      bar_chart(png, {"Cold cut complete", "", "ms (median)"}, labels, values)});
  }
  return charts;
}

}  // namespace

std::vector<SuiteChart> suite_charts(const std::string& suite, const json& report,
                                     const std::filesystem::path& dir) {
  using Maker = std::function<Charts(const json&, const std::filesystem::path&)>;
  static const std::map<std::string, Maker> makers{
      {"io", io_charts},       {"extract", extract_charts}, {"latency", latency_charts},
      {"scene", scene_charts}, {"scaling", scaling_charts}};
  const auto it = makers.find(suite);
  return it == makers.end() ? Charts{} : it->second(report, dir);
}

ArrivalCurve pooled_arrival_curve(const std::vector<std::vector<double>>& rounds,
                                  const std::vector<std::size_t>& cut_sizes,
                                  std::size_t max_points) {
  ArrivalCurve curve;
  std::vector<double> all;
  double total = 0;
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    all.insert(all.end(), rounds[r].begin(), rounds[r].end());
    total += r < cut_sizes.size() ? double(cut_sizes[r]) : double(rounds[r].size());
  }
  if (all.empty() || total <= 0) return curve;
  std::sort(all.begin(), all.end());
  const std::size_t n = all.size();
  const std::size_t points = std::max<std::size_t>(2, std::min(n, max_points));
  for (std::size_t k = 0; k < points; ++k) {
    const std::size_t i = points == 1 ? 0 : (k * (n - 1)) / (points - 1);
    if (!curve.seconds.empty() && i == 0) continue;
    curve.seconds.push_back(all[i]);
    curve.percent.push_back(100.0 * double(i + 1) / total);
  }
  return curve;
}

}  // namespace strielad::bench
