// SPDX-License-Identifier: Apache-2.0
#include "view/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strielad::view {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace

OrbitCamera::OrbitCamera(const lod::WorldBox& domain) : domain_(domain) { home(); }

void OrbitCamera::home() {
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

void OrbitCamera::pan(double right_fraction, double up_fraction) {
  const auto basis = lod::camera_basis(camera(1.0));
  const double height = 2 * distance_ * std::tan(22.5 * kRadPerDeg);
  target_ = add(target_, add(scale(basis.right, right_fraction * height),
                                       scale(basis.up, up_fraction * height)));
}

void OrbitCamera::zoom(double factor) {
  if (!std::isfinite(factor) || factor <= 0) return;
  const double size = std::max(domain_.radius(), 1e-3);
  distance_ = std::clamp(distance_ * factor, 0.01, 100 * size);
}

void OrbitCamera::fly(double forward_km, double right_km, double up_km) {
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
  if (!(ratio > 0) || !std::isfinite(ratio)) return;
  look_from({e[0], e[1], e[2] * ratio}, {target_[0], target_[1], target_[2] * ratio});
}

lod::Camera OrbitCamera::camera(double aspect, double fov_y_deg) const {
  return lod::look_at(eye(), target_, fov_y_deg, aspect, domain_);
}

}  // namespace strielad::view
