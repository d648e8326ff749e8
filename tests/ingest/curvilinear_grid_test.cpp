// SPDX-License-Identifier: Apache-2.0
// Variables on curvilinear grids placed by 2-D latitude/longitude that the `coordinates`
// attribute names: scanned with index axes and the file's coordinates (longitudes
// unwrapped across the antimeridian), and refused, naming the file, variable and (i, j),
// when the coordinates cannot place a store: missing or non-finite values, latitudes
// outside [-90, 90], a cell over a pole, longitudes that cannot be unwrapped, a folded
// grid, coordinates that differ between files. NCL's Eta file, whose coordinates
// attribute names variables it lacks, stays refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ingest/input_catalog.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

// A (time, lev, y, x) variable T on an nx x ny grid placed by 2-D lon(y, x), lat(y, x).
std::filesystem::path write_grid(const TempDir& dir, const std::string& name, std::size_t nx,
                                 std::size_t ny, const std::vector<double>& lon,
                                 const std::vector<double>& lat, double time = 0,
                                 std::vector<NcAttr> lat_extra = {}) {
  std::vector<NcAttr> lat_attrs{NcAttr::text_value("standard_name", "latitude"),
                                NcAttr::text_value("units", "degrees_north")};
  lat_attrs.insert(lat_attrs.end(), lat_extra.begin(), lat_extra.end());
  const auto path = dir / name;
  NetcdfFixture(NC_NETCDF4)
      .coordinate("time", {time}, {NcAttr::text_value("units", "hours since 2000-01-01")},
                  NC_DOUBLE, true)
      .coordinate("lev", {1000, 500}, {NcAttr::text_value("units", "hPa")})
      .dimension("y", ny)
      .dimension("x", nx)
      .variable("lat", NC_DOUBLE, {"y", "x"}, lat, lat_attrs)
      .variable("lon", NC_DOUBLE, {"y", "x"}, lon,
                {NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"time", "lev", "y", "x"}, ramp(2 * nx * ny),
                {NcAttr::text_value("coordinates", "lon lat")})
      .write(path);
  return path;
}

// 4 x 3: longitudes 10, 11, 12, 13 east, latitudes 50, 51, 52 north, slightly sheared.
std::vector<double> plain_lon() { return {10, 11, 12, 13, 10.1, 11.1, 12.1, 13.1, 10.2, 11.2, 12.2, 13.2}; }
std::vector<double> plain_lat() { return {50, 50.1, 50.2, 50.3, 51, 51.1, 51.2, 51.3, 52, 52.1, 52.2, 52.3}; }

InputCatalog scan_t(const std::vector<std::filesystem::path>& files) {
  ScanOptions o;
  o.variables = {"T"};
  return scan_inputs(files, o);
}

TEST(CurvilinearGridTest, TwoDimensionalCoordinatesPlaceIndexAxes) {
  TempDir dir;
  const auto file = write_grid(dir, "c.nc", 4, 3, plain_lon(), plain_lat());
  const InputCatalog c = scan_t({file});
  EXPECT_EQ(c.x.kind, AxisKind::kIndex);
  EXPECT_EQ(c.y.kind, AxisKind::kIndex);
  EXPECT_EQ(c.x.name, "x");
  EXPECT_EQ(c.x.values, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(c.y.values, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(c.z.name, "lev");
  EXPECT_FALSE(c.grid_mapping);
  ASSERT_TRUE(c.curvilinear);
  EXPECT_EQ(c.curvilinear->lon_variable, "lon");
  EXPECT_EQ(c.curvilinear->lat_variable, "lat");
  EXPECT_EQ(c.curvilinear->lon, plain_lon());
  EXPECT_EQ(c.curvilinear->lat, plain_lat());
  EXPECT_EQ(c.curvilinear->orientation, 1);
}

TEST(CurvilinearGridTest, TransposedPlacementTurnsTheOtherWay) {
  TempDir dir;
  // i runs north, j runs east.
  const std::vector<double> lon{10, 10, 10, 11, 11, 11}, lat{50, 51, 52, 50, 51, 52};
  const InputCatalog c = scan_t({write_grid(dir, "t.nc", 3, 2, lon, lat)});
  ASSERT_TRUE(c.curvilinear);
  EXPECT_EQ(c.curvilinear->orientation, -1);
}

TEST(CurvilinearGridTest, LongitudesAreUnwrappedAcrossTheAntimeridian) {
  TempDir dir;
  const std::vector<double> lon{178, 179, -180, -179, 178, 179, 180, -179};
  const std::vector<double> lat{10, 10, 10, 10, 11, 11, 11, 11};
  const InputCatalog c = scan_t({write_grid(dir, "a.nc", 4, 2, lon, lat)});
  ASSERT_TRUE(c.curvilinear);
  EXPECT_EQ(c.curvilinear->lon, (std::vector<double>{178, 179, 180, 181, 178, 179, 180, 181}));
  EXPECT_EQ(c.curvilinear->lat, lat);
}

TEST(CurvilinearGridTest, NonFiniteCoordinateIsRefused) {
  TempDir dir;
  std::vector<double> lon = plain_lon();
  lon[1 * 4 + 2] = std::numeric_limits<double>::quiet_NaN();
  const auto file = write_grid(dir, "nan.nc", 4, 3, lon, plain_lat());
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"nan.nc: variable 'T'", "2-D coordinate 'lon' at (i 2, j 1) is nan"});
}

