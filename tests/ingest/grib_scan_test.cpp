// SPDX-License-Identifier: Apache-2.0
// GRIB messages grouped into 3-D variables by (shortName, typeOfLevel), with levels and
// validity times: NCEP's AWIPS 211 file (libncarg-data) and generated files for what
// must be refused (a field twice, a level missing at one time, a variable on two grids).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ingest/grib_scan.h"
#include "support/expect_error.h"
#include "support/grib_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::GribFixtureMessage;
using strielad::testing::ncarg_file;

const GribVariable* find(const GribScan& scan, const std::string& short_name) {
  for (const auto& v : scan.variables) {
    if (v.short_name == short_name) return &v;
  }
  return nullptr;
}

TEST(GribScanTest, NcepFileGivesItsIsobaricVariables) {
  const GribScan scan = scan_grib_file(ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2"));
  for (const char* name : {"gh", "r", "t", "u", "v", "w"}) {
    const GribVariable* v = find(scan, name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->type_of_level, "isobaricInhPa");
    EXPECT_EQ(v->z.kind, AxisKind::kPressure);
    EXPECT_EQ(v->z.units, "hPa");
    ASSERT_EQ(v->z.size(), 19u) << name;
    EXPECT_EQ(v->z.values.front(), 100.0);
    EXPECT_EQ(v->z.values.back(), 1000.0);
    ASSERT_EQ(v->times.size(), 1u);
    EXPECT_EQ(v->times[0], 1169640000);  // 2007-01-24 12:00 UTC, the 12 h forecast
    ASSERT_EQ(v->messages.size(), 1u);
    ASSERT_EQ(v->messages[0].size(), 19u);
    for (std::size_t k = 0; k < 19; ++k) EXPECT_EQ(v->messages[0][k].level_value, v->z.values[k]);
  }
  const GribVariable* t = find(scan, "t");
  EXPECT_EQ(t->units, "K");
  EXPECT_EQ(t->name, "Temperature");
  const GribVariable* absv = find(scan, "absv");
  ASSERT_NE(absv, nullptr);
  EXPECT_EQ(absv->z.values, (std::vector<double>{250, 500, 700, 850, 1000}));
  const auto skipped = [&](const std::string& name, const std::string& why) {
    return std::any_of(scan.skipped.begin(), scan.skipped.end(), [&](const GribSkipped& s) {
      return s.short_name == name && s.why.find(why) != std::string::npos;
    });
  };
  EXPECT_TRUE(skipped("mslet", "not a vertical level type"));
  EXPECT_TRUE(skipped("2t", "one level"));
}

GribFixtureMessage t_message(long level, long date, long time, long ni = 16) {
  return {"regular_ll_pl_grib2",
          {{"Ni", ni}, {"level", level}, {"dataDate", date}, {"dataTime", time}},
          std::vector<double>(static_cast<std::size_t>(ni) * 31, 250.0)};
}

TEST(GribScanTest, StepsAndLevelsOfASeries) {
  const testing::TempDir dir;
  testing::write_grib_file(dir / "s.grb2",
                           {t_message(500, 20240101, 0), t_message(850, 20240101, 0),
                            t_message(850, 20240101, 600), t_message(500, 20240101, 600)});
  const GribScan scan = scan_grib_file(dir / "s.grb2");
  ASSERT_EQ(scan.variables.size(), 1u);
  const GribVariable& v = scan.variables[0];
  EXPECT_EQ(v.z.values, (std::vector<double>{500, 850}));
  ASSERT_EQ(v.times.size(), 2u);
  EXPECT_EQ(v.times[1] - v.times[0], 6 * 3600);
  EXPECT_EQ(v.messages[1][0].offset, v.messages[0][1].offset + v.messages[0][1].size * 2);
}

TEST(GribScanTest, AFieldInTwoMessagesIsRefusedWithBothOffsets) {
  const testing::TempDir dir;
  testing::write_grib_file(
      dir / "d.grb2",
      {t_message(500, 20240101, 0), t_message(850, 20240101, 0), t_message(500, 20240101, 0)});
  expect_error([&] { scan_grib_file(dir / "d.grb2"); }, ErrorCode::kInvalidInput,
               {"d.grb2", "'t' on isobaricInhPa", "level 500", "two messages", "at bytes 0 and"});
}

TEST(GribScanTest, ALevelMissingAtOneTimeIsRefused) {
  const testing::TempDir dir;
  testing::write_grib_file(
      dir / "g.grb2",
      {t_message(500, 20240101, 0), t_message(850, 20240101, 0), t_message(500, 20240101, 600)});
  expect_error([&] { scan_grib_file(dir / "g.grb2"); }, ErrorCode::kInvalidInput,
               {"g.grb2", "'t' on isobaricInhPa", "level 850 is missing"});
}

TEST(GribScanTest, OneVariableOnTwoGridsIsRefused) {
  const testing::TempDir dir;
  testing::write_grib_file(dir / "two.grb2",
                           {t_message(500, 20240101, 0), t_message(850, 20240101, 0, 17)});
  expect_error([&] { scan_grib_file(dir / "two.grb2"); }, ErrorCode::kInvalidInput,
               {"two.grb2", "different grids"});
}

TEST(GribScanTest, ValiditySecondsAreUtcSinceTheEpoch) {
  EXPECT_EQ(grib_validity_seconds(19700101, 0), 0);
  EXPECT_EQ(grib_validity_seconds(20070124, 1200), 1169640000);
  EXPECT_EQ(grib_validity_seconds(20000301, 2359), 951868800 + 23 * 3600 + 59 * 60);
  expect_error([] { grib_validity_seconds(20070229, 0); }, ErrorCode::kInvalidInput,
               {"20070229", "not a date"});
  expect_error([] { grib_validity_seconds(20070101, 2460); }, ErrorCode::kInvalidInput,
               {"2460", "not a date"});
}

}  // namespace
}  // namespace strielad::ingest
