// SPDX-License-Identifier: Apache-2.0
#include "bench/report_runs.h"

#include <nlohmann/json.hpp>

#include <fstream>

#include "core/error.h"
#include "core/file_io.h"

namespace strielad::bench {

using nlohmann::json;

void save_report_runs(const ReportInput& input, const std::filesystem::path& file) {
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
  const std::string text = j.dump(2) + "\n";
  write_file_atomically(file, std::as_bytes(std::span(text.data(), text.size())));
}

ReportInput load_report_runs(const std::filesystem::path& file) {
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
      run.argv = r.at("argv").get<std::vector<std::string>>();
      run.exit_status = r.at("exit_status").get<int>();
      run.seconds = r.at("seconds").get<double>();
      run.json = r.at("json").get<std::string>();
      run.csv = r.at("csv").get<std::string>();
      run.log = r.at("log").get<std::string>();
      run.plot = r.at("plot").get<std::string>();
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
