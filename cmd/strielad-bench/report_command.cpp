// SPDX-License-Identifier: Apache-2.0
// strielad-bench report --out DIR [--quick] [--dims XxYxZ] [--suites io,extract,...]
//                       [--work DIR] [--rerun SUITES]
// Runs every suite as its own process (this binary), one after the other, each writing
// its JSON, CSV and output into DIR, then writes DIR/BENCHMARKS.md with the charts.
// Paths in all of them as bench/report_paths.h writes them. When a suite failed, the
// report is still written and the tool exits with the internal-error status (70).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

#include "bench/benchmark_report.h"
#include "bench/noise_probe.h"
#include "bench/report_runs.h"
#include "bench/process_runner.h"
#include "commands.h"
#include "core/error.h"

namespace strielad::bench_cmd {
namespace {

struct ReportFlags {
  std::string out = "bench/report";
  std::string dims = "715x778x150";
  std::string suites = "io,extract,latency,lossy,view,scene,scaling,advect,robustness";
  std::string work = "/tmp/strielad-bench-report";
  std::string rerun;
  bool quick = false;
  std::string command_line;
};

// What the report ran, for a later --rerun (bench/report_runs.h).
constexpr const char* kRunsFile = "runs.json";

const std::set<std::string>& known_suites() {
  static const std::set<std::string> s{"io",    "extract", "latency", "lossy",     "view",
                                       "scene", "scaling", "advect",  "robustness"};
  return s;
}

bool takes_dims(const std::string& suite) {
  return suite == "io" || suite == "extract" || suite == "latency" || suite == "lossy" ||
         suite == "view" || suite == "scene";
}

bool takes_plot(const std::string& suite) {
  return suite == "extract" || suite == "advect" || suite == "lossy";
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    if (comma > start) out.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// Three noise probes (bench/noise_probe.h): how much other load slows a core now.
void take_probes(bench::ReportInput& input, const std::string& when) {
  for (int i = 0; i < 3; ++i) input.probes.push_back({when, bench::noise_probe_seconds()});
}

bench::SuiteRun planned_run(const ReportFlags& f, const std::string& suite,
                            const std::filesystem::path& out, const std::string& self) {
  bench::SuiteRun run;
  run.suite = suite;
  run.json = out / (suite + ".json");
  run.csv = out / (suite + ".csv");
  run.log = out / (suite + ".txt");
  run.argv = {self, suite};
  if (f.quick) run.argv.push_back("--quick");
  else if (takes_dims(suite)) run.argv.insert(run.argv.end(), {"--dims", f.dims});
  if (suite != "advect") {
    run.argv.insert(run.argv.end(), {"--work", (std::filesystem::path(f.work) / suite).string()});
  }
  run.argv.insert(run.argv.end(), {"--json", run.json.string(), "--csv", run.csv.string()});
  if (takes_plot(suite)) {
    run.plot = out / (suite + ".png");
    run.argv.insert(run.argv.end(), {"--plot", run.plot.string()});
  }
  return run;
}

// Runs the suite; its captured output names paths as `paths` writes them.
void execute(bench::SuiteRun& run, const bench::ReportPaths& paths) {
  std::filesystem::remove(run.json);
  spdlog::info("report: running {}", bench::shell_command(run.argv));
  const auto result = bench::run_process(run.argv, run.log);
  paths.rewrite_file(run.log);
  run.exit_status = result.exit_status;
  run.seconds = result.seconds;
  run.output_tail = result.exit_status != 0 ? paths.text(result.output_tail) : std::string();
  spdlog::info("report: {} exited {} after {:.1f} s", run.suite, run.exit_status, run.seconds);
}

int run(const ReportFlags& f) {
  const bool rerun = !f.rerun.empty();
  const auto suites = split(rerun ? f.rerun : f.suites);
  const char* flag = rerun ? "--rerun" : "--suites";
  if (suites.empty()) throw make_error(ErrorCode::kInvalidArgument, "{}: no suite named", flag);
  for (const auto& s : suites) {
    if (!known_suites().count(s)) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: unknown suite '{}' (known: {})", flag, s,
                       fmt::join(known_suites(), ", "));
    }
  }
  const std::filesystem::path out = std::filesystem::absolute(f.out);
  std::filesystem::create_directories(out);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const auto paths = bench::ReportPaths::for_suite(f.work, {(out / kRunsFile).string()});
  bench::ReportInput input;
  if (rerun) {
    input = bench::load_report_runs(out / kRunsFile, paths);
    input.notes.push_back(fmt::format("Re-run by `{}`: {}; the other suites are as first run.",
                                      paths.text(f.command_line), fmt::join(suites, ", ")));
  } else {
    input.command_line = paths.text(f.command_line);
    input.mode = f.quick ? "quick mode: small data, checks the harness, not the figures"
                         : fmt::format("generated data {}", f.dims);
  }
  input.out = out;
  for (const auto& suite : suites) {
    const auto kept = std::find_if(input.runs.begin(), input.runs.end(),
                                   [&](const bench::SuiteRun& r) { return r.suite == suite; });
    take_probes(input, (rerun ? "re-run, before " : "before ") + suite);
    if (kept != input.runs.end()) {
      execute(*kept, paths);  // the same command as the first run
    } else {
      input.runs.push_back(planned_run(f, suite, out, self));
      execute(input.runs.back(), paths);
    }
  }
  take_probes(input, (rerun ? "re-run, after " : "after ") + suites.back());
  bench::save_report_runs(input, out / kRunsFile, paths);
  const auto written = bench::write_benchmark_report(input, paths);
  std::cout << "report: " << written.markdown.string() << " (" << written.charts.size()
            << " charts";
  if (!written.chart_problems.empty()) {
    std::cout << "; not drawn: " << fmt::format("{}", fmt::join(written.chart_problems, "; "));
  }
  std::cout << ")\n";
  std::vector<std::string> failed;
  for (const auto& r : input.runs) {
    if (r.exit_status != 0) {
      failed.push_back(fmt::format("{} (exit status {})", r.suite, r.exit_status));
    }
  }
  if (!failed.empty()) {
    // The report is written; the run's check (every suite succeeds) failed.
    std::cerr << fmt::format("strielad-bench: {} suite(s) failed: {}; see {}\n", failed.size(),
                             fmt::join(failed, ", "), written.markdown.string());
    return kExitStatusChecksFailed;
  }
  return 0;
}

}  // namespace

void register_report(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<ReportFlags>();
  f->command_line = std::move(command_line);
  auto* sub = app.add_subcommand(
      "report",
      "Runs every suite (each its own process) and writes one report: BENCHMARKS.md with the "
      "machine, each suite's command, tables and charts, plus the suites' CSV and JSON");
  sub->add_option("--out", f->out, "Folder of the report")->capture_default_str();
  sub->add_option("--dims", f->dims,
                  "Grid XxYxZ of the generated data for io, extract, latency, lossy, view and scene "
                  "(default: a quarter of the paper's time step)")
      ->capture_default_str();
  sub->add_option("--suites", f->suites, "Comma-separated suites to run")->capture_default_str();
  sub->add_option("--work", f->work, "Scratch folder; each suite gets its own below it")
      ->capture_default_str();
  sub->add_flag("--quick", f->quick, "Every suite in quick mode: seconds, checks the harness");
  sub->add_option("--rerun", f->rerun,
                  "Run only these suites again (comma-separated), with their first commands, "
                  "keep the other suites of the report in --out, and write the whole report");
  sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
