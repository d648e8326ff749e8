// SPDX-License-Identifier: Apache-2.0
// A store whose fields are distances to two points, so that sub-volumes "d1 <= r" are
// spheres whose pictures a render test can predict. Axes: lon 0..1 degree, lat -0.5..0.5
// degree, height 0..11,119.5 m, 33 samples each by default, so that at the default vertical
// exaggeration (10) the domain is a cube 111.2 km on a side in the viewer's world
// frame, centred at (0, 0, 55.6) km. Variables "d1" and "d2": world-frame distance (km,
// exaggeration 10) to kSphereCenter1 and kSphereCenter2. Two time steps: in step 1 both
// centres are 10 km further east.
#pragma once

#include <filesystem>

#include "lod/geometry.h"

namespace strielad::testing {

inline constexpr Vec3 kSphereCenter1{-20.0, 0.0, 55.0};
inline constexpr Vec3 kSphereCenter2{30.0, 0.0, 55.0};
inline constexpr double kSphereStepShiftKm = 10.0;

// Writes the NetCDF files under `dir` and converts them into `dir / "spheres"` with
// bricks of `brick` cells and `samples` samples per axis (the same domain: more samples
// are a finer grid); returns the store path.
std::filesystem::path write_sphere_store(const std::filesystem::path& dir, unsigned brick = 8,
                                         std::size_t samples = 33);

}  // namespace strielad::testing
