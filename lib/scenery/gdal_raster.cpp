// SPDX-License-Identifier: Apache-2.0
#include "scenery/gdal_raster.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace strielad::geo {
namespace {

// The most source pixels one read of the strided fallback takes (4 MB of floats).
constexpr std::size_t kFallbackPiecePixels = std::size_t(1) << 20;

void register_gdal() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// GDAL's last error message, or `fallback`.
std::string gdal_message(const char* fallback) {
  const char* m = CPLGetLastErrorMsg();
  return (m && *m) ? std::string(m) : std::string(fallback);
}

// Silences GDAL's stderr printing for the scope (errors are reported as values).
struct QuietGdal {
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
};

GDALDatasetH handle(void* p) { return static_cast<GDALDatasetH>(p); }

// What kind of CRS `srs` is, in words.
const char* crs_kind(OGRSpatialReferenceH srs) {
  if (OSRIsCompound(srs)) return "compound";
  if (OSRIsProjected(srs)) return "projected";
  if (OSRIsGeocentric(srs)) return "geocentric";
  if (OSRIsGeographic(srs)) return "geographic";
  if (OSRIsVertical(srs)) return "vertical";
  return "other";
}

// Refuses a CRS whose EPSG code (of the whole CRS, `node` nullptr, or of its GEOGCS)
// names a CRS of another kind: PROJ looks the code up when it builds a transformation,
// and a geographic CRS carrying a geocentric CRS's code (EPSG:4342, from a damaged
// GeoTIFF's keys) made it dereference null (SEGV in ObjectUsage::domains).
void check_authority_matches(OGRSpatialReferenceH srs, const char* node,
                             const std::filesystem::path& path) {
  const char* authority = OSRGetAuthorityName(srs, node);
  const char* code = OSRGetAuthorityCode(srs, node);
  if (!authority || !code || std::string_view(authority) != "EPSG") return;
  char* end = nullptr;
  const long epsg = std::strtol(code, &end, 10);
  if (end == code || *end != '\0' || epsg <= 0 || epsg > 2147483647L) {
    throw make_error(ErrorCode::kInvalidInput, "{}: the CRS's EPSG code '{}' is not a number",
                     path.string(), code);
  }
  OGRSpatialReferenceH own = OSRNewSpatialReference(nullptr);
  const bool known = OSRImportFromEPSG(own, static_cast<int>(epsg)) == OGRERR_NONE;
  const std::string actual = known ? crs_kind(own) : "";
  OSRDestroySpatialReference(own);
  std::string claimed = crs_kind(srs);
  if (node) {  // the geographic base of a projected CRS
    OGRSpatialReferenceH base = OSRCloneGeogCS(srs);
    claimed = crs_kind(base);
    OSRDestroySpatialReference(base);
  }
  if (known && claimed != actual) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the file's {} CRS carries the code EPSG:{}, which is a {} CRS; a CRS that "
                     "contradicts its own code is refused",
                     path.string(), claimed, epsg, actual);
  }
}

}  // namespace

