// SPDX-License-Identifier: Apache-2.0
// The view frustum of a camera as six planes in the world frame, built from the camera's
// basis in double precision (not extracted from the float matrices), and the box test
// the level-of-detail cut culls by.
#pragma once

#include <array>

#include "lod/camera.h"
#include "lod/geometry.h"

namespace strielad::lod {

// The half-space n . p + offset >= 0 (n is unit length, pointing into the frustum).
struct Plane {
  Vec3 normal{};
  double offset = 0;
  double distance(const Vec3& p) const { return dot(normal, p) + offset; }
};

struct Frustum {
  // left, right, bottom, top, near, far
  std::array<Plane, 6> planes{};

  // Whether p lies inside or on every plane.
  bool contains(const Vec3& p) const;

  // False only when the box lies wholly outside one plane (its corner farthest along
  // the plane's normal is outside). Conservative: a box that meets the frustum is never
  // reported outside; a box near a frustum edge or corner may be kept though it misses.
  bool may_intersect(const WorldBox& box) const {
    for (const Plane& p : planes) {
      const Vec3 far_corner{p.normal[0] >= 0 ? box.hi[0] : box.lo[0],
                            p.normal[1] >= 0 ? box.hi[1] : box.lo[1],
                            p.normal[2] >= 0 ? box.hi[2] : box.lo[2]};
      if (p.distance(far_corner) < 0) return false;
    }
    return true;
  }
};

// The frustum of a valid camera (validate_camera); agrees with projection * view: a
// point is inside iff its clip coordinates satisfy -w <= x, y, z <= w (up to rounding).
Frustum view_frustum(const Camera& camera);

}  // namespace strielad::lod
