// SPDX-License-Identifier: Apache-2.0
#include "advect/rosenbrock_stepper.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace strielad::advect {
namespace {

// RODAS3 (rosenbrock_stepper.h). a21 = a32 = a42 = 0 and alpha = (0, 0, 1, 1): stage 2
// reuses stage 1's rate, stages 3 and 4 evaluate at the step's end time. m2 = 0.
constexpr double kGamma = 0.5;
constexpr double a31 = 2, a41 = 2, a43 = 1;
constexpr double c21 = 4, c31 = 1, c32 = -1, c41 = 1, c42 = -1, c43 = -8.0 / 3;
constexpr double m1 = 2, m3 = 1, m4 = 1;
constexpr double gamma1 = 0.5, gamma2 = 1.5;  // gamma3 = gamma4 = 0
constexpr double kSingularPivot = 1e-12;

// The rate's derivatives at the start of a step: kept while a rejected step is retried.
struct Linearization {
  Mat3 jacobian{};  // d rate[row] / d position[column]
  Vec3 rate_dt{};   // d rate / dt
};

// Forward differences of the rate at (p, t), whose rate is `rate`; a difference that
// fails (outside the grid, fill) is taken backwards. Not kOk when neither way works.
Sample linearize(CountedField& field, const Vec3& p, double t, double direction, const Vec3& rate,
                 Linearization& out) {
  const WindGrid& grid = field.wind.grid();
  Vec3 moved{};
  for (int a = 0; a < 3; ++a) {
    const auto& axis = grid.axes[a];
    double delta = std::max(kJacobianFraction * std::abs(axis.back() - axis.front()),
                            1e-12 * std::abs(p[a]));
    Vec3 q = p;
    q[a] = p[a] + delta;
    Sample s = field.rate(q, t, moved);
    if (s != Sample::kOk) {
      delta = -delta;
      q[a] = p[a] + delta;
      if ((s = field.rate(q, t, moved)) != Sample::kOk) return s;
    }
    for (int row = 0; row < 3; ++row) out.jacobian[row][a] = (moved[row] - rate[row]) / delta;
  }
  // The field is linear in time between its steps (and constant outside): any step
  // inside gives the exact slope.
  const double dt = direction * kJacobianFraction * (field.wind.t1() - field.wind.t0());
  if (const Sample s = field.rate(p, t + dt, moved); s != Sample::kOk) return s;
  for (int row = 0; row < 3; ++row) out.rate_dt[row] = (moved[row] - rate[row]) / dt;
  return Sample::kOk;
}

struct RosenbrockStep {
  Sample sample = Sample::kOk;
  bool singular = false;  // M could not be solved: retry smaller
  Vec3 next{};
  double error = 0;       // scaled RMS norm of K4
};

Vec3 combine(const Vec3& p, double a, const Vec3& x, double b = 0, const Vec3& y = {}) {
  return {p[0] + a * x[0] + b * y[0], p[1] + a * x[1] + b * y[1], p[2] + a * x[2] + b * y[2]};
}

// One RODAS3 step from (p, t) by h (signed), given the rate f0 at (p, t).
RosenbrockStep rosenbrock_step(CountedField& field, const Vec3& p, double t, double h,
                               const Vec3& f0, const Linearization& lin, const AdvectOptions& o) {
  RosenbrockStep r;
  const double hg = h * kGamma;
  Mat3 m{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] = (i == j ? 1.0 : 0.0) - hg * lin.jacobian[i][j];
  }
  // M K = h gamma rhs for each stage.
  const auto stage = [&](const Vec3& rhs, Vec3& k) {
    if (solve_3x3(m, {hg * rhs[0], hg * rhs[1], hg * rhs[2]}, k)) return true;
    r.singular = true;
    return false;
  };
  Vec3 k1{}, k2{}, k3{}, k4{}, f{}, rhs{};
  for (int a = 0; a < 3; ++a) rhs[a] = f0[a] + h * gamma1 * lin.rate_dt[a];
  if (!stage(rhs, k1)) return r;
  for (int a = 0; a < 3; ++a) rhs[a] = f0[a] + c21 / h * k1[a] + h * gamma2 * lin.rate_dt[a];
  if (!stage(rhs, k2)) return r;
  if ((r.sample = field.rate(combine(p, a31, k1), t + h, f)) != Sample::kOk) return r;
  for (int a = 0; a < 3; ++a) rhs[a] = f[a] + (c31 * k1[a] + c32 * k2[a]) / h;
  if (!stage(rhs, k3)) return r;
  if ((r.sample = field.rate(combine(p, a41, k1, a43, k3), t + h, f)) != Sample::kOk) return r;
  for (int a = 0; a < 3; ++a) rhs[a] = f[a] + (c41 * k1[a] + c42 * k2[a] + c43 * k3[a]) / h;
  if (!stage(rhs, k4)) return r;
  for (int a = 0; a < 3; ++a) r.next[a] = p[a] + m1 * k1[a] + m3 * k3[a] + m4 * k4[a];
  r.error = scaled_error(k4, p, r.next, o);
  return r;
}

}  // namespace

