// SPDX-License-Identifier: Apache-2.0
#include "extract/geographic_conditions.h"

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

#include "core/error.h"
#include "geo/grid_projection.h"

namespace strielad {

namespace {

// One table per store (by id), kept while some extraction holds it; made by `make`
// (under the lock) when none is held.
template <class Make>
std::shared_ptr<const GeoLocation> cached(std::uint64_t store_id, Make make) {
  static std::mutex mutex;
  static std::map<std::uint64_t, std::weak_ptr<const GeoLocation>> cache;
  std::lock_guard lock(mutex);
  if (auto it = cache.find(store_id); it != cache.end()) {
    if (auto table = it->second.lock()) return table;
  }
  std::shared_ptr<const GeoLocation> table = make();
  cache[store_id] = table;
  return table;
}

}  // namespace

std::shared_ptr<const GeoLocation> GeoLocation::of(const format::Manifest& m) {
  if (!m.grid_mapping || m.grid_mapping->proj.empty()) {
    throw make_error(ErrorCode::kUnsupported, "the store's grid has no grid mapping to place it by");
  }
  return cached(m.store_id, [&] {
    auto table = std::make_shared<GeoLocation>();
    const geo::GridProjection projection(m.grid_mapping->proj);
    table->nx_ = m.x.size();
    table->lonlat_.resize(m.x.size() * m.y.size());
    for (std::size_t j = 0; j < m.y.size(); ++j) {
      for (std::size_t i = 0; i < m.x.size(); ++i) {
        table->lonlat_[j * m.x.size() + i] = projection.to_geographic(m.x.values[i], m.y.values[j]);
      }
    }
    return table;
  });
}

std::shared_ptr<const GeoLocation> GeoLocation::of(const Store& store) {
  const format::Manifest& m = store.manifest();
  if (!format::is_curvilinear(m)) return of(m);
  const auto coordinates = store.horizontal_coordinates();
  if (coordinates == nullptr || !coordinates->has_coordinates()) {
    throw make_error(ErrorCode::kCorrupt, "{}: a curvilinear store without its coordinates",
                     store.path().string());
  }
  return cached(m.store_id, [&] {
    auto table = std::make_shared<GeoLocation>();
    table->nx_ = coordinates->nx;
    table->lonlat_.resize(coordinates->lon.size());
    for (std::size_t k = 0; k < coordinates->lon.size(); ++k) {
      table->lonlat_[k] = {coordinates->lon[k], coordinates->lat[k]};
    }
    return table;
  });
}

std::vector<std::vector<double>> geographic_conditions(const GeographicBox& box,
                                                       const GeoLocation& geo,
                                                       const std::vector<std::size_t>& xi,
                                                       const std::vector<std::size_t>& yi) {
  constexpr double kRad = std::numbers::pi / 180.0;
  const std::size_t n = xi.size() * yi.size();
  std::vector<std::vector<double>> out;
  auto add = [&](auto value) {
    std::vector<double> v(n);
    std::size_t k = 0;
    for (std::size_t j : yi) {
      for (std::size_t i : xi) {
        const auto& ll = geo.at(i, j);
        // A sample without a position (outside the projection's domain) is outside.
        v[k++] = std::isfinite(ll[0]) && std::isfinite(ll[1]) ? value(ll[0], ll[1]) : -1.0;
      }
    }
    out.push_back(std::move(v));
  };
  if (box.lat) {
    const double lo = box.lat->lo, hi = box.lat->hi;
    if (lo > -90.0) add([lo](double, double lat) { return lat - lo; });
    if (hi < 90.0) add([hi](double, double lat) { return hi - lat; });
  }
  if (box.lon && box.lon->hi - box.lon->lo < 360.0) {
    const double lo = box.lon->lo, hi = box.lon->hi, width = hi - lo;
    if (width <= 180.0) {
      add([lo](double lon, double lat) { return std::cos(lat * kRad) * std::sin((lon - lo) * kRad); });
      add([hi](double lon, double lat) { return std::cos(lat * kRad) * std::sin((hi - lon) * kRad); });
    } else {
      const double centre = 0.5 * (lo + hi), limit = std::cos(0.5 * width * kRad);
      add([centre, limit](double lon, double) { return std::cos((lon - centre) * kRad) - limit; });
    }
  }
  return out;
}

}  // namespace strielad
