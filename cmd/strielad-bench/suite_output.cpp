// SPDX-License-Identifier: Apache-2.0
#include "suite_output.h"

#include <spdlog/spdlog.h>

#include <iostream>
#include <sstream>

#include "bench/report_paths.h"

namespace strielad::bench_cmd {

void emit_suite_report(const std::string& header, std::vector<bench::Table> tables,
                       const std::string& csv_path, const std::string& json_path,
                       const std::filesystem::path& work,
                       const std::function<nlohmann::json()>& report_json) {
  const auto paths = bench::ReportPaths::for_suite(work, {csv_path, json_path});
  paths.rewrite(tables);
  std::cout << paths.text(header) << "\n\n";
  for (const auto& t : tables) bench::print_table(std::cout, t);
  std::cout.flush();
  if (!csv_path.empty()) {
    std::ostringstream csv;
    bench::write_csv(csv, tables);
    bench::write_text_file(csv_path, csv.str());
    spdlog::info("bench: wrote {}", csv_path);
  }
  if (!json_path.empty()) {
    nlohmann::json report = report_json();
    paths.rewrite(report);
    bench::write_text_file(json_path, report.dump(2) + "\n");
    spdlog::info("bench: wrote {}", json_path);
  }
}

}  // namespace strielad::bench_cmd
