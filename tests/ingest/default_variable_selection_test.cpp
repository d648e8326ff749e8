// SPDX-License-Identifier: Apache-2.0
// Without a variable list, every 3D variable on the grid of the first one is converted;
// variables on other grids (half levels) and 2D fields are skipped. Asked for by name, a
// variable on another grid is an error naming both axes.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

// ua on 3 full levels, wa on 4 half levels, ps 2D, time_bnds auxiliary.
std::filesystem::path write_model_output(const TempDir& dir) {
  SimpleGrid g;
  g.lev = {1, 2, 3};
  g.lev_units = "1";
  const auto path = dir / "model.nc";
  NetcdfFixture()
      .grid(g)
      .coordinate("lev_2", {0.5, 1.5, 2.5, 3.5}, {NcAttr::text_value("axis", "Z")})
      .dimension("bnds", 2)
      .variable("time_bnds", NC_DOUBLE, {"time", "bnds"}, {0, 1})
      .variable("ps", NC_FLOAT, {"time", "lat", "lon"}, ramp(12))
      .variable("ua", NC_FLOAT, g.dims(), ramp(g.samples()))
      .variable("wa", NC_FLOAT, {"time", "lev_2", "lat", "lon"}, ramp(48))
      .variable("va", NC_FLOAT, g.dims(), ramp(g.samples()))
      .write(path);
  return path;
}

TEST(DefaultVariableSelectionTest, SkipsOtherGridsAnd2DFields) {
  TempDir dir;
  const InputCatalog c = scan_inputs({write_model_output(dir)}, {});
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "ua");
  EXPECT_EQ(c.variables[1].name, "va");
  EXPECT_EQ(c.z.name, "lev");
  EXPECT_EQ(c.z.size(), 3u);
}

TEST(DefaultVariableSelectionTest, RequestedHalfLevelVariableIsAGridMismatch) {
  TempDir dir;
  const auto path = write_model_output(dir);
  ScanOptions o;
  o.variables = {"ua", "wa"};
  expect_error([&] { scan_inputs({path}, o); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'wa' is not on the grid of variable 'ua'",
                "axis 'lev_2' has 4 values but axis 'lev'", "has 3"});
}

TEST(DefaultVariableSelectionTest, RequestedVariableDecidesTheGrid) {
  TempDir dir;
  ScanOptions o;
  o.variables = {"wa"};
  const InputCatalog c = scan_inputs({write_model_output(dir)}, o);
  EXPECT_EQ(c.z.name, "lev_2");
  EXPECT_EQ(c.z.size(), 4u);
}

TEST(DefaultVariableSelectionTest, RequestedSurfaceFieldIsUnsupported) {
  TempDir dir;
  const auto path = write_model_output(dir);
  ScanOptions o;
  o.variables = {"ps"};
  expect_error([&] { scan_inputs({path}, o); }, ErrorCode::kUnsupported,
               {"variable 'ps' has no vertical dimension", "(time, lat, lon)"});
}

}  // namespace
}  // namespace strielad::ingest
