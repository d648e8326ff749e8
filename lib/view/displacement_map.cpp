// SPDX-License-Identifier: Apache-2.0
#include "view/displacement_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/wgs84_globe.h"

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

constexpr double kDegrees = 180.0 / std::numbers::pi;

// The smallest cos(latitude) a globe displacement's east part is divided by (as
// lib/advect's rate).
constexpr double kMinCosLatitude = 1e-6;

// Trajectories of a globe map start at most this far from the equator: at a pole a
// longitude has no meaning (lib/advect turns it at u / (R 1e-6)), while 0.1 degree away
// the zonal displacement times cos(latitude), what the map stores, is that of the pole's
// neighbourhood.
constexpr double kMaxStartLatitude = 89.9;

// A globe map's lattice box: the domain's geographic box (a whole turn of longitudes
// when periodic) by its height range in km.
lod::WorldBox globe_box(const lod::WorldFrame& frame, bool periodic) {
  const auto g = frame.geographic_bounds();
  const double z0 = frame.sample_world_z(0);
  const double z1 = frame.sample_world_z(frame.dims().z - 1);
  lod::WorldBox box;
  box.lo = {g.lon_lo, g.lat_lo, std::min(z0, z1)};
  box.hi = {periodic ? g.lon_lo + 360.0 : g.lon_hi, g.lat_hi, std::max(z0, z1)};
  return box;
}

}  // namespace

Vec3 DisplacementMap::displacement_at(const Vec3& p_in, double s) const {
  Vec3 p = p_in;
  if (periodic) {
    const double x = p[0] - box.lo[0];
    p[0] = box.lo[0] + (x - 360.0 * std::floor(x / 360.0));
  }
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

Vec3 DisplacementMap::moved_on_globe(const Vec3& ecef_km, double s, double exaggeration) const {
  const auto g = lod::ecef_km_to_geodetic(ecef_km);
  double lon = g.lon_deg;
  if (!periodic) {  // about the lattice's centre, then clamped by displacement_at
    const double centre = 0.5 * (box.lo[0] + box.hi[0]);
    lon = centre + std::remainder(lon - centre, 360.0);
  }
  const double height = g.height_km / exaggeration;
  const Vec3 d = displacement_at({lon, g.lat_deg, height}, s);
  const double c = std::max(std::cos(g.lat_deg / kDegrees), kMinCosLatitude);
  const Vec3 from = lod::geodetic_to_ecef_km(g.lon_deg, g.lat_deg, g.height_km);
  const Vec3 to = lod::geodetic_to_ecef_km(g.lon_deg + d[0] / c, g.lat_deg + d[1],
                                           (height + d[2]) * exaggeration);
  // The shader adds the difference of the two placements to the vertex (so that a zero
  // displacement leaves it exactly where it was); so does this.
  return {ecef_km[0] + to[0] - from[0], ecef_km[1] + to[1] - from[1],
          ecef_km[2] + to[2] - from[2]};
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
  map.globe = frame.globe();
  map.periodic = map.globe && wind.field.grid().periodic_x;
  map.box = map.globe ? globe_box(frame, map.periodic) : frame.domain();
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
      // On the globe the lattice point is a geodetic position (km heights), its
      // trajectory starting at most kMaxStartLatitude from the equator.
      if (map.globe) start[1] = std::clamp(start[1], -kMaxStartLatitude, kMaxStartLatitude);
      const Vec3 start_world =
          map.globe ? frame.place_geographic(start[0], start[1], start[2]) : start;
      const double start_cos = std::cos(start[1] / kDegrees);
      const Vec3 start_axis = frame.to_axis(start_world);
      Vec3 position = wind.units.to_wind(start_axis);
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
          if (finite && map.globe) {
            const Vec3 g = frame.geographic_of(world);
            // A longitude axis gives the trajectory's longitude unwrapped (it may go
            // round more than half a turn near a pole); other axes through the globe,
            // the short way round.
            const double dlon = frame.horizontal() == lod::HorizontalMap::kGeographic
                                    ? wind.units.to_axis(position)[0] - start_axis[0]
                                    : std::remainder(g[0] - start[0], 360.0);
            last = {dlon * start_cos, g[1] - start[1], g[2] - start[2]};
          } else if (finite) {
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
