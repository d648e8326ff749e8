// SPDX-License-Identifier: Apache-2.0
// The GDAL DEM reader (scenery/dem_source.h): band 1 of any raster GDAL reads.
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "core/error.h"
#include "scenery/dem_source.h"
#include "scenery/gdal_raster.h"

namespace strielad::geo {
namespace {

class GdalDem final : public DemSource {
 public:
  explicit GdalDem(const std::filesystem::path& path) : raster_(path, "DEM") {
    std::string unit = raster_.band_unit(1);
    for (auto& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (unit == "km") {
      metres_per_unit_ = 1000.0;
    } else if (unit == "ft" || unit == "foot" || unit == "feet" || unit == "us-ft") {
      metres_per_unit_ = 0.3048;
    } else if (!unit.empty() && unit != "m" && unit != "metre" && unit != "meter" &&
               unit != "metres" && unit != "meters") {
      throw make_error(ErrorCode::kInvalidInput, "{}: band 1's unit '{}' is not a height (m, km, ft)",
                       describe(), unit);
    }
    scale_ = raster_.band_scale(1);
    offset_ = raster_.band_offset(1);
  }

  std::size_t width() const override { return raster_.width(); }
  std::size_t height() const override { return raster_.height(); }
  void georeference(std::span<const double> cols, std::span<const double> rows,
                    std::span<LonLat> out) const override {
    raster_.to_lonlat(cols, rows, out);
  }
  std::vector<float> read(const DemWindow& w) const override {
    check_dem_window(w, width(), height(), describe());
    auto v = raster_.read_band(1, w.col0, w.row0, w.cols, w.rows, w.stride);
    for (auto& x : v) x = static_cast<float>((x * scale_ + offset_) * metres_per_unit_);
    return v;
  }
  std::string describe() const override {
    return fmt::format("{} (GDAL {})", raster_.path().string(), raster_.driver());
  }
  std::string georeferencing() const override { return "CRS " + raster_.crs_name(); }

 private:
  GdalRaster raster_;
  double metres_per_unit_ = 1.0, scale_ = 1.0, offset_ = 0.0;
};

}  // namespace

std::unique_ptr<DemSource> open_gdal_dem(const std::filesystem::path& path) {
  return std::make_unique<GdalDem>(path);
}

}  // namespace strielad::geo
