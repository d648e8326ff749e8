// SPDX-License-Identifier: Apache-2.0
// Flight tracks from CF trajectory NetCDF files (lib/scenery/flight_tracks.h): the
// multidimensional layout with fill padding, the contiguous ragged layout, ids and
// altitude units, and files that are not trajectory files.
#include <gtest/gtest.h>

#include <cmath>

#include "scenery/flight_tracks.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::geo {
namespace {

using strielad::testing::expect_error;
using strielad::testing::NcAttr;
using strielad::testing::NetcdfFixture;

const double kFill = -999;

NetcdfFixture with_variables(NetcdfFixture f, const std::vector<std::string>& dims,
                             std::vector<double> time, std::vector<double> lon,
                             std::vector<double> lat, std::vector<double> alt) {
  const auto fill = NcAttr::number("_FillValue", NC_DOUBLE, {kFill});
  return f.global_attribute(NcAttr::text_value("featureType", "trajectory"))
      .variable("time", NC_DOUBLE, dims, std::move(time),
                {NcAttr::text_value("standard_name", "time"),
                 NcAttr::text_value("units", "seconds since 2013-04-26 12:00:00"), fill})
      .variable("lon", NC_DOUBLE, dims, std::move(lon),
                {NcAttr::text_value("standard_name", "longitude"), fill})
      .variable("lat", NC_DOUBLE, dims, std::move(lat),
                {NcAttr::text_value("standard_name", "latitude"), fill})
      .variable("alt", NC_DOUBLE, dims, std::move(alt),
                {NcAttr::text_value("standard_name", "altitude"), NcAttr::text_value("units", "km"), fill});
}

TEST(FlightTracksNetcdfTest, MultidimensionalLayoutWithPadding) {
  testing::TempDir dir;
  NetcdfFixture f;
  f.dimension("trajectory", 2).dimension("obs", 3);
  f.variable("flight", NC_INT, {"trajectory"}, {4711, 815}, {NcAttr::text_value("cf_role", "trajectory_id")});
  with_variables(f, {"trajectory", "obs"}, {60, 0, 120, 30, 90, kFill}, {6, 5, 7, 10, 11, kFill},
                 {50, 49, 51, 52, 53, kFill}, {10, 9.5, 10.5, 3, 4, kFill})
      .write(dir / "tracks.nc");
  const FlightTracks tracks = load_flight_tracks(dir / "tracks.nc");
  ASSERT_EQ(tracks.tracks.size(), 2u);
  EXPECT_EQ(tracks.reports, 5u);
  EXPECT_DOUBLE_EQ(tracks.reference_julian_day, 2456409.0);
  const auto& a = tracks.tracks[0];
  EXPECT_EQ(a.id, "4711");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_NEAR(a.seconds[0], 0, 1e-4);  // sorted by time
  EXPECT_EQ(a.lon[0], 5.0);
  EXPECT_EQ(a.altitude_m[0], 9500.0);  // km -> m
  const auto& b = tracks.tracks[1];
  EXPECT_EQ(b.id, "815");
  EXPECT_EQ(b.size(), 2u);  // the padding is not a report
  EXPECT_NEAR(b.seconds[0], 30, 1e-4);
}

TEST(FlightTracksNetcdfTest, ContiguousRaggedLayout) {
  testing::TempDir dir;
  NetcdfFixture f;
  f.dimension("trajectory", 2).dimension("obs", 5);
  f.variable("row_size", NC_INT, {"trajectory"}, {2, 3}, {NcAttr::text_value("sample_dimension", "obs")});
  with_variables(f, {"obs"}, {0, 60, 10, 20, 30}, {5, 6, 9, 9.1, 9.2}, {48, 49, 50, 50, 50},
                 {1, 2, 3, 3, 3})
      .write(dir / "ragged.nc");
  const FlightTracks tracks = load_flight_tracks(dir / "ragged.nc");
  ASSERT_EQ(tracks.tracks.size(), 2u);
  EXPECT_EQ(tracks.tracks[0].id, "0");  // no trajectory_id variable: the index
  EXPECT_EQ(tracks.tracks[0].size(), 2u);
  EXPECT_EQ(tracks.tracks[1].size(), 3u);
  EXPECT_EQ(tracks.tracks[1].lon[2], 9.2);
}

TEST(FlightTracksNetcdfTest, FilesThatAreNotTrajectoriesAreRefused) {
  testing::TempDir dir;
  NetcdfFixture plain;
  plain.dimension("obs", 2);
  plain.variable("time", NC_DOUBLE, {"obs"}, {0, 1}).write(dir / "plain.nc");
  expect_error([&] { load_flight_tracks(dir / "plain.nc"); }, ErrorCode::kInvalidInput,
               {"plain.nc", "featureType"});
  NetcdfFixture no_alt;
  no_alt.dimension("obs", 2);
  no_alt.global_attribute(NcAttr::text_value("featureType", "trajectory"))
      .variable("time", NC_DOUBLE, {"obs"}, {0, 1}, {NcAttr::text_value("units", "seconds since 2000-01-01")})
      .variable("lon", NC_DOUBLE, {"obs"}, {0, 1})
      .variable("lat", NC_DOUBLE, {"obs"}, {0, 1})
      .write(dir / "no-alt.nc");
  expect_error([&] { load_flight_tracks(dir / "no-alt.nc"); }, ErrorCode::kInvalidInput,
               {"no-alt.nc", "altitude"});
  expect_error([&] { load_flight_tracks(dir / "missing.nc"); }, ErrorCode::kNotFound, {"missing.nc"});
}

}  // namespace
}  // namespace strielad::geo
