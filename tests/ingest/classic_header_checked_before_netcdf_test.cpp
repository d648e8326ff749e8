// SPDX-License-Identifier: Apache-2.0
// Every NetCDF reader opens files through ingest::NcFile, which checks a classic-format
// header against the file's size before netCDF-C reads it: a 460-byte CDF-2 file that
// declares 33 million dimensions (the dem_netcdf fuzz target's reproducer) made nc_open
// calloc 1.7 GB and take seconds, and dereference null where the allocation failed.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "geo/dem_source.h"
#include "geo/flight_tracks.h"
#include "ingest/netcdf_file.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

const std::filesystem::path kDimensions = std::filesystem::path(STRIELAD_SOURCE_DIR) /
                                          "tests/fuzz/regressions/dem_netcdf/33-million-dimensions-in-460-bytes.nc";

TEST(ClassicHeaderCheckedBeforeNetcdfTest, HeaderDeclaringMoreThanTheFileHoldsIsRefusedAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  expect_error([] { ingest::NcFile file(kDimensions); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated", "inside its netCDF header"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(ClassicHeaderCheckedBeforeNetcdfTest, DemAndFlightTrackReadersRefuseIt) {
  expect_error([] { geo::open_netcdf_dem(kDimensions, ""); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated"});
  expect_error([] { geo::load_flight_tracks_netcdf(kDimensions); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated"});
}

}  // namespace
}  // namespace strielad