GdalRaster::GdalRaster(const std::filesystem::path& path, const std::string& what) : path_(path) {
  register_gdal();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such {} file", path.string(), what);
  }
  QuietGdal quiet;
  dataset_ = GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (!dataset_) {
    throw make_error(ErrorCode::kInvalidInput, "{}: not a raster GDAL reads ({})", path.string(),
                     gdal_message("no driver recognises it"));
  }
  try {
    width_ = static_cast<std::size_t>(GDALGetRasterXSize(handle(dataset_)));
    height_ = static_cast<std::size_t>(GDALGetRasterYSize(handle(dataset_)));
    bands_ = GDALGetRasterCount(handle(dataset_));
    if (GDALDriverH d = GDALGetDatasetDriver(handle(dataset_))) driver_ = GDALGetDriverShortName(d);
    if (bands_ < 1 || width_ < 2 || height_ < 2) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: a {} needs at least one band of 2 x 2 samples ({} bands of {} x {})",
                       path.string(), what, bands_, width_, height_);
    }
    if (GDALGetGeoTransform(handle(dataset_), transform_.data()) != CE_None) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: no georeferencing (the {} has no geotransform; GDAL driver {})",
                       path.string(), what, driver_);
    }
    if (!GDALInvGeoTransform(transform_.data(), inverse_.data())) {
      throw make_error(ErrorCode::kInvalidInput, "{}: the geotransform is singular", path.string());
    }
    const char* wkt = GDALGetProjectionRef(handle(dataset_));
    if (!wkt || !*wkt) {
      // No CRS: taken as longitude/latitude when the extent fits the globe.
      const double x0 = transform_[0], y0 = transform_[3];
      const double x1 = x0 + transform_[1] * double(width_) + transform_[2] * double(height_);
      const double y1 = y0 + transform_[4] * double(width_) + transform_[5] * double(height_);
      if (std::min(x0, x1) < -180.0 || std::max(x0, x1) > 360.0 || std::min(y0, y1) < -90.5 ||
          std::max(y0, y1) > 90.5) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: no georeferencing: no CRS, and the geotransform's extent is not "
                         "longitude/latitude",
                         path.string());
      }
      crs_name_ = "none (taken as longitude/latitude)";
      return;
    }
    OGRSpatialReferenceH source = OSRNewSpatialReference(wkt);
    if (!source) {
      throw make_error(ErrorCode::kInvalidInput, "{}: the {}'s CRS cannot be read ({})",
                       path.string(), what, gdal_message("malformed WKT"));
    }
    try {
      check_authority_matches(source, nullptr, path);
      if (OSRIsProjected(source)) check_authority_matches(source, "GEOGCS", path);
    } catch (...) {
      OSRDestroySpatialReference(source);
      throw;
    }
    OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr);
    OSRSetWellKnownGeogCS(wgs84, "WGS84");
    OSRSetAxisMappingStrategy(source, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
    if (const char* name = OSRGetName(source)) crs_name_ = name;
    to_wgs84_ = OCTNewCoordinateTransformation(source, wgs84);
    from_wgs84_ = OCTNewCoordinateTransformation(wgs84, source);
    OSRDestroySpatialReference(source);
    OSRDestroySpatialReference(wgs84);
    if (!to_wgs84_ || !from_wgs84_) {
      throw make_error(ErrorCode::kUnsupported, "{}: CRS '{}' cannot be transformed to WGS84 ({})",
                       path.string(), crs_name_, gdal_message("no transformation"));
    }
  } catch (...) {
    if (to_wgs84_) OCTDestroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(to_wgs84_));
    if (from_wgs84_) OCTDestroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(from_wgs84_));
    GDALClose(handle(dataset_));
    throw;
  }
}

GdalRaster::~GdalRaster() {
  if (to_wgs84_) OCTDestroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(to_wgs84_));
  if (from_wgs84_) OCTDestroyCoordinateTransformation(static_cast<OGRCoordinateTransformationH>(from_wgs84_));
  if (dataset_) GDALClose(handle(dataset_));
}

void GdalRaster::to_lonlat(std::span<const double> cols, std::span<const double> rows,
                           std::span<LonLat> out) const {
  const std::size_t n = out.size();
  std::vector<double> x(n), y(n);
  const auto& t = transform_;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = cols[i] + 0.5, r = rows[i] + 0.5;
    x[i] = t[0] + c * t[1] + r * t[2];
    y[i] = t[3] + c * t[4] + r * t[5];
  }
  if (to_wgs84_ && n > 0) {
    std::lock_guard lock(mutex_);
    std::vector<int> ok(n, 0);
    OCTTransformEx(static_cast<OGRCoordinateTransformationH>(to_wgs84_), static_cast<int>(n),
                   x.data(), y.data(), nullptr, ok.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (!ok[i]) x[i] = y[i] = NAN;
    }
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = {x[i], y[i]};
}

void GdalRaster::to_pixel(std::span<const LonLat> lonlat, std::span<double> cols,
                          std::span<double> rows) const {
  const std::size_t n = lonlat.size();
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = lonlat[i].lon;
    y[i] = lonlat[i].lat;
  }
  if (from_wgs84_ && n > 0) {
    std::lock_guard lock(mutex_);
    std::vector<int> ok(n, 0);
    OCTTransformEx(static_cast<OGRCoordinateTransformationH>(from_wgs84_), static_cast<int>(n),
                   x.data(), y.data(), nullptr, ok.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (!ok[i]) x[i] = y[i] = NAN;
    }
  }
  const auto& v = inverse_;
  for (std::size_t i = 0; i < n; ++i) {
    cols[i] = v[0] + x[i] * v[1] + y[i] * v[2] - 0.5;
    rows[i] = v[3] + x[i] * v[4] + y[i] * v[5] - 0.5;
  }
}

