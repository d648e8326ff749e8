// SPDX-License-Identifier: Apache-2.0
// What every suite command does with its report: print the header line and the tables,
// then write the tables as CSV and the report as JSON where the flags ask for them; paths
// in all of them as bench/report_paths.h writes them (`work`: the suite's scratch folder,
// empty for none).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench/table_writer.h"

namespace strielad::bench_cmd {

// `report_json` is called only when `json_path` is not empty.
void emit_suite_report(const std::string& header, std::vector<bench::Table> tables,
                       const std::string& csv_path, const std::string& json_path,
                       const std::filesystem::path& work,
                       const std::function<nlohmann::json()>& report_json);

}  // namespace strielad::bench_cmd
