// SPDX-License-Identifier: Apache-2.0
// Every NetCDF reader opens files through ingest::NcFile, which checks a classic-format
// header against the file's size before netCDF-C reads it: a 460-byte CDF-2 file that
// declares 33 million dimensions (the dem_netcdf fuzz target's reproducer) made nc_open
// calloc 1.7 GB and take seconds, and dereference null where the allocation failed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scenery/dem_source.h"
#include "scenery/flight_tracks.h"
#include "ingest/classic_layout.h"
#include "ingest/netcdf_file.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

const std::filesystem::path kDimensions = std::filesystem::path(STRIELAD_SOURCE_DIR) /
                                          "tests/fuzz/regressions/dem_netcdf/33-million-dimensions-in-460-bytes.nc";

TEST(ClassicHeaderCheckedBeforeNetcdfTest, HeaderDeclaringMoreThanTheFileHoldsIsRefusedAtOnce) {
  expect_error([] { ingest::NcFile file(kDimensions); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated", "inside its netCDF header"});
}

TEST(ClassicHeaderCheckedBeforeNetcdfTest, HeaderOutsideTheGrammarNeverReachesNetcdf) {
  // Mutated classic headers (a variable count overwritten by a name's bytes, ...) that
  // made netCDF-C's header parser crash (SEGV in NC_hashmapadd and in
  // free_NC_vararrayV): refused by the grammar check, naming the file.
  const std::filesystem::path regressions =
      std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/fuzz/regressions";
  for (const auto& path : {regressions / "dem_netcdf/mutated-variable-count-crashes-nc-hashmapadd.nc",
                           regressions / "flight_tracks_netcdf/damaged-header-crashes-free-nc-vararray.nc"}) {
    expect_error([&] { ingest::NcFile file(path); }, ErrorCode::kInvalidInput,
                 {path.string(), "classic-format header is damaged"});
  }
}

TEST(ClassicHeaderCheckedBeforeNetcdfTest, EveryClassicFileOfLibncargDataPasses) {
  // Real classic, 64-bit offset and CDF-5 files: the grammar check refuses none of them.
  std::size_t classic = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(STRIELAD_NCARG_DATA_DIR)) {
    if (!e.is_regular_file()) continue;
    char magic[4] = {};
    std::ifstream(e.path(), std::ios::binary).read(magic, 4);
    if (magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F') continue;
    ++classic;
    EXPECT_NO_THROW(ingest::check_classic_header(e.path())) << e.path();
  }
  EXPECT_GT(classic, 50u) << "libncarg-data missing?";
}

TEST(ClassicHeaderCheckedBeforeNetcdfTest, DemAndFlightTrackReadersRefuseIt) {
  expect_error([] { geo::open_netcdf_dem(kDimensions, ""); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated"});
  expect_error([] { geo::load_flight_tracks_netcdf(kDimensions); }, ErrorCode::kInvalidInput,
               {kDimensions.string(), "file is truncated"});
}

}  // namespace
}  // namespace strielad
