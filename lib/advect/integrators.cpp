// SPDX-License-Identifier: Apache-2.0
#include "advect/integrators.h"

#include <algorithm>
#include <cmath>

#include "advect/rosenbrock_stepper.h"
#include "advect/stepper_support.h"
#include "core/error.h"

namespace strielad::advect {
namespace {

using Field = CountedField;

Vec3 axpy(const Vec3& p, double h, const Vec3& k) {
  return {p[0] + h * k[0], p[1] + h * k[1], p[2] + h * k[2]};
}

// One explicit step of a fixed-step method from (p, t) by h, given the rate k1 at (p, t).
// kOk when every stage had wind and so has the end point: `out` and its rate `k_end`
// (the next step's k1, so the end point costs no extra evaluation).
Sample fixed_step(Field& field, Method method, const Vec3& p, double t, double h, const Vec3& k1,
                  Vec3& out, Vec3& k_end) {
  Vec3 k2{}, k3{}, k4{};
  Sample s = Sample::kOk;
  if (method == Method::kEuler) {
    out = axpy(p, h, k1);
  } else {
    if ((s = field.rate(axpy(p, h / 2, k1), t + h / 2, k2)) != Sample::kOk) return s;
    if ((s = field.rate(axpy(p, h / 2, k2), t + h / 2, k3)) != Sample::kOk) return s;
    if ((s = field.rate(axpy(p, h, k3), t + h, k4)) != Sample::kOk) return s;
    for (int a = 0; a < 3; ++a) out[a] = p[a] + h / 6 * (k1[a] + 2 * k2[a] + 2 * k3[a] + k4[a]);
  }
  return field.rate(out, t + h, k_end);
}

// Dormand-Prince 5(4) coefficients.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                 b6 = 11.0 / 84;
// Differences b - b* (5th minus 4th order weights); the 7th stage is the FSAL one.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;

struct DopriStep {
  Sample sample = Sample::kOk;
  Vec3 next{}, k7{};
  double error = 0;  // scaled RMS norm
};

DopriStep dopri_step(Field& field, const Vec3& p, double t, double h, const Vec3& k1,
                     const AdvectOptions& o) {
  DopriStep r;
  Vec3 k2{}, k3{}, k4{}, k5{}, k6{};
  const auto stage = [&](const Vec3& q, double tq, Vec3& k) {
    r.sample = field.rate(q, tq, k);
    return r.sample == Sample::kOk;
  };
  Vec3 q;
  for (int a = 0; a < 3; ++a) q[a] = p[a] + h * a21 * k1[a];
  if (!stage(q, t + c2 * h, k2)) return r;
  for (int a = 0; a < 3; ++a) q[a] = p[a] + h * (a31 * k1[a] + a32 * k2[a]);
  if (!stage(q, t + c3 * h, k3)) return r;
  for (int a = 0; a < 3; ++a) q[a] = p[a] + h * (a41 * k1[a] + a42 * k2[a] + a43 * k3[a]);
  if (!stage(q, t + c4 * h, k4)) return r;
  for (int a = 0; a < 3; ++a) {
    q[a] = p[a] + h * (a51 * k1[a] + a52 * k2[a] + a53 * k3[a] + a54 * k4[a]);
  }
  if (!stage(q, t + c5 * h, k5)) return r;
  for (int a = 0; a < 3; ++a) {
    q[a] = p[a] + h * (a61 * k1[a] + a62 * k2[a] + a63 * k3[a] + a64 * k4[a] + a65 * k5[a]);
  }
  if (!stage(q, t + h, k6)) return r;
  for (int a = 0; a < 3; ++a) {
    r.next[a] = p[a] + h * (b1 * k1[a] + b3 * k3[a] + b4 * k4[a] + b5 * k5[a] + b6 * k6[a]);
  }
  if (!field.inside(r.next)) {
    r.sample = Sample::kOutside;
    return r;
  }
  if (!stage(r.next, t + h, r.k7)) return r;
  Vec3 err;
  for (int a = 0; a < 3; ++a) {
    err[a] = h * (e1 * k1[a] + e3 * k3[a] + e4 * k4[a] + e5 * k5[a] + e6 * k6[a] + e7 * r.k7[a]);
  }
  r.error = scaled_error(err, p, r.next, o);
  return r;
}

void validate(const Vec3& start, double t_start, double t_end, const AdvectOptions& o) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(start[a])) {
      throw make_error(ErrorCode::kInvalidArgument, "advect: start[{}] is not finite", a);
    }
    if (!(o.atol[a] > 0) || !std::isfinite(o.atol[a])) {
      throw make_error(ErrorCode::kInvalidArgument, "advect: atol[{}] must be finite and > 0", a);
    }
  }
  if (!std::isfinite(t_start) || !std::isfinite(t_end)) {
    throw make_error(ErrorCode::kInvalidArgument, "advect: times {} and {} must be finite", t_start,
                     t_end);
  }
  if (!(o.step_s > 0) || !std::isfinite(o.step_s)) {
    throw make_error(ErrorCode::kInvalidArgument, "advect: step {} s must be finite and > 0", o.step_s);
  }
  if (!(o.rtol > 0) || !std::isfinite(o.rtol)) {
    throw make_error(ErrorCode::kInvalidArgument, "advect: rtol {} must be finite and > 0", o.rtol);
  }
  if (!(o.min_step_s > 0) || !std::isfinite(o.min_step_s)) {
    throw make_error(ErrorCode::kInvalidArgument, "advect: min_step {} s must be finite and > 0",
                     o.min_step_s);
  }
}

