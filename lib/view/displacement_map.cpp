// SPDX-License-Identifier: Apache-2.0
#include "view/displacement_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "core/error.h"

namespace strielad::view {
namespace {

std::size_t default_lattice(std::size_t level_samples, std::size_t factor, std::size_t max) {
  return std::clamp<std::size_t>(level_samples * factor, 8, max);
}

// Lattice coordinate of p along an axis: fractional index in [0, n - 1].
double lattice_coordinate(double p, double lo, double hi, std::size_t n) {
  if (!(hi > lo)) return 0;
  const double u = (p - lo) / (hi - lo) * static_cast<double>(n - 1);
  return std::clamp(u, 0.0, static_cast<double>(n - 1));
}

}  // namespace

Vec3 DisplacementMap::displacement_at(const Vec3& p, double s) const {
  std::array<std::size_t, 3> i0{};
  std::array<double, 3> f{};
  for (int a = 0; a < 3; ++a) {
    const double u = lattice_coordinate(p[a], box.lo[a], box.hi[a], lattice[a]);
    i0[a] = std::min(static_cast<std::size_t>(u), lattice[a] - 2);
    f[a] = u - static_cast<double>(i0[a]);
  }
  const double k_real = std::clamp(s / seconds, 0.0, 1.0) * static_cast<double>(keyframes - 1);
  const std::size_t k0 = std::min(static_cast<std::size_t>(k_real), keyframes - 2);
  const double fk = k_real - static_cast<double>(k0);
  Vec3 out{0, 0, 0};
  for (std::size_t k = k0; k <= k0 + 1; ++k) {
    const double wk = k == k0 ? 1 - fk : fk;
    const float* d = keyframe(k);
    for (int corner = 0; corner < 8; ++corner) {
      double w = wk;
      std::array<std::size_t, 3> c{};
      for (int a = 0; a < 3; ++a) {
        const bool up = (corner >> a) & 1;
        c[a] = i0[a] + (up ? 1 : 0);
        w *= up ? f[a] : 1 - f[a];
      }
      const std::size_t index = (c[2] * lattice[1] + c[1]) * lattice[0] + c[0];
      for (int a = 0; a < 3; ++a) out[a] += w * d[index * 3 + a];
    }
  }
  return out;
}

DisplacementMap compute_displacement_map(const WindStep& wind, const lod::WorldFrame& frame,
                                         const DisplacementOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const auto& axes = wind.field.grid().axes;
  std::array<std::size_t, 3> lattice = options.lattice;
  for (int a = 0; a < 3; ++a) {
    if (lattice[a] == 0) {
      lattice[a] = a < 2 ? default_lattice(axes[a].size(), 1, 128)
                         : default_lattice(axes[a].size(), 2, 64);
    }
    if (lattice[a] < 2 || lattice[a] > 1024) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "displacement lattice: {} points along axis {}: need 2..1024",
                       lattice[a], a);
    }
  }
  if (options.keyframes < 2 || options.keyframes > 64) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "displacement keyframes: {}: need 2..64", options.keyframes);
  }
  DisplacementMap map;
  map.step = wind.step;
  map.seconds = wind.seconds;
  map.box = frame.domain();
  map.lattice = lattice;
  map.keyframes = options.keyframes;
  const std::size_t points = map.points();
  map.displacement.assign(points * 3 * map.keyframes, 0.0f);
  // Checks the integrator options once, before the parallel loop (advect() throws).
  if (points > 0) {
    advect::advect(wind.field, wind.units.to_wind(frame.to_axis(map.box.center())), 0, 0,
                   options.integrator);
  }
  std::atomic<std::uint64_t> stopped{0}, evaluations{0};
  tbb::parallel_for(std::size_t{0}, lattice[2] * lattice[1], [&](std::size_t zy) {
    const std::size_t z = zy / lattice[1], y = zy % lattice[1];
    std::uint64_t local_stopped = 0, local_evaluations = 0;
    for (std::size_t x = 0; x < lattice[0]; ++x) {
      const std::array<std::size_t, 3> index{x, y, z};
      Vec3 start{};
      for (int a = 0; a < 3; ++a) {
        // Points on the box's faces start a hair inside, so that rounding in the
        // world-to-axis map does not put them outside the grid (where they could not
        // move at all).
        const double extent = map.box.hi[a] - map.box.lo[a];
        start[a] = std::clamp(map.box.lo[a] + extent * static_cast<double>(index[a]) /
                                                  static_cast<double>(lattice[a] - 1),
                              map.box.lo[a] + 1e-9 * extent, map.box.hi[a] - 1e-9 * extent);
      }
      Vec3 position = wind.units.to_wind(frame.to_axis(start));
      bool moving = true;
      const std::size_t point = (z * lattice[1] + y) * lattice[0] + x;
      Vec3 last{0, 0, 0};
      for (std::size_t k = 1; k < map.keyframes; ++k) {
        if (moving) {
          const auto r = advect::advect(wind.field, position, map.keyframe_seconds(k - 1),
                                        map.keyframe_seconds(k), options.integrator);
          local_evaluations += r.evaluations;
          position = r.position;
          if (r.stop != advect::Stop::kReached) {
            moving = false;
            ++local_stopped;
          }
          const Vec3 world = frame.to_world(wind.units.to_axis(position));
          bool finite = true;
          for (int a = 0; a < 3; ++a) finite = finite && std::isfinite(world[a]);
          if (finite) {
            for (int a = 0; a < 3; ++a) last[a] = world[a] - start[a];
          } else {
            moving = false;  // e.g. a pressure the standard atmosphere cannot place
          }
        }
        float* d = map.displacement.data() + (k * points + point) * 3;
        for (int a = 0; a < 3; ++a) d[a] = static_cast<float>(last[a]);
      }
    }
    stopped += local_stopped;
    evaluations += local_evaluations;
  });
  map.stopped = stopped.load();
  map.evaluations = evaluations.load();
  map.compute_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return map;
}

}  // namespace strielad::view
