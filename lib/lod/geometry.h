// SPDX-License-Identifier: Apache-2.0
// The small amount of 3-D geometry the level-of-detail code needs, in the world frame
// (lod/world_frame.h: right-handed, kilometres, z up): vectors, axis-aligned boxes and
// the solid angle a box's bounding sphere covers. Header-only, no allocation.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace strielad::lod {

using Vec3 = std::array<double, 3>;

inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// a / |a|; the zero vector stays zero.
inline Vec3 normalize(const Vec3& a) {
  const double n = length(a);
  return n > 0 ? scale(a, 1.0 / n) : a;
}
// a + s (b - a)
inline Vec3 lerp(const Vec3& a, const Vec3& b, double s) { return add(a, scale(sub(b, a), s)); }
inline bool all_finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

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
