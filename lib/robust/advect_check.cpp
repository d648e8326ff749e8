// SPDX-License-Identifier: Apache-2.0
#include "robust/advect_check.h"

#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "advect/integrators.h"
#include "core/error.h"
#include "store/level_samples.h"

namespace strielad::robust {
namespace {

advect::WindSlice wind_slice(const Store& store, std::uint32_t step) {
  const LevelSamples<double> level = read_level_samples<double>(store, step, 0, 0);
  advect::WindSlice slice;
  slice.u.reserve(level.values.size());
  for (double v : level.values) slice.u.push_back(static_cast<float>(v));
  slice.v = slice.u;
  slice.w = slice.u;
  return slice;
}

}  // namespace

StageFindings check_advection(const Store& store) {
  StageFindings f;
  const format::Manifest& m = store.manifest();
  if (store.step_count() < 2) {
    f.refusal = "advection needs two time steps";
    return f;
  }
  advect::WindGrid grid;
  grid.axes = {m.x.values, m.y.values, m.z.values};
  const bool geographic = m.x.kind == AxisKind::kLongitude && m.y.kind == AxisKind::kLatitude;
  grid.horizontal = geographic ? advect::Horizontal::kDegrees : advect::Horizontal::kMetres;
  grid.periodic_x = m.x.periodic;
  const double t0 = m.time.values[0], t1 = m.time.values[1];
  std::optional<advect::WindField> field;
  try {
    field.emplace(grid, t0, wind_slice(store, 0), t1, wind_slice(store, 1));
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kInternal) throw;
    f.refusal = e.what();
    return f;
  }
  // Start points: centre, first sample (a corner), an inner sample, near the far corner,
  // and one outside the grid.
  const auto along = [&](int a, double u) {
    const auto& v = grid.axes[a];
    return v.front() + u * (v.back() - v.front());
  };
  const auto sample = [&](int a, std::size_t i) {
    const auto& v = grid.axes[a];
    return v[std::min(i, v.size() - 1)];
  };
  struct Start {
    std::string name;
    Vec3 p;
    bool outside = false;
  };
  const std::vector<Start> starts{
      {"centre", {along(0, 0.5), along(1, 0.5), along(2, 0.5)}},
      {"corner", {sample(0, 0), sample(1, 0), sample(2, 0)}},
      {"sample", {sample(0, 2), sample(1, 1), sample(2, 1)}},
      {"far corner", {along(0, 0.999), along(1, 0.999), along(2, 0.999)}},
      {"outside", {along(0, 1.5), along(1, 0.5), along(2, 0.5)}, true}};
  std::vector<advect::AdvectOptions> methods(3);
  methods[0].method = advect::Method::kEuler;
  methods[1].method = advect::Method::kRk4;
  methods[2].method = advect::Method::kDopri5;
  std::map<std::string, int> stops;
  int runs = 0;
  for (const auto& options : methods) {
    for (const Start& s : starts) {
      const advect::AdvectResult r = advect::advect(*field, s.p, t0, t1, options);
      ++runs;
      ++stops[std::string(advect::stop_name(r.stop))];
      const std::string where =
          fmt::format("{} from the {}", advect::method_name(options.method), s.name);
      const bool finite = std::isfinite(r.position[0]) && std::isfinite(r.position[1]) &&
                          std::isfinite(r.position[2]) && std::isfinite(r.t);
      if (!finite) {
        f.problem("{}: ended at ({}, {}, {}) t {}", where, r.position[0], r.position[1],
                  r.position[2], r.t);
        continue;
      }
      if (r.t < t0 || r.t > t1) f.problem("{}: ended at t {} outside [{}, {}]", where, r.t, t0, t1);
      if (s.outside) {
        if (r.stop != advect::Stop::kLeftDomain) {
          f.problem("{}: started outside the grid but stopped '{}'", where, advect::stop_name(r.stop));
        }
        continue;
      }
      if (r.stop == advect::Stop::kReached && r.t != t1) {
        f.problem("{}: 'reached' at t {} instead of {}", where, r.t, t1);
      }
      if (!field->inside(r.position)) {
        f.problem("{}: stopped '{}' outside the grid at ({}, {}, {})", where,
                  advect::stop_name(r.stop), r.position[0], r.position[1], r.position[2]);
      }
    }
  }
  std::string counts;
  for (const auto& [name, count] : stops) {
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", count, name);
  }
  f.summary = fmt::format("{} trajectories: {}", runs, counts);
  return f;
}

}  // namespace strielad::robust
