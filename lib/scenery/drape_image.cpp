// SPDX-License-Identifier: Apache-2.0
#include "scenery/drape_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scenery/gdal_raster.h"

namespace strielad::geo {

DrapeImage::DrapeImage(const std::filesystem::path& path)
    : raster_(std::make_unique<GdalRaster>(path, "drape image")) {}

DrapeImage::~DrapeImage() = default;

std::string DrapeImage::describe() const {
  return fmt::format("{} (GDAL {}, {} x {}, {} band{})", raster_->path().string(),
                     raster_->driver(), raster_->width(), raster_->height(), raster_->bands(),
                     raster_->bands() == 1 ? "" : "s");
}

DrapePatch DrapeImage::read(std::span<const LonLat> lonlat, std::span<float> u,
                            std::span<float> v, int max_size) const {
  const std::size_t n = lonlat.size();
  std::vector<double> cols(n), rows(n);
  raster_->to_pixel(lonlat, cols, rows);
  double c0 = INFINITY, c1 = -INFINITY, r0 = INFINITY, r1 = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(cols[i]) || !std::isfinite(rows[i])) continue;
    c0 = std::min(c0, cols[i]);
    c1 = std::max(c1, cols[i]);
    r0 = std::min(r0, rows[i]);
    r1 = std::max(r1, rows[i]);
  }
  DrapePatch patch;
  const double w = double(raster_->width()), h = double(raster_->height());
  std::fill(u.begin(), u.end(), -1.0f);
  std::fill(v.begin(), v.end(), -1.0f);
  if (!(c1 >= -0.5 && c0 <= w - 0.5 && r1 >= -0.5 && r0 <= h - 0.5)) return patch;
  const auto first_c = static_cast<std::size_t>(std::clamp(std::floor(c0), 0.0, w - 1));
  const auto last_c = static_cast<std::size_t>(std::clamp(std::ceil(c1), 0.0, w - 1));
  const auto first_r = static_cast<std::size_t>(std::clamp(std::floor(r0), 0.0, h - 1));
  const auto last_r = static_cast<std::size_t>(std::clamp(std::ceil(r1), 0.0, h - 1));
  const std::size_t span = std::max(last_c - first_c, last_r - first_r) + 1;
  const std::size_t cap = static_cast<std::size_t>(std::max(max_size, 2));
  const std::size_t stride = std::max<std::size_t>(1, (span + cap - 1) / cap);
  const std::size_t pc = (last_c - first_c) / stride + 1, pr = (last_r - first_r) / stride + 1;
  patch.width = static_cast<int>(pc);
  patch.height = static_cast<int>(pr);
  patch.rgba.assign(pc * pr * 4, 255);
  const int bands = raster_->bands() >= 3 ? 3 : 1;
  for (int b = 0; b < bands; ++b) {
    const auto values = raster_->read_band(b + 1, first_c, first_r, pc, pr, stride);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const float x = std::isnan(values[i]) ? 0.0f : std::clamp(values[i], 0.0f, 255.0f);
      const auto byte = static_cast<std::uint8_t>(std::lround(x));
      if (bands == 1) {
        patch.rgba[i * 4] = patch.rgba[i * 4 + 1] = patch.rgba[i * 4 + 2] = byte;
      } else {
        patch.rgba[i * 4 + b] = byte;
      }
    }
  }
  // Texel j covers pixels around first + j * stride; vertices off the image stay at -1.
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(cols[i]) || cols[i] < -0.5 || cols[i] > w - 0.5 || rows[i] < -0.5 ||
        rows[i] > h - 0.5) {
      continue;
    }
    u[i] = static_cast<float>(((cols[i] - double(first_c)) / double(stride) + 0.5) / double(pc));
    v[i] = static_cast<float>(((rows[i] - double(first_r)) / double(stride) + 0.5) / double(pr));
  }
  return patch;
}

}  // namespace strielad::geo
