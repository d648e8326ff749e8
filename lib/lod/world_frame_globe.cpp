// SPDX-License-Identifier: Apache-2.0
// The globe shape of the world frame (lod/world_frame.h): the plane's positions carried to
// WGS84 ECEF kilometres through their true longitude and latitude.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/wgs84_globe.h"
#include "lod/world_frame.h"

namespace strielad::lod {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Vec3 unit(const Vec3& v) {
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return len > 0 ? Vec3{v[0] / len, v[1] / len, v[2] / len} : Vec3{0.0, 0.0, 1.0};
}

double angle_between(const Vec3& a, const Vec3& b) {
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const Vec3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), d);
}

}  // namespace

void WorldFrame::choose_shape(FrameShape shape) {
  plane_domain_ = domain_;
  if (shape == FrameShape::kPlane) return;
  if (!on_earth()) {
    if (shape == FrameShape::kAuto) return;
    throw make_error(ErrorCode::kUnsupported, "the globe needs a grid on the Earth: {}",
                     no_earth_reason_);
  }
  if (shape == FrameShape::kAuto) {
    const GeographicBounds b = geographic_bounds();
    if (b.lon_hi - b.lon_lo <= kGlobeMinExtentDeg && b.lat_hi - b.lat_lo <= kGlobeMinExtentDeg) {
      return;
    }
  }
  globe_ = true;
  domain_ = globe_index_box(IndexBox{{0, 0, 0}, {dims_.x - 1, dims_.y - 1, dims_.z - 1}});
}

void WorldFrame::check_plane(const char* what) const {
  if (globe_) {
    throw make_error(ErrorCode::kUnsupported,
                     "{} gives plane x/y, and this frame is the globe (ECEF km): place "
                     "positions with place_geographic / geographic_of",
                     what);
  }
}

Vec3 WorldFrame::plane_to_globe(const Vec3& plane) const {
  const auto g = geographic_of_plane(plane[0], plane[1]);
  return geodetic_to_ecef_km(g[0], g[1], plane[2]);
}

Vec3 WorldFrame::globe_to_plane(const Vec3& world) const {
  const Geodetic g = ecef_km_to_geodetic(world);
  const auto xy = plane_of_geographic(g.lon_deg, g.lat_deg);
  return {xy[0], xy[1], g.height_km};
}

Vec3 WorldFrame::globe_normal(const Vec3& plane, const Vec3& n) const {
  // The plane-to-globe Jacobian is [east a1 | north a2 | up] (orthonormal columns scaled:
  // a1, a2 km of the globe per km of the plane east and north); its inverse transpose is
  // [east / a1 | north / a2 | up].
  const auto g = geographic_of_plane(plane[0], plane[1]);
  const LocalAxes axes = local_axes(g[0], g[1]);
  const double h = plane[2];
  const double a1 = std::max((prime_vertical_radius_km(g[1]) + h) * std::cos(g[1] * kDeg) * kDeg /
                                 km_per_lon_,
                             1e-9);
  const double a2 = (meridional_radius_km(g[1]) + h) * kDeg / kKmPerDegree;
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    out[c] = axes.east[c] * n[0] / a1 + axes.north[c] * n[1] / a2 + axes.up[c] * n[2];
  }
  return unit(out);
}

Vec3 WorldFrame::up_at(const Vec3& world) const {
  if (!globe_) return {0.0, 0.0, 1.0};
  const Geodetic g = ecef_km_to_geodetic(world);
  return local_axes(g.lon_deg, g.lat_deg).up;
}

Vec3 WorldFrame::place_geographic(double lon, double lat, double world_height) const {
  check_on_earth();
  if (globe_) return geodetic_to_ecef_km(lon, lat, world_height);
  const auto xy = plane_of_geographic(lon, lat);
  return {xy[0], xy[1], world_height};
}

Vec3 WorldFrame::geographic_of(const Vec3& world) const {
  check_on_earth();
  if (!globe_) {
    const auto g = geographic_of_plane(world[0], world[1]);
    return {g[0], g[1], world[2]};
  }
  const Geodetic g = ecef_km_to_geodetic(world);
  return {lon0_ + std::remainder(g.lon_deg - lon0_, 360.0), g.lat_deg, g.height_km};
}

WorldBox WorldFrame::globe_index_box(const IndexBox& box) const {
  const double za = z_samples_[box.lo[2]], zb = z_samples_[box.hi[2]];
  const double z0 = std::min(za, zb), z1 = std::max(za, zb);
  const auto lonlat = [this](std::size_t i, std::size_t j) {
    const auto xy = sample_world_xy(i, j);
    return geographic_of_plane(xy[0], xy[1]);
  };
  const auto mid = lonlat((box.lo[0] + box.hi[0]) / 2, (box.lo[1] + box.hi[1]) / 2);
  const Vec3 centre = unit(geodetic_to_ecef_km(mid[0], mid[1], 0.0));
  WorldBox b{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  double widest = 0, step = 0;
  Vec3 previous{};
  bool has_previous = false;
  const auto take = [&](std::size_t i, std::size_t j) {
    const auto g = lonlat(i, j);
    for (const double h : {z0, z1}) {
      const Vec3 p = geodetic_to_ecef_km(g[0], g[1], h);
      for (int c = 0; c < 3; ++c) {
        b.lo[c] = std::min(b.lo[c], p[c]);
        b.hi[c] = std::max(b.hi[c], p[c]);
      }
    }
    const Vec3 d = unit(geodetic_to_ecef_km(g[0], g[1], 0.0));
    widest = std::max(widest, angle_between(centre, d));
    if (has_previous) step = std::max(step, angle_between(previous, d));
    previous = d;
    has_previous = true;
  };
  // The boundary walked round, so that neighbours follow each other.
  for (std::size_t i = box.lo[0]; i <= box.hi[0]; ++i) take(i, box.lo[1]);
  for (std::size_t j = box.lo[1]; j <= box.hi[1]; ++j) take(box.hi[0], j);
  for (std::size_t i = box.hi[0] + 1; i-- > box.lo[0];) take(i, box.hi[1]);
  for (std::size_t j = box.hi[1] + 1; j-- > box.lo[1];) take(box.lo[0], j);
  const double alpha = std::min(widest + step + 0.2 * kDeg, std::numbers::pi);
  const double r_top = kWgs84SemiMajorKm + std::max(z1, 0.0);
  const double pad = 1.01 * (r_top * (1.0 - std::cos(alpha)) +
                             (kWgs84SemiMajorKm - kWgs84SemiMinorKm) * alpha) +
                     1e-9 * r_top;
  for (int c = 0; c < 3; ++c) {
    b.lo[c] = std::max(b.lo[c] - pad, -r_top);
    b.hi[c] = std::min(b.hi[c] + pad, r_top);
  }
  return b;
}

}  // namespace strielad::lod
