// SPDX-License-Identifier: Apache-2.0
#include "bench/table_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"

namespace strielad::bench {
namespace {

std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string Cell::display() const {
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  const double v = std::get<double>(value);
  if (std::isnan(v)) return "-";
  return fmt::format("{:.{}f}", v, std::max(0, decimals));
}

std::string Cell::exact() const {
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  const double v = std::get<double>(value);
  if (std::isnan(v)) return "";
  return fmt::format("{}", v);
}

nlohmann::json Cell::json() const {
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  const double v = std::get<double>(value);
  if (!std::isfinite(v)) return nullptr;
  return v;
}

Table& Table::add(std::vector<Cell> row) {
  if (row.size() != columns.size()) {
    throw make_error(ErrorCode::kInternal, "table '{}': row of {} cells for {} columns", name,
                     row.size(), columns.size());
  }
  rows.push_back(std::move(row));
  return *this;
}

void print_table(std::ostream& out, const Table& table) {
  std::vector<std::size_t> width(table.columns.size());
  std::vector<bool> numeric(table.columns.size(), true);
  for (std::size_t c = 0; c < table.columns.size(); ++c) width[c] = table.columns[c].size();
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      width[c] = std::max(width[c], row[c].display().size());
      if (!row[c].is_number()) numeric[c] = false;
    }
  }
  out << "== " << table.title << " ==\n";
  const auto line = [&](const auto& cell_text) {
    std::string s;
    for (std::size_t c = 0; c < width.size(); ++c) {
      const std::string text = cell_text(c);
      if (c > 0) s += "  ";
      s += numeric[c] && c > 0 ? fmt::format("{:>{}}", text, width[c])
                               : fmt::format("{:<{}}", text, width[c]);
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    out << s << "\n";
  };
  line([&](std::size_t c) { return table.columns[c]; });
  line([&](std::size_t c) { return std::string(width[c], '-'); });
  for (const auto& row : table.rows) line([&](std::size_t c) { return row[c].display(); });
  for (const auto& note : table.notes) out << "  * " << note << "\n";
  out << "\n";
}

void write_csv(std::ostream& out, std::span<const Table> tables) {
  out << "table,row,column,value\n";
  for (const auto& t : tables) {
    for (const auto& row : t.rows) {
      const std::string key = row.empty() ? "" : row.front().exact();
      for (std::size_t c = 1; c < row.size(); ++c) {
        out << csv_escape(t.name) << ',' << csv_escape(key) << ',' << csv_escape(t.columns[c])
            << ',' << csv_escape(row[c].exact()) << '\n';
      }
    }
  }
}

nlohmann::json table_json(const Table& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : table.rows) {
    nlohmann::json r = nlohmann::json::object();
    for (std::size_t c = 0; c < row.size(); ++c) r[table.columns[c]] = row[c].json();
    rows.push_back(std::move(r));
  }
  return {{"name", table.name},
          {"title", table.title},
          {"columns", table.columns},
          {"rows", rows},
          {"notes", table.notes}};
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
  }
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  f.close();
  if (!f) throw make_error(ErrorCode::kIo, "{}: cannot write the file", path.string());
}

}  // namespace strielad::bench