TEST(CurvilinearGridTest, MissingCoordinateIsRefused) {
  TempDir dir;
  std::vector<double> lat = plain_lat();
  lat[1] = -999;
  const auto file = write_grid(dir, "fill.nc", 4, 3, plain_lon(), lat, 0,
                               {NcAttr::number("_FillValue", NC_DOUBLE, {-999})});
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"fill.nc: variable 'T'", "2-D coordinate 'lat' at (i 1, j 0) is missing"});
}

TEST(CurvilinearGridTest, LatitudeOutsideRangeIsRefused) {
  TempDir dir;
  std::vector<double> lat = plain_lat();
  lat[2 * 4 + 3] = 91;
  const auto file = write_grid(dir, "lat.nc", 4, 3, plain_lon(), lat);
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"lat.nc: variable 'T'", "latitude 'lat' at (i 3, j 2) is 91, outside [-90, 90]"});
}

TEST(CurvilinearGridTest, CellOverAPoleIsRefused) {
  TempDir dir;
  // The four corners round the north pole at 80 N.
  const std::vector<double> lon{0, 90, 270, 180}, lat{80, 80, 80, 80};
  const auto file = write_grid(dir, "pole.nc", 2, 2, lon, lat);
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"pole.nc: variable 'T'", "the grid cell from (i 0, j 0) to (i 1, j 1) contains "
                                         "the north pole"});
}

TEST(CurvilinearGridTest, SampleOnAPoleIsRefused) {
  TempDir dir;
  const std::vector<double> lon{0, 10, 0, 10}, lat{80, 80, 90, 85};
  const auto file = write_grid(dir, "onpole.nc", 2, 2, lon, lat);
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"onpole.nc: variable 'T'", "(i 0, j 1) lies on the north pole"});
}

TEST(CurvilinearGridTest, LongitudesThatCannotBeUnwrappedAreRefused) {
  TempDir dir;
  // Neighbours half a turn apart: no unwrapping brings them within 180 degrees.
  const std::vector<double> lon{0, 180, 0, 180}, lat{0, 0, 10, 10};
  const auto file = write_grid(dir, "wrap.nc", 2, 2, lon, lat);
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"wrap.nc: variable 'T'", "2-D longitude 'lon' cannot be unwrapped: (i 0, j 0) "
                                         "and (i 1, j 0) lie 180 degrees apart"});
}

TEST(CurvilinearGridTest, FoldedGridIsRefused) {
  TempDir dir;
  // Column 2 turns back west: the second cell is mirrored.
  const std::vector<double> lon{0, 1, 0.5, 0, 1, 0.5}, lat{0, 0, 0, 1, 1, 1};
  const auto file = write_grid(dir, "fold.nc", 3, 2, lon, lat);
  expect_error([&] { scan_t({file}); }, ErrorCode::kInvalidInput,
               {"fold.nc: variable 'T'", "the grid folds: the cell from (i 1, j 0) to (i 2, j 1) "
                                         "turns the other way than the cell at (i 0, j 0)"});
}

TEST(CurvilinearGridTest, CoordinatesThatDifferBetweenFilesAreRefused) {
  TempDir dir;
  std::vector<double> lon = plain_lon();
  const auto first = write_grid(dir, "t0.nc", 4, 3, lon, plain_lat(), 0);
  lon[2 * 4 + 1] += 0.25;
  const auto second = write_grid(dir, "t1.nc", 4, 3, lon, plain_lat(), 1);
  expect_error([&] { scan_t({first, second}); }, ErrorCode::kInvalidInput,
               {"t1.nc: variable 'T'", "2-D coordinate 'lon' at (i 1, j 2) is 11.45",
                "t0.nc has 11.2", "the same in every file and time step"});
}

TEST(CurvilinearGridTest, SameCoordinatesInEveryFileMakeOneSeries) {
  TempDir dir;
  const auto first = write_grid(dir, "t0.nc", 4, 3, plain_lon(), plain_lat(), 0);
  const auto second = write_grid(dir, "t1.nc", 4, 3, plain_lon(), plain_lat(), 1);
  const InputCatalog c = scan_t({first, second});
  EXPECT_EQ(c.time.values.size(), 2u);
  ASSERT_TRUE(c.curvilinear);
}

TEST(CurvilinearGridTest, EtaFileNamingAbsentCoordinatesStaysRefused) {
  const auto file = ncarg_file("cdf/ced1.lf00.t00z.eta.nc");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "libncarg-data is not installed";
  expect_error([&] { scan_inputs({file}, {}); }, ErrorCode::kUnsupported,
               {"ced1.lf00.t00z.eta.nc: variable", "is on a curvilinear grid",
                "which the file does not contain"});
}

}  // namespace
}  // namespace strielad::ingest
