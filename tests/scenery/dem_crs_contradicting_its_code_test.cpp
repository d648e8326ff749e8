// SPDX-License-Identifier: Apache-2.0
// A GeoTIFF whose (damaged) keys give a geographic CRS the code of a geocentric one
// (EPSG:4342, "EST97 (geocentric)"): PROJ looks the code up when GDAL builds the
// transformation to WGS84 and dereferenced null (SEGV). The DEM reader refuses such a
// CRS, naming the file and the code, before any transformation is built.
#include <gtest/gtest.h>

#include <filesystem>

#include "scenery/dem_source.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

TEST(DemCrsContradictingItsCodeTest, GeographicCrsWithAGeocentricCodeIsRefused) {
  const auto path = std::filesystem::path(STRIELAD_SOURCE_DIR) /
                    "tests/fuzz/regressions/dem_gdal/geographic-crs-with-a-geocentric-epsg-code.tif";
  testing::expect_error([&] { geo::open_gdal_dem(path); }, ErrorCode::kInvalidInput,
                        {path.string(), "geographic CRS carries the code EPSG:4342",
                         "which is a geocentric CRS"});
}

}  // namespace
}  // namespace strielad
