// SPDX-License-Identifier: Apache-2.0
#include "view/model_surface_dem.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace strielad::view {
namespace {

// The axis value at fractional index `f`, linear between samples and beyond the ends.
double axis_at(const std::vector<double>& v, double f) {
  if (v.size() < 2) return v.front();
  const double c = std::clamp(std::floor(f), 0.0, double(v.size() - 2));
  const auto i = static_cast<std::size_t>(c);
  return v[i] + (f - c) * (v[i + 1] - v[i]);
}

}  // namespace

ModelSurfaceDem::ModelSurfaceDem(const format::Manifest& manifest, const lod::WorldFrame& frame,
                                 std::shared_ptr<const format::HorizontalCoordinates> coordinates,
                                 std::string store_name)
    : frame_(frame),
      coordinates_(std::move(coordinates)),
      x_(manifest.x.values),
      y_(manifest.y.values),
      z0_(manifest.z.values.front()),
      nx_(manifest.x.size()),
      ny_(manifest.y.size()),
      name_(std::move(store_name)) {
  if (!frame_.on_earth()) {
    throw make_error(ErrorCode::kUnsupported, "{}: the model's surface cannot be placed: {}",
                     name_, frame_.no_earth_reason());
  }
  if (!coordinates_ || !coordinates_->surface_m || coordinates_->surface_m->size() != nx_ * ny_) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: the store's GEOMETRY has no surface of {} x {} samples", name_, nx_,
                     ny_);
  }
}

void ModelSurfaceDem::georeference(std::span<const double> cols, std::span<const double> rows,
                                   std::span<geo::LonLat> out) const {
  for (std::size_t k = 0; k < out.size(); ++k) {
    // Through the world and back: on the plane or on the globe, for every horizontal map.
    const Vec3 world = frame_.to_world({axis_at(x_, cols[k]), axis_at(y_, rows[k]), z0_});
    const Vec3 g = frame_.geographic_of(world);
    out[k] = geo::LonLat{g[0], g[1]};
  }
}

std::vector<float> ModelSurfaceDem::read(const geo::DemWindow& w) const {
  geo::check_dem_window(w, nx_, ny_, describe());
  const std::vector<double>& s = *coordinates_->surface_m;
  std::vector<float> out(w.cols * w.rows);
  for (std::size_t j = 0; j < w.rows; ++j) {
    for (std::size_t i = 0; i < w.cols; ++i) {
      out[j * w.cols + i] =
          static_cast<float>(s[(w.row0 + j * w.stride) * nx_ + w.col0 + i * w.stride]);
    }
  }
  return out;
}

std::string ModelSurfaceDem::describe() const {
  return fmt::format("{}: the model's surface", name_);
}

std::string ModelSurfaceDem::georeferencing() const { return frame_.describe_horizontal(); }

}  // namespace strielad::view
