// SPDX-License-Identifier: Apache-2.0
// Aligned text columns (lib/core/text_columns.h): widths from the content, so long cells
// never run into the next column; UTF-8 text counted in characters.
#include <gtest/gtest.h>

#include <sstream>

#include "core/text_columns.h"

namespace strielad {
namespace {

TEST(TextColumnsTest, ColumnsAreAsWideAsTheirLongestCell) {
  TextColumns t;
  t.add_row({"t", "float32", "K", "delta"});
  t.add_row({"grp1/sub/very_long_variable_name_of_40chr", "float64", "kg m-2 s-1", "none"});
  std::ostringstream out;
  t.print(out, "  ");
  EXPECT_EQ(out.str(),
            "  t                                          float32  K           delta\n"
            "  grp1/sub/very_long_variable_name_of_40chr  float64  kg m-2 s-1  none\n");
}

TEST(TextColumnsTest, Utf8CellsAreMeasuredInCharacters) {
  EXPECT_EQ(text_width("m s⁻¹"), 5u);
  EXPECT_EQ(text_width("°C"), 2u);
  TextColumns t;
  t.add_row({"ua", "m s⁻¹", "wind"});
  t.add_row({"ta", "°C", "temperature"});
  std::ostringstream out;
  t.print(out);
  EXPECT_EQ(out.str(),
            "ua  m s⁻¹  wind\n"
            "ta  °C     temperature\n");
}

TEST(TextColumnsTest, ShortRowsAndEmptyLastCellsLeaveNoTrailingSpace) {
  TextColumns t;
  t.add_row({"step 0", "0", ""});
  t.add_row({"step 10", "48"});
  std::ostringstream out;
  t.print(out);
  EXPECT_EQ(out.str(),
            "step 0   0\n"
            "step 10  48\n");
}

}  // namespace
}  // namespace strielad
