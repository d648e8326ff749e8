// SPDX-License-Identifier: Apache-2.0
// Rows of text printed as aligned columns for people (strielad-convert info): each column
// as wide as its widest cell, in characters (UTF-8 code points, so "m s⁻¹" is 5 wide),
// columns separated by at least two spaces, the last cell of a row not padded. Names of
// any length keep their columns apart.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace strielad {

class TextColumns {
 public:
  // Rows may have different numbers of cells; missing cells are empty.
  void add_row(std::vector<std::string> cells);

  // Each row on its own line, after `indent`.
  void print(std::ostream& out, std::string_view indent = "") const;

 private:
  std::vector<std::vector<std::string>> rows_;
};

// The width of `text` in characters: its UTF-8 code points.
std::size_t text_width(std::string_view text) noexcept;

}  // namespace strielad
