// SPDX-License-Identifier: Apache-2.0
#include "lod/frustum.h"

#include <cmath>
#include <numbers>

namespace strielad::lod {

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
