// SPDX-License-Identifier: Apache-2.0
// Markdown for the benchmark report (strielad-bench report): every suite's JSON
// (`--json`) holds its tables as table_json objects, either as an array or as an object
// keyed by table name; these turn them back into Markdown tables for BENCHMARKS.md.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace strielad::bench {

// The tables of a suite's JSON report, in order (an array as it is, an object's values
// in key order). Empty when there are none.
std::vector<nlohmann::json> report_tables(const nlohmann::json& suite);

// One table as Markdown: its title in bold, the table, its notes as a list. Numbers
// keep four significant digits (integers in full); `|` in text is escaped.
std::string table_markdown(const nlohmann::json& table);

// The machine object of a suite (bench/machine_info.h) as a Markdown list.
std::string machine_markdown(const nlohmann::json& machine);

// A number as the report prints it: integers in full, others with 4 significant digits.
std::string report_number(double value);

}  // namespace strielad::bench
