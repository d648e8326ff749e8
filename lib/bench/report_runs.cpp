// SPDX-License-Identifier: Apache-2.0
#include "bench/report_runs.h"

#include <nlohmann/json.hpp>

#include <fstream>

#include "core/error.h"
#include "core/file_io.h"

namespace strielad::bench {

using nlohmann::json;

namespace {

bool takes_path(const std::string& flag) {
  return flag == "--work" || flag == "--json" || flag == "--csv" || flag == "--plot";
}

// A saved command as it can run here: the program and the values of the path flags
// resolved (bench/report_paths.h), every other argument as saved.
std::vector<std::string> resolved_argv(const std::vector<std::string>& saved,
                                       const ReportPaths& paths) {
  std::vector<std::string> argv = saved;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (i == 0 || takes_path(saved[i - 1])) argv[i] = paths.resolve(saved[i]).string();
  }
  return argv;
}

}  // namespace

void save_report_runs(const ReportInput& input, const std::filesystem::path& file,
                      const ReportPaths& paths) {
  json j;
  j["command_line"] = input.command_line;
  j["mode"] = input.mode;
  j["notes"] = input.notes;
  j["runs"] = json::array();
  for (const auto& r : input.runs) {
    j["runs"].push_back({{"suite", r.suite},
                         {"argv", r.argv},
                         {"exit_status", r.exit_status},
                         {"seconds", r.seconds},
                         {"json", r.json.string()},
                         {"csv", r.csv.string()},
                         {"log", r.log.string()},
                         {"plot", r.plot.string()},
                         {"output_tail", r.output_tail}});
  }
  j["probes"] = json::array();
  for (const auto& p : input.probes) j["probes"].push_back({{"when", p.when}, {"seconds", p.seconds}});
  paths.rewrite(j);
  const std::string text = j.dump(2) + "\n";
  write_file_atomically(file, std::as_bytes(std::span(text.data(), text.size())));
}

ReportInput load_report_runs(const std::filesystem::path& file, const ReportPaths& paths) {
  std::ifstream in(file);
  if (!in) {
    throw make_error(ErrorCode::kNotFound, "{}: no earlier report here to re-run suites of",
                     file.string());
  }
  try {
    const json j = json::parse(in);
    ReportInput input;
    input.command_line = j.at("command_line").get<std::string>();
    input.mode = j.at("mode").get<std::string>();
    input.notes = j.value("notes", std::vector<std::string>{});
    for (const auto& r : j.at("runs")) {
      SuiteRun run;
      run.suite = r.at("suite").get<std::string>();
      run.argv = resolved_argv(r.at("argv").get<std::vector<std::string>>(), paths);
      run.exit_status = r.at("exit_status").get<int>();
      run.seconds = r.at("seconds").get<double>();
      run.json = paths.resolve(r.at("json").get<std::string>());
      run.csv = paths.resolve(r.at("csv").get<std::string>());
      run.log = paths.resolve(r.at("log").get<std::string>());
      const auto plot = r.at("plot").get<std::string>();
      run.plot = plot.empty() ? std::filesystem::path() : paths.resolve(plot);
      run.output_tail = r.value("output_tail", std::string());
      input.runs.push_back(std::move(run));
    }
    for (const auto& p : j.at("probes")) {
      input.probes.push_back({p.at("when").get<std::string>(), p.at("seconds").get<double>()});
    }
    return input;
  } catch (const json::exception& e) {
    throw make_error(ErrorCode::kInvalidInput, "{}: not a report's runs file ({})", file.string(),
                     e.what());
  }
}

}  // namespace strielad::bench
