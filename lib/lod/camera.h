// SPDX-License-Identifier: Apache-2.0
// A perspective camera in the world frame (lod/world_frame.h, kilometres) and the
// OpenGL-convention matrices a renderer needs. Matrices are column-major float[16]
// (element (row r, column c) at [c * 4 + r]), ready for glUniformMatrix4fv: the view
// matrix maps world to eye space (camera at the origin looking down -z, y up), the
// projection maps eye space to clip space with z in [-w, w] between near and far.
#pragma once

#include <array>

#include "lod/geometry.h"

namespace strielad::lod {

struct Camera {
  Vec3 eye{0, -1, 0};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 0, 1};          // need not be unit or orthogonal to the view direction
  double fov_y_deg = 45.0;   // vertical field of view, in (0, 180)
  double aspect = 16.0 / 9.0;  // width / height, > 0
  double near_km = 0.1;      // > 0
  double far_km = 1.0e4;     // > near_km
};

// \error kInvalidArgument naming the field: a non-finite value, eye == target, up
// (nearly) parallel to the view direction, fov outside (0, 180), aspect <= 0,
// near <= 0 or far <= near.
void validate_camera(const Camera& camera);

// The camera's orthonormal basis: forward (to the target), right, and true up.
struct CameraBasis {
  Vec3 forward, right, up;
};
CameraBasis camera_basis(const Camera& camera);

using Mat4 = std::array<float, 16>;  // column-major

Mat4 view_matrix(const Camera& camera);
Mat4 projection_matrix(const Camera& camera);
Mat4 multiply(const Mat4& a, const Mat4& b);  // a * b
// Clip coordinates (x, y, z, w) of a world point under projection * view.
std::array<double, 4> to_clip(const Mat4& view_projection, const Vec3& p);

// The up vector a camera path uses: world +z, or world +y (north up) when the view
// direction is within about 0.6 degrees of vertical, where +z would be degenerate.
Vec3 default_up(const Vec3& eye, const Vec3& target);

// A camera at `eye` looking at `target` with default_up, whose far plane lies beyond
// the farthest corner of `scene` (so nothing of the scene is clipped by distance) and
// whose near plane is far / 10^4 (at least 1 m): depth precision stays usable while
// the near plane hides at most the last metres in front of the eye.
// \error as validate_camera (e.g. eye == target).
Camera look_at(const Vec3& eye, const Vec3& target, double fov_y_deg, double aspect,
               const WorldBox& scene);

}  // namespace strielad::lod
