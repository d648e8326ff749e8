// SPDX-License-Identifier: Apache-2.0
// A wind field between two output time steps on a rectilinear grid: u, v, w at t0 and
// t1, trilinear in space on the real (non-uniform, possibly descending) axes and linear
// in time, turned into the rate of change of a point's axis coordinates.
//
// Units (R = 6,371,008.8 m, the IUGG mean Earth radius, as lod/world_frame.h):
// - geographic x/y (longitude/latitude in degrees), u/v in m/s:
//     dlon/dt = u / (R cos(lat)) * 180/pi,  dlat/dt = v / R * 180/pi  (degrees per second);
//   cos(lat) is taken as at least 1e-6 (0.2 m from a pole), so a point at a pole gets a
//   large but finite longitude rate, never Inf or NaN;
// - metric x/y (metres), u/v in m/s: dx/dt = u, dy/dt = v;
// - vertical height (m) with w in m/s, or pressure (Pa) with w in Pa/s (omega): dz/dt = w.
// A point outside the grid, or where any of the eight samples around it at either time
// is fill (NaN), has no rate: the integrators stop there and say why. On a periodic
// longitude axis no point is outside in x.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/vec3.h"

namespace strielad::advect {

inline constexpr double kEarthRadiusM = 6371008.8;

enum class Horizontal { kDegrees, kMetres };
enum class Vertical { kMetres, kPascals };

struct WindGrid {
  std::array<std::vector<double>, 3> axes;  // x, y, z coordinates; each strictly monotonic
  Horizontal horizontal = Horizontal::kDegrees;
  Vertical vertical = Vertical::kMetres;
  // x is a longitude axis round the Earth whose last value is its first + 360
  // (formats/store.md, "Grid placement"): a point is located a whole turn back into the
  // axis, so trajectories cross the seam (their longitudes go on past it, unwrapped).
  bool periodic_x = false;
  std::size_t count() const { return axes[0].size() * axes[1].size() * axes[2].size(); }
};

// One time's components, x fastest then y then z (the store's brick order); NaN = fill.
struct WindSlice {
  std::vector<float> u, v, w;
};

enum class Sample { kOk, kOutside, kMissing };

class WindField {
 public:
  // \error kInvalidArgument naming the field: an axis with fewer than 2 values, not
  // finite or not strictly monotonic; a latitude outside [-90, 90]; a component whose
  // size is not the grid's count; t1 <= t0 or a non-finite time.
  WindField(WindGrid grid, double t0, WindSlice at_t0, double t1, WindSlice at_t1);

  // The rate of change of the axis coordinates at point p and time t (t clamped to
  // [t0, t1]). Writes `rate` only for kOk. Thread-safe (const, no state).
  Sample rate(const Vec3& p, double t, Vec3& rate) const;
  bool inside(const Vec3& p) const;

  const WindGrid& grid() const { return grid_; }
  double t0() const { return t0_; }
  double t1() const { return t1_; }

 private:
  // x located on the axis: a whole turn back into it on a periodic axis.
  double grid_x(double x) const;

  WindGrid grid_;
  double t0_, t1_;
  std::array<WindSlice, 2> slices_;
};

// (u, v, w) of a wind given by a formula at (x, y, z, t).
using WindFormula = std::function<Vec3(double x, double y, double z, double t)>;

// A WindField of `formula` sampled (as float, like model output) on `grid` at t0 and t1:
// for benchmarks and tests with known trajectories. \error as WindField's constructor.
WindField sample_wind(WindGrid grid, double t0, double t1, const WindFormula& formula);

// n values from first to last, evenly spaced (n >= 2).
std::vector<double> evenly_spaced(double first, double last, std::size_t n);

}  // namespace strielad::advect
