// SPDX-License-Identifier: Apache-2.0
// The one 3-vector of the library: lattice, axis, wind and world coordinates alike, with
// the few operations on it. Header-only, no allocation.
#pragma once

#include <array>
#include <cmath>

namespace strielad {

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

}  // namespace strielad
