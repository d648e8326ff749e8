// SPDX-License-Identifier: Apache-2.0
// Variables may come from different files, as long as all have the same time steps.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

void write(const std::filesystem::path& path, const std::string& var, SimpleGrid g,
           double base) {
  NetcdfFixture().grid(g).variable(var, NC_FLOAT, g.dims(), ramp(g.samples(), base)).write(path);
}

TEST(VariablesSplitOverFilesTest, EachVariableFromItsFile) {
  TempDir dir;
  SimpleGrid g;
  g.time = {0, 6};
  write(dir / "t.nc", "T", g, 100);
  write(dir / "u.nc", "U", g, 200);
  const InputCatalog c = scan_inputs({dir / "t.nc", dir / "u.nc"}, {});
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "T");
  EXPECT_EQ(c.variables[1].name, "U");
  EXPECT_EQ(c.locations[0][1].file, 0u);
  EXPECT_EQ(c.locations[1][1].file, 1u);
  EXPECT_EQ(c.locations[1][1].time_in_file, 1u);
  SlabReader reader(c, {});
  std::vector<float> out(g.samples_per_step());
  reader.read(1, 1, 0, 2, out);
  EXPECT_EQ(out[0], static_cast<float>(200 + g.samples_per_step()));
}

TEST(VariablesSplitOverFilesTest, VariableMissingATimeStepNamesVariableFileAndTime) {
  TempDir dir;
  SimpleGrid g, h;
  g.time = {0, 6};
  h.time = {0};
  write(dir / "t.nc", "T", g, 0);
  write(dir / "u.nc", "U", h, 0);
  expect_error([&] { scan_inputs({dir / "t.nc", dir / "u.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"variable 'U' has no time step 6 (hours since 2000-01-01 00:00:00)",
                (dir / "t.nc").string(), "variable 'T'"});
}

TEST(VariablesSplitOverFilesTest, FilesWithoutTimeAreOneStep) {
  TempDir dir;
  SimpleGrid g;
  g.with_time = false;
  write(dir / "t.nc", "T", g, 0);
  write(dir / "u.nc", "U", g, 0);
  const InputCatalog c = scan_inputs({dir / "t.nc", dir / "u.nc"}, {});
  EXPECT_EQ(c.time.values, std::vector<double>{0.0});
  EXPECT_EQ(c.time.units, "");
  EXPECT_EQ(c.locations[1][0].file, 1u);
  EXPECT_EQ(c.locations[1][0].time_in_file, 0u);
  SlabReader reader(c, {});
  std::vector<float> out(g.samples());
  reader.read(1, 0, 0, 2, out);
  EXPECT_EQ(out[5], 5.0f);
}

TEST(VariablesSplitOverFilesTest, TimeSeriesAndVariablesSplitTogether) {
  TempDir dir;
  SimpleGrid a, b;
  a.time = {0};
  b.time = {6};
  write(dir / "t0.nc", "T", a, 0);
  write(dir / "t6.nc", "T", b, 0);
  write(dir / "u0.nc", "U", a, 0);
  write(dir / "u6.nc", "U", b, 0);
  const InputCatalog c =
      scan_inputs({dir / "u6.nc", dir / "t6.nc", dir / "t0.nc", dir / "u0.nc"}, {});
  EXPECT_EQ(c.time.values, (std::vector<double>{0, 6}));
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "U");  // first found in command-line order
  EXPECT_EQ(c.locations[0][0].file, 3u);
  EXPECT_EQ(c.locations[1][1].file, 1u);
}

}  // namespace
}  // namespace strielad::ingest
