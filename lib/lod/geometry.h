// SPDX-License-Identifier: Apache-2.0
// The small amount of 3-D geometry the level-of-detail code needs, in the world frame
// (lod/world_frame.h: right-handed, kilometres, z up): axis-aligned boxes of Vec3
// (core/vec3.h) and the solid angle a box's bounding sphere covers. Header-only, no
// allocation.
#pragma once

#include <cmath>
#include <numbers>

#include "core/vec3.h"

namespace strielad::lod {

// Axis-aligned box, lo <= hi per axis (a degenerate, flat box is allowed).
struct WorldBox {
  Vec3 lo{}, hi{};
  Vec3 center() const { return scale(add(lo, hi), 0.5); }
  // Radius of the bounding sphere about center(): half the diagonal.
  double radius() const { return 0.5 * length(sub(hi, lo)); }
  bool contains(const Vec3& p) const {
    for (int a = 0; a < 3; ++a) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
    }
    return true;
  }
  bool contains(const WorldBox& b) const { return contains(b.lo) && contains(b.hi); }
  friend bool operator==(const WorldBox&, const WorldBox&) = default;
};

// Solid angle (steradians) of a sphere of `radius` whose centre lies `distance` away:
// the cap 2 pi (1 - sqrt(1 - r^2 / d^2)), and the whole sphere of directions, 4 pi, when
// the point is inside the sphere (d <= r). A box is judged by its bounding sphere: this
// over-estimates a flat or long box by up to the ratio of sphere to box silhouette, which
// errs towards more detail, never less.
inline double sphere_solid_angle(double radius, double distance) {
  constexpr double kFull = 4.0 * std::numbers::pi;
  if (!(distance > radius)) return kFull;
  const double q = radius / distance;
  // 1 - sqrt(1 - q^2) without cancellation for small q.
  return 2.0 * std::numbers::pi * (q * q) / (1.0 + std::sqrt(1.0 - q * q));
}

}  // namespace strielad::lod
