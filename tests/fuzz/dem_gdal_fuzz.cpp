// SPDX-License-Identifier: Apache-2.0
// Fuzzes the GDAL DEM reader (scenery/dem_source.h, open_gdal_dem) on the input written to a
// file: opening, a strided read of the whole grid and georeferencing must reject with
// strielad::Error, never crash. Seeds are GeoTIFFs written through GDAL (EPSG:4326 with
// nodata, a UTM zone with a height unit and scale) and an ESRI ASCII grid; GDAL picks the
// driver from the bytes, so the mutations reach whatever raster drivers GDAL has.
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <stdexcept>
#include <string>

#include "core/error.h"
#include "fuzz/dem_checks.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;

namespace {

// A 5 x 4 float32 GeoTIFF, value 10 * row + col.
void write_geotiff(const std::filesystem::path& path, const double (&transform)[6], int epsg,
                   const char* unit) {
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 5, 4, 1, GDT_Float32, nullptr);
  if (ds == nullptr) throw std::runtime_error("GDALCreate failed: " + path.string());
  GDALSetGeoTransform(ds, const_cast<double*>(transform));
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  float v[20];
  for (int i = 0; i < 20; ++i) v[i] = float(10 * (i / 5) + i % 5);
  v[7] = -9999.0f;
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, -9999.0);
  GDALSetRasterUnitType(band, unit);
  if (GDALRasterIO(band, GF_Write, 0, 0, 5, 4, v, 5, 4, GDT_Float32, 0, 0) != CE_None) {
    throw std::runtime_error("GDALRasterIO failed: " + path.string());
  }
  GDALClose(ds);
}

std::vector<std::uint8_t> text(const std::string& s) { return {s.begin(), s.end()}; }

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {fuzz::bytes_written_by(".tif",
                                 [](const std::filesystem::path& p) {
                                   write_geotiff(p, {5.0, 0.5, 0.0, 55.0, 0.0, -0.25}, 4326, "m");
                                 }),
          fuzz::bytes_written_by(".tif",
                                 [](const std::filesystem::path& p) {
                                   write_geotiff(p, {500000, 1000, 0, 5600000, 0, -1000}, 32632, "ft");
                                 }),
          text("ncols 4\nnrows 3\nxllcorner 5.0\nyllcorner 50.0\ncellsize 0.5\n"
               "NODATA_value -9999\n1 2 3 4\n5 -9999 7 8\n9 10 11 12\n")};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool configured = [] {
    CPLSetConfigOption("GDAL_CACHEMAX", "64");  // MB: keep the block cache inside -rss_limit_mb
    CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml side files
    return true;
  }();
  (void)configured;
  try {
    fuzz::exercise_dem(*geo::open_gdal_dem(fuzz::input_file(data, size, ".dem")));
  } catch (const Error&) {
  }
  return 0;
}
