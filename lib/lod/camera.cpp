// SPDX-License-Identifier: Apache-2.0
#include "lod/camera.h"
#include "lod/frustum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace strielad::lod {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// sin of the smallest angle allowed between up and the view direction (~0.06 degrees).
constexpr double kMinUpSine = 1e-3;

void check_finite(const Vec3& v, const char* name) {
  if (!all_finite(v)) {
    throw make_error(ErrorCode::kInvalidArgument, "camera {} ({}, {}, {}) is not finite", name,
                     v[0], v[1], v[2]);
  }
}

}  // namespace

void validate_camera(const Camera& c) {
  check_finite(c.eye, "eye");
  check_finite(c.target, "target");
  check_finite(c.up, "up");
  const Vec3 view = sub(c.target, c.eye);
  const double view_length = length(view);
  if (!(view_length > 0) || !std::isfinite(view_length)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "camera eye and target must be distinct finite points");
  }
  const double up_length = length(c.up);
  if (!(up_length > 0) || !std::isfinite(up_length) ||
      length(cross(scale(view, 1.0 / view_length), scale(c.up, 1.0 / up_length))) < kMinUpSine) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "camera up ({}, {}, {}) is zero or parallel to the view direction",
                     c.up[0], c.up[1], c.up[2]);
  }
  if (!(c.fov_y_deg > 0 && c.fov_y_deg < 180)) {
    throw make_error(ErrorCode::kInvalidArgument, "camera fov_y_deg {} must be in (0, 180)",
                     c.fov_y_deg);
  }
  if (!(c.aspect > 0) || !std::isfinite(c.aspect)) {
    throw make_error(ErrorCode::kInvalidArgument, "camera aspect {} must be finite and > 0",
                     c.aspect);
  }
  if (!(c.near_km > 0) || !(c.far_km > c.near_km) || !std::isfinite(c.far_km)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "camera near {} and far {} must be finite with 0 < near < far", c.near_km,
                     c.far_km);
  }
}

CameraBasis camera_basis(const Camera& c) {
  CameraBasis b;
  b.forward = normalize(sub(c.target, c.eye));
  b.right = normalize(cross(b.forward, c.up));
  b.up = cross(b.right, b.forward);
  return b;
}

Mat4 view_matrix(const Camera& c) {
  const CameraBasis b = camera_basis(c);
  auto f = [](double v) { return static_cast<float>(v); };
  // Rows: right, up, -forward; translation -R * eye.
  return Mat4{f(b.right[0]), f(b.up[0]), f(-b.forward[0]), 0,
              f(b.right[1]), f(b.up[1]), f(-b.forward[1]), 0,
              f(b.right[2]), f(b.up[2]), f(-b.forward[2]), 0,
              f(-dot(b.right, c.eye)), f(-dot(b.up, c.eye)), f(dot(b.forward, c.eye)), 1};
}

Mat4 projection_matrix(const Camera& c) {
  const double t = 1.0 / std::tan(0.5 * c.fov_y_deg * kDegree);
  const double n = c.near_km, fa = c.far_km;
  Mat4 m{};
  m[0] = static_cast<float>(t / c.aspect);
  m[5] = static_cast<float>(t);
  m[10] = static_cast<float>(-(fa + n) / (fa - n));
  m[11] = -1.0f;
  m[14] = static_cast<float>(-2.0 * fa * n / (fa - n));
  return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 out{};
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      float s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[col * 4 + k];
      out[col * 4 + row] = s;
    }
  }
  return out;
}

std::array<double, 4> to_clip(const Mat4& m, const Vec3& p) {
  std::array<double, 4> out{};
  for (int row = 0; row < 4; ++row) {
    out[row] = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
  }
  return out;
}

Vec3 default_up(const Vec3& eye, const Vec3& target) {
  const Vec3 forward = normalize(sub(target, eye));
  const Vec3 z{0, 0, 1};
  return length(cross(forward, z)) < 1e-2 ? Vec3{0, 1, 0} : z;
}

Camera look_at(const Vec3& eye, const Vec3& target, double fov_y_deg, double aspect,
               const WorldBox& scene) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = default_up(eye, target);
  c.fov_y_deg = fov_y_deg;
  c.aspect = aspect;
  double farthest = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? scene.hi[0] : scene.lo[0], (i & 2) ? scene.hi[1] : scene.lo[1],
                      (i & 4) ? scene.hi[2] : scene.lo[2]};
    farthest = std::max(farthest, length(sub(corner, eye)));
  }
  c.far_km = std::max(farthest * 1.01, 1.0);
  c.near_km = std::max(c.far_km * 1e-4, 1e-3);
  validate_camera(c);
  return c;
}

bool Frustum::contains(const Vec3& p) const {
  for (const Plane& plane : planes) {
    if (plane.distance(p) < 0) return false;
  }
  return true;
}

Frustum view_frustum(const Camera& c) {
  const CameraBasis b = camera_basis(c);
  const double half_h = std::tan(0.5 * c.fov_y_deg * std::numbers::pi / 180.0);
  const double half_w = half_h * c.aspect;
  // A side plane through the eye containing the edge direction forward +- half * side;
  // its inward normal is side_dir * (+-1) + half * forward.
  auto through_eye = [&](const Vec3& normal) {
    const Vec3 n = normalize(normal);
    return Plane{n, -dot(n, c.eye)};
  };
  Frustum f;
  f.planes[0] = through_eye(add(b.right, scale(b.forward, half_w)));        // left
  f.planes[1] = through_eye(sub(scale(b.forward, half_w), b.right));        // right
  f.planes[2] = through_eye(add(b.up, scale(b.forward, half_h)));           // bottom
  f.planes[3] = through_eye(sub(scale(b.forward, half_h), b.up));           // top
  f.planes[4] = Plane{b.forward, -(dot(b.forward, c.eye) + c.near_km)};    // near
  f.planes[5] = Plane{scale(b.forward, -1.0), dot(b.forward, c.eye) + c.far_km};  // far
  return f;
}

}  // namespace strielad::lod
