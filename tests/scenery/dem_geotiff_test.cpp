// SPDX-License-Identifier: Apache-2.0
// GeoTIFF DEMs written by the test through GDAL: the geotransform places samples
// (EPSG:4326 and a UTM CRS transformed to lon/lat), nodata becomes NaN, strided reads
// equal the full read's samples.
#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <vector>

#include "scenery/dem_source.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

// width x height float32 band, value 10 * row + col, nodata -9999 at (row 1, col 2).
std::filesystem::path write_geotiff(const std::filesystem::path& path, int width, int height,
                                    const double transform[6], int epsg) {
  GDALAllRegister();
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  GDALDatasetH ds = GDALCreate(driver, path.c_str(), width, height, 1, GDT_Float32, nullptr);
  EXPECT_NE(ds, nullptr);
  GDALSetGeoTransform(ds, const_cast<double*>(transform));
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  std::vector<float> v(std::size_t(width) * height);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) v[std::size_t(r) * width + c] = float(10 * r + c);
  }
  v[std::size_t(1) * width + 2] = -9999.0f;
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, -9999.0);
  EXPECT_EQ(GDALRasterIO(band, GF_Write, 0, 0, width, height, v.data(), width, height,
                         GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
  return path;
}

TEST(DemGeotiffTest, GeotransformAndNodata) {
  testing::TempDir dir;
  const double t[6] = {5.0, 0.5, 0.0, 55.0, 0.0, -0.25};  // north up, 0.5 x 0.25 degrees
  const auto dem = geo::open_dem(write_geotiff(dir.path() / "dem.tif", 8, 6, t, 4326));
  ASSERT_EQ(dem->width(), 8u);
  ASSERT_EQ(dem->height(), 6u);
  const auto ll = dem->georeference(0, 0);  // the first sample's centre
  EXPECT_NEAR(ll.lon, 5.25, 1e-9);
  EXPECT_NEAR(ll.lat, 54.875, 1e-9);
  const auto h = dem->read({0, 0, 8, 6, 1});
  EXPECT_EQ(h[0], 0.0f);
  EXPECT_EQ(h[5 * 8 + 7], 57.0f);
  EXPECT_TRUE(std::isnan(h[1 * 8 + 2]));
  EXPECT_NE(dem->describe().find("GTiff"), std::string::npos);
}

TEST(DemGeotiffTest, StridedReadEqualsTheFullReadsSamples) {
  testing::TempDir dir;
  const double t[6] = {5.0, 0.01, 0.0, 55.0, 0.0, -0.01};
  const auto dem = geo::open_dem(write_geotiff(dir.path() / "dem.tif", 101, 77, t, 4326));
  const auto all = dem->read({0, 0, 101, 77, 1});
  for (const std::size_t stride : {2u, 3u, 4u, 7u}) {
    const geo::DemWindow w{1, 2, (100 - 1) / stride + 1, (76 - 2) / stride + 1, stride};
    const auto s = dem->read(w);
    for (std::size_t r = 0; r < w.rows; ++r) {
      for (std::size_t c = 0; c < w.cols; ++c) {
        const float want = all[(w.row0 + r * stride) * 101 + w.col0 + c * stride];
        const float got = s[r * w.cols + c];
        if (std::isnan(want)) {
          EXPECT_TRUE(std::isnan(got));
        } else {
          ASSERT_EQ(got, want) << "stride " << stride << " at " << r << "," << c;
        }
      }
    }
  }
}

TEST(DemGeotiffTest, ProjectedCrsIsTransformedToLonLat) {
  testing::TempDir dir;
  // UTM zone 32N: easting 500 km is the central meridian 9 E.
  const double t[6] = {499000.0, 1000.0, 0.0, 5540000.0, 0.0, -1000.0};
  const auto dem = geo::open_dem(write_geotiff(dir.path() / "utm.tif", 4, 4, t, 32632));
  const auto ll = dem->georeference(0.5, 0);  // easting 500,000 m
  EXPECT_NEAR(ll.lon, 9.0, 1e-6);
  EXPECT_NEAR(ll.lat, 50.0, 0.01);  // northing 5,539.5 km is about 50.0 N
  EXPECT_NE(dem->georeferencing().find("UTM"), std::string::npos);
}

}  // namespace
}  // namespace strielad
