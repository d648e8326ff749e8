// SPDX-License-Identifier: Apache-2.0
#include "view/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lod/wgs84_globe.h"

namespace strielad::view {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace

OrbitCamera::OrbitCamera(const lod::WorldBox& domain) : domain_(domain) { home(); }

void OrbitCamera::set_globe(double lon_deg, double lat_deg) {
  globe_ = true;
  home_lon_deg_ = lon_deg;
  home_lat_deg_ = lat_deg;
  home();
}

void OrbitCamera::home() {
  if (globe_) {
    // The eye over (lon, lat): back = (cos lat cos lon, cos lat sin lon, sin lat).
    const double lon = home_lon_deg_ * kRadPerDeg;
    target_ = {0, 0, 0};
    pitch_deg_ = std::clamp(home_lat_deg_, -89.0, 89.0);
    yaw_deg_ = std::atan2(-std::cos(lon), -std::sin(lon)) / kRadPerDeg;
    distance_ = 1.15 * lod::kWgs84SemiMajorKm / std::sin(22.5 * kRadPerDeg);
    return;
  }
  target_ = domain_.center();
  distance_ = std::max(domain_.radius(), 1e-3) / std::sin(22.5 * kRadPerDeg);
  yaw_deg_ = 0;
  pitch_deg_ = 50;
}

Vec3 OrbitCamera::eye() const {
  const double yaw = yaw_deg_ * kRadPerDeg, pitch = pitch_deg_ * kRadPerDeg;
  const Vec3 back{-std::sin(yaw) * std::cos(pitch), -std::cos(yaw) * std::cos(pitch),
                       std::sin(pitch)};
  return add(target_, scale(back, distance_));
}

void OrbitCamera::orbit(double yaw_deg, double pitch_deg) {
  yaw_deg_ = std::fmod(yaw_deg_ + yaw_deg, 360.0);
  pitch_deg_ = std::clamp(pitch_deg_ + pitch_deg, -89.0, 89.0);
}

namespace {

// Degrees of the Earth's centre that the view's height spans on the ground below an eye
// `distance` km from the centre.
double ground_view_degrees(double distance) {
  const double altitude = std::max(distance - lod::kWgs84SemiMajorKm, 1.0);
  return 2 * altitude * std::tan(22.5 * kRadPerDeg) / lod::kWgs84SemiMajorKm / kRadPerDeg;
}

}  // namespace

double OrbitCamera::drag_scale() const {
  if (!globe_) return 1.0;
  const double home = 1.15 / std::sin(22.5 * kRadPerDeg) - 1.0;  // in equatorial radii
  return std::clamp((distance_ / lod::kWgs84SemiMajorKm - 1.0) / home, 1e-3, 1.0);
}

void OrbitCamera::zoom_at(double factor, double right_fraction, double up_fraction) {
  if (globe_ && std::isfinite(factor) && factor > 0 && factor < 1) {
    // The eye's sub-point moves east as yaw falls and north as pitch grows; towards the
    // cursor's ground by the share of the view that the zoom removes.
    const double move = (1.0 - factor) * ground_view_degrees(distance_);
    orbit(-right_fraction * move, up_fraction * move);
  }
  zoom(factor);
}

void OrbitCamera::pan(double right_fraction, double up_fraction) {
  if (globe_) {
    const double view = ground_view_degrees(distance_);
    orbit(-right_fraction * view, up_fraction * view);
    return;
  }
  const auto basis = lod::camera_basis(camera(1.0));
  const double height = 2 * distance_ * std::tan(22.5 * kRadPerDeg);
  target_ = add(target_, add(scale(basis.right, right_fraction * height),
                                       scale(basis.up, up_fraction * height)));
}

void OrbitCamera::zoom(double factor) {
  if (!std::isfinite(factor) || factor <= 0) return;
  if (globe_) {
    // Above the ground (the equatorial radius and 10 km more), at most 20 radii away.
    const double a = lod::kWgs84SemiMajorKm;
    const double altitude = std::clamp((distance_ - a) * factor, 10.0, 19 * a);
    distance_ = a + altitude;
    return;
  }
  const double size = std::max(domain_.radius(), 1e-3);
  distance_ = std::clamp(distance_ * factor, 0.01, 100 * size);
}

void OrbitCamera::fly(double forward_km, double right_km, double up_km) {
  if (globe_) {
    // North and east over the ground (scaled to the altitude as the keys' speed is to the
    // distance), up and down by the altitude's share.
    const double a = lod::kWgs84SemiMajorKm;
    const double share = std::clamp((distance_ - a) / distance_, 1e-4, 1.0);
    orbit(-right_km * share / a / kRadPerDeg, forward_km * share / a / kRadPerDeg);
    if (up_km != 0) zoom(1.0 + up_km / distance_);
    return;
  }
  const double yaw = yaw_deg_ * kRadPerDeg;
  const Vec3 forward{std::sin(yaw), std::cos(yaw), 0}, right{std::cos(yaw), -std::sin(yaw), 0};
  target_ = add(target_, add(scale(forward, forward_km),
                                       add(scale(right, right_km), Vec3{0, 0, up_km})));
}

void OrbitCamera::look_from(const Vec3& eye, const Vec3& target) {
  const Vec3 back = sub(eye, target);
  const double d = length(back);
  if (!(d > 0) || !std::isfinite(d)) return;
  target_ = target;
  distance_ = d;
  pitch_deg_ = std::clamp(std::asin(std::clamp(back[2] / d, -1.0, 1.0)) / kRadPerDeg, -89.0, 89.0);
  yaw_deg_ = std::atan2(-back[0], -back[1]) / kRadPerDeg;
}

void OrbitCamera::rescale_vertical(double ratio, const lod::WorldBox& new_domain) {
  const Vec3 e = eye();
  domain_ = new_domain;
  if (globe_ || !(ratio > 0) || !std::isfinite(ratio)) return;
  look_from({e[0], e[1], e[2] * ratio}, {target_[0], target_[1], target_[2] * ratio});
}

lod::Camera OrbitCamera::camera(double aspect, double fov_y_deg) const {
  const double a = lod::kWgs84SemiMajorKm;
  const Vec3 e = eye();
  const double r = length(e);
  if (globe_ && r < 2 * a && r > 0) {
    // Tilted from the nadir towards the view's up (north of the eye's meridian plane).
    const double tilt = 70.0 * kRadPerDeg * std::clamp((2 * a - r) / a, 0.0, 1.0);
    const Vec3 radial = scale(e, 1.0 / r);
    Vec3 up = sub(Vec3{0, 0, 1}, scale(radial, radial[2]));
    const double up_length = length(up);
    up = up_length > 1e-9 ? scale(up, 1.0 / up_length) : Vec3{1, 0, 0};
    const Vec3 look = add(scale(radial, -std::cos(tilt)), scale(up, std::sin(tilt)));
    return lod::look_at(e, add(e, scale(look, r - a + 1.0)), fov_y_deg, aspect, domain_);
  }
  return lod::look_at(e, target_, fov_y_deg, aspect, domain_);
}

}  // namespace strielad::view
