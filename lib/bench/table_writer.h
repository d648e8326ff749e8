// SPDX-License-Identifier: Apache-2.0
// Benchmark result tables: printed aligned for people, written as tidy CSV
// (table,row,column,value) and as JSON for tools. A cell is text or a number shown with a
// fixed number of decimals; JSON and CSV keep full precision.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <ostream>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace strielad::bench {

struct Cell {
  std::variant<std::string, double> value;
  int decimals = 2;  // for numbers, on screen only

  Cell(std::string text) : value(std::move(text)) {}  // NOLINT(google-explicit-constructor)
  Cell(const char* text) : value(std::string(text)) {}  // NOLINT(google-explicit-constructor)
  Cell(double number, int places = 2) : value(number), decimals(places) {}  // NOLINT
  static Cell integer(double number) { return Cell(number, 0); }

  bool is_number() const { return std::holds_alternative<double>(value); }
  std::string display() const;   // on screen
  std::string exact() const;     // CSV: round-trip precision for numbers
  nlohmann::json json() const;
};

struct Table {
  std::string name;   // machine name, e.g. "conversion"
  std::string title;  // one line for people
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;  // each row has columns.size() cells
  std::vector<std::string> notes;       // printed under the table

  // Appends a row; throws kInternal when its size differs from the column count.
  Table& add(std::vector<Cell> row);
};

void print_table(std::ostream& out, const Table& table);
// Tidy CSV of all tables: header "table,row,column,value", the row key is the first cell.
void write_csv(std::ostream& out, std::span<const Table> tables);
nlohmann::json table_json(const Table& table);

// Writes text to a file (parents created). Throws kIo naming the file.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace strielad::bench
