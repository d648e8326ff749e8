// SPDX-License-Identifier: Apache-2.0
#include "bench/benchmark_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <ctime>
#include <fstream>
#include <map>

#include "bench/process_runner.h"
#include "bench/report_markdown.h"
#include "bench/report_charts.h"
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
    for (const auto& chart : suite_charts(run.suite, it->second, input.out)) {
      if (chart.status != "written") {
        out.chart_problems.push_back(fmt::format("{}: {}", chart.png.filename().string(), chart.status));
        continue;
      }
      out.charts.push_back(chart.png);
      md += fmt::format("![{}]({})\n\n*{}*\n\n", chart.caption, chart.png.filename().string(),
                        chart.caption);
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