std::vector<float> GdalRaster::read_band(int band, std::size_t col0, std::size_t row0,
                                         std::size_t cols, std::size_t rows,
                                         std::size_t stride) const {
  std::vector<float> out(cols * rows, NAN);
  std::lock_guard lock(mutex_);
  QuietGdal quiet;
  GDALRasterBandH b = GDALGetRasterBand(handle(dataset_), band);
  if (!b) throw make_error(ErrorCode::kIo, "{}: no band {}", path_.string(), band);
  const int s = static_cast<int>(stride);
  // Nearest-neighbour downsampling takes source pixel floor(off + (i + 0.5) * size / n):
  // a window of cols * stride pixels starting stride / 2 before col0 picks exactly
  // col0 + i * stride. The floating-point window may reach past the raster's edge by
  // less than a stride; no pixel outside it is read.
  GDALRasterIOExtraArg extra;
  INIT_RASTERIO_EXTRA_ARG(extra);
  extra.eResampleAlg = GRIORA_NearestNeighbour;
  CPLErr err = CE_None;
  if (stride == 1) {
    err = GDALRasterIOEx(b, GF_Read, int(col0), int(row0), int(cols), int(rows), out.data(),
                         int(cols), int(rows), GDT_Float32, 0, 0, &extra);
  } else {
    extra.bFloatingPointWindowValidity = TRUE;
    extra.dfXOff = double(col0) - double(s / 2);
    extra.dfYOff = double(row0) - double(s / 2);
    extra.dfXSize = double(cols) * s;
    extra.dfYSize = double(rows) * s;
    const int x0 = int(col0), y0 = int(row0);
    const int xs = int((cols - 1) * stride + 1), ys = int((rows - 1) * stride + 1);
    err = GDALRasterIOEx(b, GF_Read, x0, y0, xs, ys, out.data(), int(cols), int(rows),
                         GDT_Float32, 0, 0, &extra);
    if (err != CE_None) {
      // Row by row at full resolution, every stride-th sample, in pieces of at most
      // kFallbackPiecePixels source pixels: a raster that declares a row of 2^30 pixels
      // must not make this read allocate the whole row.
      CPLErrorReset();
      const std::size_t per_piece = (kFallbackPiecePixels - 1) / stride + 1;
      std::vector<float> piece(std::min<std::size_t>(std::size_t(xs), kFallbackPiecePixels));
      err = CE_None;
      for (std::size_t j = 0; j < rows && err == CE_None; ++j) {
        for (std::size_t i0 = 0; i0 < cols && err == CE_None; i0 += per_piece) {
          const std::size_t n = std::min(per_piece, cols - i0);
          const int len = int((n - 1) * stride + 1);
          err = GDALRasterIO(b, GF_Read, int(col0 + i0 * stride), int(row0 + j * stride), len, 1,
                             piece.data(), len, 1, GDT_Float32, 0, 0);
          for (std::size_t i = 0; i < n; ++i) out[j * cols + i0 + i] = piece[i * stride];
        }
      }
    }
  }
  if (err != CE_None) {
    throw make_error(ErrorCode::kIo, "{}: reading band {}: {}", path_.string(), band,
                     gdal_message("read failed"));
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(b, &has_nodata);
  if (has_nodata) {
    const float nd = static_cast<float>(nodata);
    for (auto& v : out) {
      if (v == nd || (std::isnan(nodata) && std::isnan(v))) v = NAN;
    }
  }
  return out;
}

double GdalRaster::band_scale(int band) const {
  std::lock_guard lock(mutex_);
  int ok = 0;
  const double s = GDALGetRasterScale(GDALGetRasterBand(handle(dataset_), band), &ok);
  return ok ? s : 1.0;
}
double GdalRaster::band_offset(int band) const {
  std::lock_guard lock(mutex_);
  int ok = 0;
  const double o = GDALGetRasterOffset(GDALGetRasterBand(handle(dataset_), band), &ok);
  return ok ? o : 0.0;
}
std::string GdalRaster::band_unit(int band) const {
  std::lock_guard lock(mutex_);
  const char* u = GDALGetRasterUnitType(GDALGetRasterBand(handle(dataset_), band));
  return u ? u : "";
}

}  // namespace strielad::geo
