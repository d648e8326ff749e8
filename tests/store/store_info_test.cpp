// SPDX-License-Identifier: Apache-2.0
// What `strielad-convert info` prints (lib/store/store_info.h): time values beside their
// dates in the store's calendar, in text and JSON, or the one reason there are none; and
// columns that stay aligned and apart whatever the length of variable names and units.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "convert/converter.h"
#include "core/text_columns.h"
#include "store/store.h"
#include "store/store_info.h"
#include "support/geometry_store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace strielad::testing;

// A store of one file with `grid` and the named float variables (a ramp each).
std::shared_ptr<const Store> make_store(const TempDir& dir, const SimpleGrid& grid,
                                  const std::vector<std::pair<std::string, std::string>>& vars,
                                  const std::string& lossy = {}) {
  NetcdfFixture file;
  file.grid(grid);
  for (const auto& [name, units] : vars) {
    file.variable(name, NC_FLOAT, grid.dims(), ramp(grid.samples()),
                  {NcAttr::text_value("units", units)});
  }
  file.write(dir / "in.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "in.nc"};
  o.store = dir / "store";
  o.brick = 2;
  o.threads = 1;
  if (!lossy.empty()) o.lossy = build::parse_lossy(lossy);
  build::convert(o);
  return Store::open(o.store);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The lines after the one starting with `heading`, up to the next unindented line.
std::vector<std::string> section(const std::string& text, const std::string& heading) {
  std::vector<std::string> out;
  bool in = false;
  for (const auto& line : lines_of(text)) {
    if (in && !line.starts_with("  ")) break;
    if (in) out.push_back(line);
    if (line.starts_with(heading)) in = true;
  }
  return out;
}

TEST(StoreInfoTest, TimeValuesAppearBesideTheirDatesInTextAndJson) {
  TempDir dir;
  SimpleGrid g;
  g.time = {0, 6, 12};
  g.time_units = "hours since 2001-01-01 00:00:00";
  g.calendar = "standard";
  const auto store = make_store(dir, g, {{"t", "K"}});
  std::ostringstream out;
  describe_store(*store, out);
  EXPECT_EQ(section(out.str(), "time "),
            (std::vector<std::string>{"  step 0  0   2001-01-01T00:00:00Z",
                                      "  step 2  12  2001-01-01T12:00:00Z"}))
      << out.str();
  const auto j = store_info_json(*store);
  EXPECT_EQ(j["time"]["values"], (std::vector<double>{0, 6, 12}));
  EXPECT_EQ(j["time"]["dates"], (std::vector<std::string>{"2001-01-01T00:00:00Z",
                                                          "2001-01-01T06:00:00Z",
                                                          "2001-01-01T12:00:00Z"}));
  EXPECT_FALSE(j["time"].contains("date_error"));
}

TEST(StoreInfoTest, DatesAreInTheStoresCalendar) {
  TempDir dir;
  SimpleGrid g;
  g.time = {0, 1, 2};
  g.time_units = "days since 2000-02-28";
  g.calendar = "360_day";
  const auto store = make_store(dir, g, {{"t", "K"}});
  // Hand count: February has 30 days in the 360-day calendar.
  EXPECT_EQ(store_info_json(*store)["time"]["dates"],
            (std::vector<std::string>{"2000-02-28T00:00:00Z", "2000-02-29T00:00:00Z",
                                      "2000-02-30T00:00:00Z"}));
  std::ostringstream out;
  describe_store(*store, out);
  EXPECT_NE(out.str().find("calendar 360_day"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("  step 2  2  2000-02-30T00:00:00Z\n"), std::string::npos) << out.str();
}

TEST(StoreInfoTest, NoDatesShowsRawValuesAndSaysWhyOnce) {
  TempDir dir;
  SimpleGrid g;
  g.time = {0, 6, 12, 24};
  g.time_units = "hours";  // as cdf/contour.cdf of libncarg-data: no reference date
  g.calendar = "";
  const auto store = make_store(dir, g, {{"t", "K"}});
  std::ostringstream out;
  describe_store(*store, out);
  const auto time = section(out.str(), "time ");
  ASSERT_EQ(time.size(), 3u) << out.str();
  EXPECT_EQ(time[0], "  step 0  0");
  EXPECT_EQ(time[1], "  step 3  24");
  EXPECT_TRUE(time[2].starts_with("  no dates: time units 'hours': no reference date")) << time[2];
  EXPECT_EQ(out.str().find("no dates"), out.str().rfind("no dates"));  // once
  const auto j = store_info_json(*store);
  EXPECT_TRUE(j["time"]["dates"].is_null());
  EXPECT_NE(j["time"]["date_error"].get<std::string>().find("no reference date"),
            std::string::npos);
}

TEST(StoreInfoTest, LongVariableNamesAndUnitsKeepAlignedSeparateColumns) {
  TempDir dir;
  SimpleGrid g;
  g.group = "grp1/sub";
  const std::string long_name = "grp1/sub/very_long_variable_name_of_forty_c";
  const auto store = make_store(dir, g,
                                {{"grp1/sub/t", "K"},
                                 {long_name, "kg m-2 s-1 of something long"},
                                 {"grp1/sub/ua", "m s⁻¹"}});
  std::ostringstream out;
  describe_store(*store, out);
  const auto rows = section(out.str(), "variables ");
  // Characters (not bytes: "m s⁻¹" is 5 characters, 8 bytes) before byte `at`.
  const auto chars_before = [](const std::string& row, std::size_t at) {
    return text_width(std::string_view(row).substr(0, at));
  };
  // The type column starts at the same character in every variable's row, after at
  // least two spaces, whatever the length of the name before it.
  std::vector<std::size_t> type_columns;
  for (const auto& row : rows) {
    const auto at = row.find("float32");
    if (at == std::string::npos) continue;
    EXPECT_EQ(row.substr(at - 2, 2), "  ") << row;
    type_columns.push_back(chars_before(row, at));
  }
  ASSERT_EQ(type_columns.size(), 3u) << out.str();
  EXPECT_EQ(type_columns[0], type_columns[1]) << out.str();
  EXPECT_EQ(type_columns[0], type_columns[2]) << out.str();
  // A heading row names the columns; every column starts where its heading does, after
  // at least two spaces.
  ASSERT_EQ(rows.size(), 4u) << out.str();
  EXPECT_TRUE(rows[0].starts_with("  name ")) << rows[0];
  for (const char* heading : {"type", "units", "predictor"}) {
    const auto column = rows[0].find(heading);
    ASSERT_NE(column, std::string::npos);
    for (std::size_t r = 1; r < rows.size(); ++r) {
      std::size_t at = 0;  // the byte where character `column` starts
      while (at < rows[r].size() && chars_before(rows[r], at + 1) <= column) ++at;
      ASSERT_GE(at, 2u);
      EXPECT_EQ(rows[r].substr(at - 2, 2), "  ") << heading << " in: " << rows[r];
      EXPECT_NE(rows[r][at], ' ') << heading << " in: " << rows[r];
    }
  }
  const auto long_row = std::find_if(rows.begin(), rows.end(), [&](const std::string& row) {
    return row.starts_with("  " + long_name + "  ");
  });
  ASSERT_NE(long_row, rows.end()) << out.str();
  EXPECT_TRUE(long_row->starts_with("  " + long_name + "  float32  kg m-2 s-1 of something long  "))
      << *long_row;
}

TEST(StoreInfoTest, GridGeometryIsOneLineInTextAndJson) {
  TempDir dir;
  write_geometry_store(dir / "store");  // curvilinear, surface, time-invariant field
  const auto store = Store::open(dir / "store");
  const std::string line =
      "curvilinear 5 x 4 from XLONG/XLAT; heights (m) from atmosphere_hybrid_height_coordinate "
      "(a, b, orog), time-invariant, float64; surface from topography_c";
  std::ostringstream out;
  describe_store(*store, out);
  EXPECT_NE(out.str().find("\ngeometry   " + line + "\n"), std::string::npos) << out.str();
  const auto j = store_info_json(*store);
  EXPECT_EQ(j["geometry_info"]["summary"], line);
  EXPECT_EQ(j["geometry_info"]["files"]["GEOMETRY"],
            std::filesystem::file_size(dir / "store" / "GEOMETRY"));
  EXPECT_EQ(j["geometry_info"]["files"]["geometry.bricks"],
            std::filesystem::file_size(dir / "store" / "geometry.bricks"));
  EXPECT_EQ(j["geometry"]["vertical"]["kind"], "field");

  GeometryStoreSpec varying;
  varying.curvilinear = false;
  varying.surface = false;
  varying.field = GeometryField::kVarying;
  write_geometry_store(dir / "varying", varying);
  const auto j2 = store_info_json(*Store::open(dir / "varying"));
  EXPECT_EQ(j2["geometry_info"]["summary"],
            "heights (m) from atmosphere_hybrid_height_coordinate (a, b, orog), time-varying, "
            "float64");
  EXPECT_TRUE(j2["geometry_info"]["files"].empty());
}

TEST(StoreInfoTest, StoreWithoutGeometryHasNoGeometryLine) {
  TempDir dir;
  SimpleGrid g;
  const auto store = make_store(dir, g, {{"t", "K"}});
  std::ostringstream out;
  describe_store(*store, out);
  EXPECT_EQ(out.str().find("geometry"), std::string::npos) << out.str();
  EXPECT_FALSE(store_info_json(*store).contains("geometry_info"));
}

TEST(StoreInfoTest, LossyVariablesShowTheirBoundInTextAndJson) {
  TempDir dir;
  SimpleGrid g;
  const auto store = make_store(dir, g, {{"t", "K"}, {"u", "m s-1"}}, "t=abs:0.25,u=rel:0.01");
  std::ostringstream out;
  describe_store(*store, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("(format version 6)"), std::string::npos) << text;
  const auto codecs = section(text, "codec");
  ASSERT_EQ(codecs.size(), 2u) << text;
  EXPECT_NE(codecs[0].find("t "), std::string::npos) << codecs[0];
  EXPECT_NE(codecs[0].find("LOSSY zfp within 0.25 (abs)"), std::string::npos) << codecs[0];
  EXPECT_NE(codecs[1].find("LOSSY zfp within 0.23 (rel 0.01 of the range)"), std::string::npos)
      << codecs[1];  // u is a ramp 0 .. 23 here
  const auto j = store_info_json(*store);
  EXPECT_EQ(j["variables"][0]["codec"]["zfp"]["tolerance"], 0.25);
  EXPECT_EQ(j["variables"][1]["codec"]["zfp"]["mode"], "rel");
}

}  // namespace
}  // namespace strielad
