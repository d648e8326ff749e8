// SPDX-License-Identifier: Apache-2.0
// GRIB input converted end to end: NCEP's AWIPS 211 forecast (libncarg-data; Lambert
// conformal, 19 isobaric levels) becomes a store whose level-0 samples are exactly the
// values ecCodes decodes, on the grid and mapping the message defines; a generated file
// with a bitmap keeps its missing points missing.
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "convert/converter.h"
#include "ingest/grib_messages.h"
#include "ingest/grib_scan.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/grib_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using strielad::testing::ncarg_file;

build::ConvertOptions options(const std::filesystem::path& input,
                              const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = {input};
  o.store = store;
  o.brick = 16;
  o.threads = 1;
  return o;
}

std::vector<double> decoded_values(const std::filesystem::path& path,
                                   const ingest::GribMessageSummary& m) {
  std::lock_guard lock(ingest::eccodes_mutex());
  return ingest::read_grib_message(path, m).double_array_key("values", path.string());
}

TEST(GribConversionTest, NcepForecastSamplesAreWhatEcCodesDecodes) {
  const testing::TempDir dir;
  const auto input = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto& m = store->manifest();
  EXPECT_EQ(m.variables.size(), 6u);  // gh, r, t, u, v, w: the 19-level set
  ASSERT_TRUE(m.grid_mapping);
  EXPECT_EQ(m.grid_mapping->name, "lambert_conformal_conic");
  EXPECT_EQ(m.time.units, "seconds since 1970-01-01 00:00:00");
  ASSERT_EQ(m.time.values.size(), 1u);
  EXPECT_EQ(m.time.values[0], 1169640000.0);

  const ingest::GribScan scan = ingest::scan_grib_file(input);
  const ingest::GribVariable* t = nullptr;
  for (const auto& v : scan.variables) {
    if (v.short_name == "t") t = &v;
  }
  ASSERT_NE(t, nullptr);
  const auto level0 =
      read_level_samples<float>(*store, 0, static_cast<std::uint32_t>(m.variable_index("t")), 0);
  ASSERT_EQ(level0.dims[0], 93u);
  ASSERT_EQ(level0.dims[1], 65u);
  ASSERT_EQ(level0.dims[2], 19u);
  const std::size_t plane = 93 * 65;
  for (std::size_t k = 0; k < 19; ++k) {
    const std::vector<double> want = decoded_values(input, t->messages[0][k]);
    ASSERT_EQ(want.size(), plane);
    for (std::size_t i = 0; i < plane; ++i) {
      ASSERT_EQ(level0.values[k * plane + i], static_cast<float>(want[i]))
          << "level " << k << " sample " << i;
    }
  }
}

TEST(GribConversionTest, BitmapPointsStayMissing) {
  const testing::TempDir dir;
  std::vector<double> values(16 * 31);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 250.0 + static_cast<double>(i % 17);
  testing::GribFixtureMessage m{
      "regular_ll_pl_grib2",
      {{"bitmapPresent", 1L}, {"missingValue", 9999.0}, {"bitsPerValue", 16L}},
      {}};
  std::vector<testing::GribFixtureMessage> messages;
  for (const long level : {500L, 850L}) {
    auto copy = m;
    copy.keys.emplace_back("level", level);
    copy.values = values;
    for (std::size_t i = 0; i < copy.values.size(); i += 7) copy.values[i] = 9999.0;  // missing
    messages.push_back(copy);
  }
  testing::write_grib_file(dir / "b.grb2", messages);
  build::convert(options(dir / "b.grb2", dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto level0 = read_level_samples<float>(*store, 0, 0, 0);
  const std::size_t plane = 16 * 31;
  ASSERT_EQ(level0.values.size(), plane * 2);
  const auto decoded = ingest::scan_grib_file(dir / "b.grb2");
  ASSERT_EQ(decoded.variables.size(), 1u);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::vector<double> want =
        decoded_values(dir / "b.grb2", decoded.variables[0].messages[0][k]);
    for (std::size_t i = 0; i < plane; ++i) {
      if (i % 7 == 0) {
        EXPECT_TRUE(std::isnan(level0.values[k * plane + i])) << k << " " << i;
      } else {
        EXPECT_EQ(level0.values[k * plane + i], static_cast<float>(want[i])) << k << " " << i;
        EXPECT_NEAR(want[i], values[i], 0.01);
      }
    }
  }
}

}  // namespace
}  // namespace strielad
