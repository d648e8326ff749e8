// SPDX-License-Identifier: Apache-2.0
#include "core/text_columns.h"

#include <algorithm>

namespace strielad {

std::size_t text_width(std::string_view text) noexcept {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a continuation byte
  }));
}

void TextColumns::add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }

void TextColumns::print(std::ostream& out, std::string_view indent) const {
  std::vector<std::size_t> widths;
  for (const auto& row : rows_) {
    if (widths.size() < row.size()) widths.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c) {
      widths[c] = std::max(widths[c], text_width(row[c]));
    }
  }
  for (const auto& row : rows_) {
    std::string line(indent);
    // The last non-empty cell ends the line: no trailing padding.
    std::size_t last = row.size();
    while (last > 0 && row[last - 1].empty()) --last;
    for (std::size_t c = 0; c < last; ++c) {
      line += row[c];
      if (c + 1 < last) line.append(widths[c] - text_width(row[c]) + 2, ' ');
    }
    out << line << '\n';
  }
}

}  // namespace strielad
