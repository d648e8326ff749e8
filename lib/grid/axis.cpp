// SPDX-License-Identifier: Apache-2.0
#include "grid/axis.h"

#include <cmath>

#include "core/error.h"

namespace strielad {

std::string_view axis_kind_name(AxisKind kind) noexcept {
  switch (kind) {
    case AxisKind::kLongitude: return "longitude";
    case AxisKind::kLatitude: return "latitude";
    case AxisKind::kHeight: return "height";
    case AxisKind::kPressure: return "pressure";
    case AxisKind::kModelLevel: return "model_level";
    case AxisKind::kOther: return "other";
    case AxisKind::kProjectionX: return "projection_x";
    case AxisKind::kProjectionY: return "projection_y";
    case AxisKind::kIndex: return "index";
  }
  return "other";
}

AxisKind axis_kind_from_name(std::string_view name) {
  for (AxisKind k : {AxisKind::kLongitude, AxisKind::kLatitude, AxisKind::kHeight,
                     AxisKind::kPressure, AxisKind::kModelLevel, AxisKind::kOther,
                     AxisKind::kProjectionX, AxisKind::kProjectionY, AxisKind::kIndex}) {
    if (axis_kind_name(k) == name) return k;
  }
  throw make_error(ErrorCode::kCorrupt, "unknown axis kind '{}'", name);
}

void check_axis_values(const Axis& axis, std::string_view what) {
  if (axis.values.empty()) {
    throw make_error(ErrorCode::kInvalidInput, "{}: axis '{}' has no values", what, axis.name);
  }
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (!std::isfinite(axis.values[i])) {
      throw make_error(ErrorCode::kInvalidInput, "{}: axis '{}' value {} at index {} is not finite",
                       what, axis.name, axis.values[i], i);
    }
  }
  if (axis.values.size() < 2) return;
  const bool ascending = axis.values[1] > axis.values[0];
  for (std::size_t i = 1; i < axis.values.size(); ++i) {
    const double a = axis.values[i - 1], b = axis.values[i];
    if (ascending ? !(b > a) : !(b < a)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: axis '{}' is not strictly monotonic: value[{}] = {} then value[{}] = {}",
                       what, axis.name, i - 1, a, i, b);
    }
  }
  if (axis.periodic && (axis.kind != AxisKind::kLongitude || !longitudes_repeat_the_first(axis.values))) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: axis '{}' is marked periodic but is not a longitude axis whose last "
                     "value ({}) is its first ({}) turned once round",
                     what, axis.name, axis.values.back(), axis.values.front());
  }
}

bool longitudes_close_the_circle(const std::vector<double>& values) {
  const std::size_t n = values.size();
  if (n < 3) return false;
  const double span = values.back() - values.front();  // negative when descending
  const double turn = span > 0 ? 360.0 : -360.0;
  const double mean = span / static_cast<double>(n - 1);
  const double gap = values.front() + turn - values.back();
  return std::fabs(span) < 360.0 && std::fabs(gap - mean) <= 1e-3 * std::fabs(mean);
}

bool longitudes_repeat_the_first(const std::vector<double>& values) {
  if (values.size() < 3) return false;
  // As the converter appends it: the first value plus (or minus) 360, rounded once.
  return values.back() == values.front() + 360.0 || values.back() == values.front() - 360.0;
}

namespace {

bool strictly_monotonic(const std::vector<double>& v) {
  if (v.size() < 2) return true;
  const bool ascending = v[1] > v[0];
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (ascending ? !(v[i] > v[i - 1]) : !(v[i] < v[i - 1])) return false;
  }
  return true;
}

}  // namespace

bool unwrap_longitudes(std::vector<double>& values) {
  for (const double v : values) {
    if (!std::isfinite(v)) return false;
  }
  if (strictly_monotonic(values)) return false;
  std::vector<double> unwrapped(values);
  double shift = 0;
  for (std::size_t i = 1; i < values.size(); ++i) {
    const double step = values[i] - values[i - 1];
    if (step > 180) shift -= 360;
    if (step < -180) shift += 360;
    unwrapped[i] = values[i] + shift;
  }
  if (!strictly_monotonic(unwrapped)) return false;
  values = std::move(unwrapped);
  return true;
}

std::string_view dtype_name(DType type) noexcept {
  return type == DType::kFloat32 ? "float32" : "float64";
}

DType dtype_from_name(std::string_view name) {
  if (name == "float32") return DType::kFloat32;
  if (name == "float64") return DType::kFloat64;
  throw make_error(ErrorCode::kCorrupt, "unknown data type '{}'", name);
}

}  // namespace strielad
