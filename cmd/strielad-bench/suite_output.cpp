// SPDX-License-Identifier: Apache-2.0
#include "suite_output.h"

#include <spdlog/spdlog.h>

#include <iostream>
#include <sstream>

namespace strielad::bench_cmd {

void emit_suite_report(const std::string& header, const std::vector<bench::Table>& tables,
                       const std::string& csv_path, const std::string& json_path,
                       const std::function<nlohmann::json()>& report_json) {
  std::cout << header << "\n\n";
  for (const auto& t : tables) bench::print_table(std::cout, t);
  std::cout.flush();
  if (!csv_path.empty()) {
    std::ostringstream csv;
    bench::write_csv(csv, tables);
    bench::write_text_file(csv_path, csv.str());
    spdlog::info("bench: wrote {}", csv_path);
  }
  if (!json_path.empty()) {
    bench::write_text_file(json_path, report_json().dump(2) + "\n");
    spdlog::info("bench: wrote {}", json_path);
  }
}

}  // namespace strielad::bench_cmd
