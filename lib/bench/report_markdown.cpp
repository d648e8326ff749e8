// SPDX-License-Identifier: Apache-2.0
#include "bench/report_markdown.h"

#include <fmt/format.h>

#include <cmath>

namespace strielad::bench {
namespace {

std::string escape_cell(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

std::string cell_text(const nlohmann::json& value) {
  if (value.is_number()) return report_number(value.get<double>());
  if (value.is_string()) return escape_cell(value.get<std::string>());
  if (value.is_null()) return "";
  return escape_cell(value.dump());
}

}  // namespace

std::string report_number(double value) {
  if (!std::isfinite(value)) return fmt::format("{}", value);
  if (value == std::round(value) && std::fabs(value) < 1e15) return fmt::format("{:.0f}", value);
  return fmt::format("{:.4g}", value);
}

std::vector<nlohmann::json> report_tables(const nlohmann::json& suite) {
  std::vector<nlohmann::json> tables;
  if (!suite.is_object() || !suite.contains("tables")) return tables;
  const auto& t = suite["tables"];
  if (t.is_array()) {
    for (const auto& x : t) tables.push_back(x);
  } else if (t.is_object()) {
    for (const auto& [key, x] : t.items()) tables.push_back(x);
  }
  return tables;
}

std::string table_markdown(const nlohmann::json& table) {
  std::string out;
  const std::string title = table.value("title", table.value("name", std::string("table")));
  out += fmt::format("**{}**\n\n", escape_cell(title));
  std::vector<std::string> columns;
  if (table.contains("columns")) {
    for (const auto& c : table["columns"]) columns.push_back(c.get<std::string>());
  }
  if (!columns.empty()) {
    out += "|";
    for (const auto& c : columns) out += fmt::format(" {} |", escape_cell(c));
    out += "\n|";
    for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
    out += "\n";
    for (const auto& row : table.value("rows", nlohmann::json::array())) {
      out += "|";
      for (const auto& c : columns) {
        out += fmt::format(" {} |", row.contains(c) ? cell_text(row[c]) : std::string());
      }
      out += "\n";
    }
  }
  const auto notes = table.value("notes", nlohmann::json::array());
  if (!notes.empty()) {
    out += "\n";
    for (const auto& n : notes) out += fmt::format("- {}\n", cell_text(n));
  }
  out += '\n';
  return out;
}

std::string machine_markdown(const nlohmann::json& machine) {
  std::string out;
  if (!machine.is_object()) return out;
  for (const auto& [key, value] : machine.items()) {
    if (value.is_object()) {
      std::string inner;
      for (const auto& [k, v] : value.items()) {
        inner += fmt::format("{}{} {}", inner.empty() ? "" : ", ", k, cell_text(v));
      }
      out += fmt::format("- {}: {}\n", key, inner);
    } else {
      out += fmt::format("- {}: {}\n", key, cell_text(value));
    }
  }
  return out;
}

}  // namespace strielad::bench
