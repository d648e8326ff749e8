// SPDX-License-Identifier: Apache-2.0
#include "bench/benchmark_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <map>

#include "bench/latency_stats.h"
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

// How much other load slowed the machine during the run, from the noise probes.
std::string noise_markdown(const std::vector<NoiseProbe>& probes) {
  if (probes.empty()) return "";
  std::vector<double> ms;
  for (const auto& p : probes) ms.push_back(p.seconds * 1000);
  const Summary s = summarize(ms);
  const auto slowest = std::max_element(probes.begin(), probes.end(),
                                        [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
  return fmt::format(
      "## Noise\n\nA fixed single-threaded CPU loop (`bench/noise_probe.h`) was timed {} times "
      "between the suites: median {:.1f} ms, fastest {:.1f} ms, slowest {:.1f} ms ({}), so "
      "other load on this machine slowed a core by up to {:.0f} % during the run (slowest / "
      "fastest {:.2f}). Read every figure below with that spread in mind; the suites give "
      "medians of repeated runs with their own spread.\n\n",
      probes.size(), s.p50, s.min, s.max, slowest->when, 100 * (s.max / s.min - 1), s.max / s.min);
}

}  // namespace

ReportOutput write_benchmark_report(const ReportInput& input, const ReportPaths& paths) {
  ReportOutput out;
  std::string md;
  md += "# STRIELAD benchmark report\n\n";
  md += fmt::format("Generated {} by `{}` ({}). Every suite ran as its own process, one "
                    "after the other, on this machine; the tables are the suites' own.\n\n",
                    utc_now(), input.command_line, input.mode);
  for (const auto& note : input.notes) md += note + "\n\n";
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
  md += noise_markdown(input.probes);
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
  write_text_file(out.markdown, paths.text(md));
  return out;
}

}  // namespace strielad::bench