bool solve_3x3(const Mat3& m, const Vec3& b, Vec3& x) {
  Mat3 a = m;
  Vec3 y = b;
  double largest = 0;
  for (const auto& row : a) {
    for (const double v : row) {
      if (!std::isfinite(v)) return false;
      largest = std::max(largest, std::abs(v));
    }
  }
  const double tiny = kSingularPivot * largest;
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row) {
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    }
    if (!(std::abs(a[pivot][col]) > tiny)) return false;
    std::swap(a[col], a[pivot]);
    std::swap(y[col], y[pivot]);
    for (int row = col + 1; row < 3; ++row) {
      const double factor = a[row][col] / a[col][col];
      for (int c = col; c < 3; ++c) a[row][c] -= factor * a[col][c];
      y[row] -= factor * y[col];
    }
  }
  Vec3 out{};
  for (int row = 2; row >= 0; --row) {
    double sum = y[row];
    for (int c = row + 1; c < 3; ++c) sum -= a[row][c] * out[c];
    out[row] = sum / a[row][row];
    if (!std::isfinite(out[row])) return false;
  }
  x = out;
  return true;
}

AdvectResult advect_rosenbrock(CountedField& field, const Vec3& start, double t_start,
                               double t_end, const AdvectOptions& o) {
  AdvectResult r{start, t_start};
  const double direction = t_end < t_start ? -1.0 : 1.0;
  const auto finish = [&](Stop stop) {
    r.stop = stop;
    r.evaluations = field.evaluations;
    return r;
  };
  Vec3 f0{};
  if (const Sample s = field.rate(r.position, r.t, f0); s != Sample::kOk) {
    return finish(stop_for(s));
  }
  Linearization lin;
  bool linearized = false;
  double h = std::min(o.step_s, std::abs(t_end - t_start));
  while (direction * (t_end - r.t) > 0) {
    if (r.accepted + r.rejected >= o.max_steps) return finish(Stop::kStepLimit);
    if (!linearized) {
      const Sample s = linearize(field, r.position, r.t, direction, f0, lin);
      if (s != Sample::kOk) return finish(stop_for(s));
      linearized = true;
    }
    const double remaining = std::abs(t_end - r.t);
    const bool last = h >= remaining;
    const double step = last ? remaining : h;
    const double t_next = last ? t_end : r.t + direction * step;
    RosenbrockStep d = rosenbrock_step(field, r.position, r.t, direction * step, f0, lin, o);
    Vec3 f_next{};
    if (!d.singular && d.sample == Sample::kOk && d.error <= 1.0) {
      // The new position must have wind, like the Dormand-Prince pair's last stage: its
      // rate is the next step's first stage.
      d.sample = field.inside(d.next) ? field.rate(d.next, t_next, f_next) : Sample::kOutside;
    }
    if (d.singular || d.sample != Sample::kOk) {
      // Towards the boundary or the fill, or past an eigenvalue 1 / (h gamma) of J:
      // smaller steps until they no longer help.
      ++r.rejected;
      if (step / 2 < o.min_step_s) {
        return finish(d.singular ? Stop::kStepTooSmall : stop_for(d.sample));
      }
      h = step / 2;
      continue;
    }
    if (d.error <= 1.0) {
      r.position = d.next;
      r.t = t_next;
      f0 = f_next;
      linearized = false;
      ++r.accepted;
      const double grow = d.error > 0 ? 0.9 * std::cbrt(1.0 / d.error) : 5.0;
      h = step * std::clamp(grow, 0.2, 5.0);
    } else {
      ++r.rejected;
      h = step * std::clamp(0.9 * std::cbrt(1.0 / d.error), 0.2, 1.0);
      if (h < o.min_step_s) return finish(Stop::kStepTooSmall);
    }
  }
  return finish(Stop::kReached);
}

}  // namespace strielad::advect