// Fixed steps; a step that fails is halved towards the boundary down to min_step_s.
AdvectResult advect_fixed(Field& field, const Vec3& start, double t_start, double t_end,
                          const AdvectOptions& o) {
  AdvectResult r{start, t_start};
  const double span = t_end - t_start;
  const double steps_needed = std::ceil(std::abs(span) / o.step_s);
  if (steps_needed > static_cast<double>(o.max_steps)) {
    r.stop = Stop::kStepLimit;
    return r;
  }
  const auto n = static_cast<std::uint64_t>(steps_needed);
  const double h = n == 0 ? 0.0 : span / static_cast<double>(n);
  Vec3 next{}, k1{}, k_next{};
  if (const Sample first = field.rate(r.position, r.t, k1); first != Sample::kOk) {
    r.stop = stop_for(first);
    r.evaluations = field.evaluations;
    return r;
  }
  for (std::uint64_t i = 0; i < n; ++i) {
    const double t = t_start + static_cast<double>(i) * h;
    const double step = i + 1 == n ? t_end - t : h;
    const Sample s = fixed_step(field, o.method, r.position, t, step, k1, next, k_next);
    if (s == Sample::kOk) {
      r.position = next;
      k1 = k_next;
      r.t = t + step;
      ++r.accepted;
      continue;
    }
    // Approach the boundary or the fill with halved steps (never beyond this step's end).
    const double step_end = t + step;
    double part = step / 2;
    double t_now = t;
    Sample last = s;
    while (std::abs(part) >= o.min_step_s && std::abs(step_end - t_now) > 0) {
      const double try_step = std::abs(part) < std::abs(step_end - t_now) ? part : step_end - t_now;
      const Sample ps = fixed_step(field, o.method, r.position, t_now, try_step, k1, next, k_next);
      if (ps == Sample::kOk) {
        r.position = next;
        k1 = k_next;
        t_now = try_step == step_end - t_now ? step_end : t_now + try_step;
        ++r.accepted;
      } else {
        last = ps;
        part /= 2;
        ++r.rejected;
      }
    }
    r.t = t_now;
    if (t_now == step_end) continue;  // the smaller steps got through after all
    r.stop = stop_for(last);
    break;
  }
  r.evaluations = field.evaluations;
  return r;
}

AdvectResult advect_dopri(Field& field, const Vec3& start, double t_start, double t_end,
                          const AdvectOptions& o) {
  AdvectResult r{start, t_start};
  const double direction = t_end < t_start ? -1.0 : 1.0;
  Vec3 k1{};
  Sample s = field.rate(r.position, r.t, k1);
  if (s != Sample::kOk) {
    r.stop = stop_for(s);
    r.evaluations = field.evaluations;
    return r;
  }
  double h = std::min(o.step_s, std::abs(t_end - t_start));
  while (direction * (t_end - r.t) > 0) {
    if (r.accepted + r.rejected >= o.max_steps) {
      r.stop = Stop::kStepLimit;
      break;
    }
    const double remaining = std::abs(t_end - r.t);
    const bool last = h >= remaining;
    const double step = last ? remaining : h;
    const DopriStep d = dopri_step(field, r.position, r.t, direction * step, k1, o);
    if (d.sample != Sample::kOk) {
      // Towards the boundary or the fill: smaller steps until they no longer help.
      ++r.rejected;
      if (step / 2 < o.min_step_s) {
        r.stop = stop_for(d.sample);
        break;
      }
      h = step / 2;
      continue;
    }
    if (d.error <= 1.0) {
      r.position = d.next;
      r.t = last ? t_end : r.t + direction * step;
      k1 = d.k7;
      ++r.accepted;
      const double grow = d.error > 0 ? 0.9 * std::pow(1.0 / d.error, 0.2) : 5.0;
      h = step * std::clamp(grow, 0.2, 5.0);
    } else {
      ++r.rejected;
      h = step * std::clamp(0.9 * std::pow(1.0 / d.error, 0.2), 0.2, 1.0);
      if (h < o.min_step_s) {
        r.stop = Stop::kStepTooSmall;
        break;
      }
    }
  }
  r.evaluations = field.evaluations;
  return r;
}

}  // namespace

std::string_view method_name(Method method) {
  switch (method) {
    case Method::kEuler: return "euler";
    case Method::kRk4: return "rk4";
    case Method::kDopri5: return "dopri5";
    case Method::kRosenbrock: return "rosenbrock";
  }
  return "unknown";
}

Method parse_method(std::string_view name) {
  for (const Method m : {Method::kEuler, Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    if (method_name(m) == name) return m;
  }
  throw make_error(ErrorCode::kInvalidArgument,
                   "integrator '{}': expected euler, rk4, dopri5 or rosenbrock", name);
}

std::string_view stop_name(Stop stop) {
  switch (stop) {
    case Stop::kReached: return "reached";
    case Stop::kLeftDomain: return "left the domain";
    case Stop::kMissingWind: return "missing wind";
    case Stop::kStepLimit: return "step limit";
    case Stop::kStepTooSmall: return "step too small";
  }
  return "unknown";
}

AdvectResult advect(const WindField& field, const Vec3& start, double t_start, double t_end,
                    const AdvectOptions& options) {
  validate(start, t_start, t_end, options);
  if (t_start == t_end) {
    AdvectResult r{start, t_start};
    if (!field.inside(start)) r.stop = Stop::kLeftDomain;
    return r;
  }
  Field counted{field};
  switch (options.method) {
    case Method::kDopri5: return advect_dopri(counted, start, t_start, t_end, options);
    case Method::kRosenbrock: return advect_rosenbrock(counted, start, t_start, t_end, options);
    case Method::kEuler:
    case Method::kRk4: break;
  }
  return advect_fixed(counted, start, t_start, t_end, options);
}

}  // namespace strielad::advect
