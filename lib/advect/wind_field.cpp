// SPDX-License-Identifier: Apache-2.0
#include "advect/wind_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace strielad::advect {
namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};
constexpr double kMinCosLatitude = 1e-6;

// Cell index i and fraction f with value = axis[i] + f (axis[i+1] - axis[i]), f in
// [0, 1], for ascending or descending axes; false outside.
bool locate(const std::vector<double>& axis, double value, std::size_t& i, double& f) {
  const bool ascending = axis.back() > axis.front();
  const double lo = ascending ? axis.front() : axis.back();
  const double hi = ascending ? axis.back() : axis.front();
  if (!(value >= lo && value <= hi)) return false;
  std::size_t k;
  if (ascending) {
    k = static_cast<std::size_t>(std::upper_bound(axis.begin(), axis.end(), value) - axis.begin());
  } else {
    k = static_cast<std::size_t>(
        std::upper_bound(axis.begin(), axis.end(), value, std::greater<double>()) - axis.begin());
  }
  i = std::min(k == 0 ? 0 : k - 1, axis.size() - 2);
  f = (value - axis[i]) / (axis[i + 1] - axis[i]);
  f = std::clamp(f, 0.0, 1.0);
  return true;
}

void check_axis(const std::vector<double>& axis, int a) {
  if (axis.size() < 2) {
    throw make_error(ErrorCode::kInvalidArgument, "wind grid: axis {} has {} values (at least 2)",
                     kAxisNames[a], axis.size());
  }
  const double sign = axis[1] > axis[0] ? 1.0 : -1.0;
  for (std::size_t i = 0; i < axis.size(); ++i) {
    if (!std::isfinite(axis[i])) {
      throw make_error(ErrorCode::kInvalidArgument, "wind grid: axis {}[{}] is not finite",
                       kAxisNames[a], i);
    }
    if (i > 0 && !((axis[i] - axis[i - 1]) * sign > 0)) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "wind grid: axis {} is not strictly monotonic at index {}", kAxisNames[a], i);
    }
  }
}

}  // namespace

WindField::WindField(WindGrid grid, double t0, WindSlice at_t0, double t1, WindSlice at_t1)
    : grid_(std::move(grid)), t0_(t0), t1_(t1), slices_{std::move(at_t0), std::move(at_t1)} {
  for (int a = 0; a < 3; ++a) check_axis(grid_.axes[a], a);
  if (grid_.horizontal == Horizontal::kDegrees) {
    for (const double lat : grid_.axes[1]) {
      if (lat < -90 || lat > 90) {
        throw make_error(ErrorCode::kInvalidArgument, "wind grid: latitude {} outside [-90, 90]", lat);
      }
    }
  }
  if (grid_.periodic_x && (grid_.horizontal != Horizontal::kDegrees ||
                           std::fabs(grid_.axes[0].back() - grid_.axes[0].front()) != 360.0)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "wind grid: a periodic x axis is a longitude axis spanning 360 degrees "
                     "(it spans {} .. {})",
                     grid_.axes[0].front(), grid_.axes[0].back());
  }
  if (!std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0)) {
    throw make_error(ErrorCode::kInvalidArgument, "wind field: times {} and {}: need t0 < t1, finite",
                     t0, t1);
  }
  const char* names[3] = {"u", "v", "w"};
  for (int s = 0; s < 2; ++s) {
    const std::vector<float>* components[3] = {&slices_[s].u, &slices_[s].v, &slices_[s].w};
    for (int c = 0; c < 3; ++c) {
      if (components[c]->size() != grid_.count()) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "wind field: {} at t{} has {} values, the grid {}", names[c], s,
                         components[c]->size(), grid_.count());
      }
    }
  }
}

double WindField::grid_x(double x) const {
  if (!grid_.periodic_x) return x;
  const auto& ax = grid_.axes[0];
  const double lo = std::min(ax.front(), ax.back());
  return lo + std::fmod(std::fmod(x - lo, 360.0) + 360.0, 360.0);
}

bool WindField::inside(const Vec3& p) const {
  std::size_t i;
  double f;
  for (int a = 0; a < 3; ++a) {
    if (!locate(grid_.axes[a], a == 0 ? grid_x(p[0]) : p[a], i, f)) return false;
  }
  return true;
}

Sample WindField::rate(const Vec3& p, double t, Vec3& rate) const {
  std::array<std::size_t, 3> i{};
  std::array<double, 3> f{};
  for (int a = 0; a < 3; ++a) {
    if (!locate(grid_.axes[a], a == 0 ? grid_x(p[0]) : p[a], i[a], f[a])) return Sample::kOutside;
  }
  const double ft = std::clamp((t - t0_) / (t1_ - t0_), 0.0, 1.0);
  const std::size_t nx = grid_.axes[0].size(), ny = grid_.axes[1].size();
  Vec3 wind{0, 0, 0};
  for (int s = 0; s < 2; ++s) {
    const double wt = s == 0 ? 1.0 - ft : ft;
    const std::vector<float>* components[3] = {&slices_[s].u, &slices_[s].v, &slices_[s].w};
    for (int corner = 0; corner < 8; ++corner) {
      const std::size_t x = i[0] + (corner & 1), y = i[1] + ((corner >> 1) & 1),
                        z = i[2] + ((corner >> 2) & 1);
      const double w = wt * ((corner & 1) ? f[0] : 1 - f[0]) *
                       (((corner >> 1) & 1) ? f[1] : 1 - f[1]) *
                       (((corner >> 2) & 1) ? f[2] : 1 - f[2]);
      const std::size_t index = (z * ny + y) * nx + x;
      for (int c = 0; c < 3; ++c) {
        const float value = (*components[c])[index];
        // A fill sample poisons the point even with weight 0: the field is undefined there.
        if (!std::isfinite(value)) return Sample::kMissing;
        wind[c] += w * value;
      }
    }
  }
  if (grid_.horizontal == Horizontal::kDegrees) {
    constexpr double kDegPerRad = 180.0 / std::numbers::pi;
    const double cos_lat = std::max(std::cos(p[1] / kDegPerRad), kMinCosLatitude);
    rate[0] = wind[0] / (kEarthRadiusM * cos_lat) * kDegPerRad;
    rate[1] = wind[1] / kEarthRadiusM * kDegPerRad;
  } else {
    rate[0] = wind[0];
    rate[1] = wind[1];
  }
  rate[2] = wind[2];
  return Sample::kOk;
}

WindField sample_wind(WindGrid grid, double t0, double t1, const WindFormula& formula) {
  std::array<WindSlice, 2> slices;
  for (int s = 0; s < 2; ++s) {
    for (const double z : grid.axes[2])
      for (const double y : grid.axes[1])
        for (const double x : grid.axes[0]) {
          const Vec3 w = formula(x, y, z, s == 0 ? t0 : t1);
          slices[s].u.push_back(static_cast<float>(w[0]));
          slices[s].v.push_back(static_cast<float>(w[1]));
          slices[s].w.push_back(static_cast<float>(w[2]));
        }
  }
  return WindField(std::move(grid), t0, std::move(slices[0]), t1, std::move(slices[1]));
}

std::vector<double> evenly_spaced(double first, double last, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = first + (last - first) * double(i) / double(n - 1);
  return v;
}

}  // namespace strielad::advect
