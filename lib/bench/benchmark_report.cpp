// SPDX-License-Identifier: Apache-2.0
#include "bench/benchmark_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>

#include "bench/process_runner.h"
#include "bench/report_markdown.h"
#include "bench/report_plots.h"
#include "bench/table_writer.h"

namespace strielad::bench {
namespace {

using nlohmann::json;

std::optional<json> read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return json::parse(in);
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

const json* find_table(const json& suite, const std::string& name) {
  static const json none;
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

struct Chart {
  std::filesystem::path png;
  std::string caption;
};

// The charts each suite's JSON gives; a suite without the table gives none.
using ChartMaker = std::function<std::vector<Chart>(const json&, const std::filesystem::path&,
                                                    ReportOutput&)>;

void keep(ReportOutput& out, std::vector<Chart>& charts, const std::filesystem::path& png,
          const std::string& caption, const std::string& status) {
  if (status == "written") {
    out.charts.push_back(png);
    charts.push_back({png, caption});
  } else {
    out.chart_problems.push_back(fmt::format("{}: {}", png.filename().string(), status));
  }
}

std::vector<Chart> io_charts(const json& s, const std::filesystem::path& dir, ReportOutput& out) {
  std::vector<Chart> charts;
  if (const json* t = find_table(s, "conversion")) {
    std::vector<std::string> labels;
    std::vector<double> values;
    for (const auto& row : (*t)["rows"]) {
      labels.push_back(text(row, "contender"));
      values.push_back(number(row, "input MB/s"));
    }
    const auto png = dir / "io-conversion.png";
    keep(out, charts, png, "Conversion throughput against nccopy and a plain read+copy",
         bar_chart(png, {"Conversion throughput (input MB/s, median)", "", "input MB/s"}, labels,
                   values));
  }
  return charts;
}

std::vector<Chart> extract_charts(const json& s, const std::filesystem::path& dir,
                                  ReportOutput& out) {
  std::vector<Chart> charts;
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
    keep(out, charts, png, (*t).value("title", name),
         bar_chart(png, {(*t).value("title", name), "", "Mcells/s per core", false, true}, labels,
                   values));
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
    keep(out, charts, png, "Error against run time over the octree levels (coarser = faster)",
         line_chart(png, {"Error against run time, whole level", "seconds, one thread",
                          "error", true, true},
                    series));
  }
  return charts;
}

std::vector<Chart> latency_charts(const json& s, const std::filesystem::path& dir,
                                  ReportOutput& out) {
  std::vector<Chart> charts;
  const json* t = find_table(s, "cut_latency");
  if (!t) return charts;
  std::vector<ChartSeries> series;
  for (const auto& row : (*t)["rows"]) {
    ChartSeries c{fmt::format("{}, prefetch {}", text(row, "phase"), text(row, "prefetch")), {}, {}};
    const double first = number(row, "first");
    c.x = {first, number(row, "50 %"), number(row, "90 %"), number(row, "100 %")};
    c.y = {0, 50, 90, 100};
    series.push_back(c);
  }
  const auto png = dir / "latency-cut-arrivals.png";
  keep(out, charts, png,
       "Share of the cut answered against time after the request (first answer, 50, 90 and "
       "100 %, medians of the rounds)",
       line_chart(png, {"Cut arrivals after a change", "ms after the request", "% of the cut",
                        true, false},
                  series));
  return charts;
}

std::vector<Chart> scene_charts(const json& s, const std::filesystem::path& dir,
                                ReportOutput& out) {
  std::vector<Chart> charts;
  const json* t = find_table(s, "scene_economy");
  if (!t) return charts;
  std::vector<std::string> labels;
  std::vector<double> values;
  for (const auto& row : (*t)["rows"]) {
    if (text(row, "view") == "whole step") continue;
    labels.push_back(text(row, "scene") + " / " + text(row, "view"));
    values.push_back(number(row, "read % step"));
  }
  const auto png = dir / "scene-economy.png";
  keep(out, charts, png, "Bytes read per scene and view, % of the whole step",
       bar_chart(png, {"Bytes read, % of the whole time step", "", "% of the step", false, true},
                 labels, values));
  return charts;
}

const std::map<std::string, ChartMaker>& chart_makers() {
  static const std::map<std::string, ChartMaker> makers{
      {"io", io_charts}, {"extract", extract_charts}, {"latency", latency_charts},
      {"scene", scene_charts}};
  return makers;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

}  // namespace

ReportOutput write_benchmark_report(const ReportInput& input) {
  ReportOutput out;
  std::string md;
  md += "# STRIELAD benchmark report\n\n";
  md += fmt::format("Generated {} by `{}` ({}). Every suite ran as its own process, one "
                    "after the other, on this machine; the tables are the suites' own.\n\n",
                    utc_now(), input.command_line, input.mode);
  std::map<std::string, json> reports;
  for (const auto& run : input.runs) {
    if (auto j = read_json(run.json)) reports[run.suite] = std::move(*j);
  }
  md += "## Machine\n\n";
  bool machine_written = false;
  for (const auto& run : input.runs) {
    auto it = reports.find(run.suite);
    if (it != reports.end() && it->second.contains("machine")) {
      md += machine_markdown(it->second["machine"]) + "\n";
      machine_written = true;
      break;
    }
  }
  if (!machine_written) md += "(no suite reported its machine)\n\n";
  md += "## Suites\n\n| suite | exit status | seconds | command |\n|---|---|---|---|\n";
  for (const auto& run : input.runs) {
    md += fmt::format("| [{}](#{}) | {} | {:.1f} | `{}` |\n", run.suite, run.suite,
                      run.exit_status, run.seconds, shell_command(run.argv));
  }
  md += "\n";
  for (const auto& run : input.runs) {
    md += fmt::format("## {}\n\n", run.suite);
    md += fmt::format("`{}`: exit status {}, {:.1f} s; raw: `{}`, `{}`, `{}`\n\n",
                      shell_command(run.argv), run.exit_status, run.seconds,
                      run.json.filename().string(), run.csv.filename().string(),
                      run.log.filename().string());
    auto it = reports.find(run.suite);
    if (it == reports.end()) {
      md += fmt::format("No report: the suite wrote no readable JSON. Its output ends:\n\n```\n{}\n```\n\n",
                        run.output_tail);
      continue;
    }
    const auto maker = chart_makers().find(run.suite);
    if (maker != chart_makers().end()) {
      for (const auto& chart : maker->second(it->second, input.out, out)) {
        md += fmt::format("![{}]({})\n\n*{}*\n\n", chart.caption, chart.png.filename().string(),
                          chart.caption);
      }
    }
    if (!run.plot.empty()) {
      const std::string status = it->second.value("plot", std::string("not reported"));
      if (status == "written") {
        out.charts.push_back(run.plot);
        md += fmt::format("![{} chart]({})\n\n", run.suite, run.plot.filename().string());
      } else {
        out.chart_problems.push_back(fmt::format("{}: {}", run.plot.filename().string(), status));
      }
    }
    for (const auto& table : report_tables(it->second)) md += table_markdown(table);
  }
  if (!out.chart_problems.empty()) {
    md += "## Charts not drawn\n\n";
    for (const auto& p : out.chart_problems) md += "- " + p + "\n";
    md += "\n";
  }
  out.markdown = input.out / "BENCHMARKS.md";
  write_text_file(out.markdown, md);
  return out;
}

}  // namespace strielad::bench
