// SPDX-License-Identifier: Apache-2.0
#include "extract/conditions.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace strielad {

double fractional_index(const std::vector<double>& coords, double value) {
  const std::size_t n = coords.size();
  const bool ascending = coords.back() >= coords.front();
  auto before = [&](double a, double b) { return ascending ? a < b : a > b; };
  if (before(value, coords.front())) return -1.0;
  if (before(coords.back(), value)) return static_cast<double>(n);
  // First sample not before value.
  const auto it = std::lower_bound(coords.begin(), coords.end(), value,
                                   [&](double c, double v) { return before(c, v); });
  const std::size_t j = static_cast<std::size_t>(it - coords.begin());
  if (j == 0) return 0.0;
  if (coords[j] == value) return static_cast<double>(j);
  const double f = (value - coords[j - 1]) / (coords[j] - coords[j - 1]);
  return static_cast<double>(j - 1) + std::clamp(f, 0.0, 1.0);
}

namespace {

// Adds the condition unless it holds at every sample; returns false when it holds
// nowhere (the region is empty).
bool add_condition(ConditionSet& set, Condition condition) {
  bool all_inside = true, any_inside = false;
  for (double v : condition.values) {
    const bool in = v >= 0;
    all_inside = all_inside && in;
    any_inside = any_inside || in;
  }
  if (!any_inside) return false;
  if (!all_inside) set.conditions.push_back(std::move(condition));
  return true;
}

}  // namespace

ConditionSet build_conditions(const NodeSamples& samples, const ExtractRequest& request) {
  const auto dims = samples.dims();
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "extraction needs at least 2 samples along axis {} (has {})", a, dims[a]);
    }
  }
  const std::size_t n = samples.sample_count();
  ConditionSet set;

  // Missing samples (NaN or infinite) in any limit field make a validity condition;
  // the limit conditions take the neutral value 0 there.
  std::vector<double> validity;
  for (const ExtractLimit& limit : request.limits) {
    if (limit.field >= samples.fields.size()) {
      throw make_error(ErrorCode::kInvalidArgument, "limit on field {} but the node has {} fields",
                       limit.field, samples.fields.size());
    }
    if (std::isnan(limit.min) || std::isnan(limit.max) || limit.min > limit.max) {
      throw make_error(ErrorCode::kInvalidArgument, "limit on field {}: bad range [{}, {}]",
                       limit.field, limit.min, limit.max);
    }
    const auto& field = samples.fields[limit.field];
    if (field.size() != n) {
      throw make_error(ErrorCode::kInvalidArgument, "field {} holds {} samples, the node has {}",
                       limit.field, field.size(), n);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(field[i])) {
        if (validity.empty()) validity.assign(n, 1.0);
        validity[i] = -1.0;
      }
    }
  }

  auto limit_condition = [&](const ExtractLimit& limit, bool is_min) {
    Condition c;
    c.kind = is_min ? ConditionKind::kLimitMin : ConditionKind::kLimitMax;
    c.field = limit.field;
    c.values.resize(n);
    const auto& field = samples.fields[limit.field];
    const double t = is_min ? limit.min : limit.max;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = field[i];
      const double s = is_min ? v - t : t - v;
      c.values[i] = std::isfinite(v) ? s : 0.0;
    }
    return c;
  };

  bool empty = false;
  for (const ExtractLimit& limit : request.limits) {
    if (limit.min > -kUnbounded) empty = empty || !add_condition(set, limit_condition(limit, true));
    if (limit.max < kUnbounded) empty = empty || !add_condition(set, limit_condition(limit, false));
  }
  if (!validity.empty()) {
    Condition c;
    c.kind = ConditionKind::kValidity;
    c.values = std::move(validity);
    empty = empty || !add_condition(set, std::move(c));
  }

  for (int a = 0; a < 3; ++a) {
    const auto [lo, hi] = request.box[a];
    if (std::isnan(lo) || std::isnan(hi) || lo > hi) {
      throw make_error(ErrorCode::kInvalidArgument, "domain box on axis {}: bad range [{}, {}]",
                       a, lo, hi);
    }
    if (lo == -kUnbounded && hi == kUnbounded) continue;
    const auto& coords = samples.coords[a];
    const bool ascending = coords.back() >= coords.front();
    // Index range covered by [lo, hi] (a descending axis swaps the ends).
    const double i_first = fractional_index(coords, ascending ? lo : hi);
    const double i_last = fractional_index(coords, ascending ? hi : lo);
    if (!(i_first < i_last)) {  // lo = hi: a box without volume, no region
      empty = true;
      continue;
    }
    for (int side = 0; side < 2; ++side) {
      Condition c;
      c.kind = ConditionKind::kBox;
      c.axis = a;
      c.side = side;
      c.values.resize(n);
      const std::size_t stride = a == 0 ? 1 : a == 1 ? dims[0] : dims[0] * dims[1];
      for (std::size_t i = 0; i < n; ++i) {
        const double index = static_cast<double>((i / stride) % dims[a]);
        c.values[i] = side == 0 ? index - i_first : i_last - index;
      }
      empty = empty || !add_condition(set, std::move(c));
    }
  }

  if (set.conditions.size() > kMaxConditions) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sub-volume {} needs {} conditions in one node (at most {})",
                     request.subvolume_id, set.conditions.size(), kMaxConditions);
  }
  set.empty = empty;
  if (empty) {
    set.conditions.clear();
    return set;
  }
  set.inside.assign(n, 0);
  for (std::size_t c = 0; c < set.conditions.size(); ++c) {
    const std::uint64_t bit = std::uint64_t{1} << c;
    set.all |= bit;
    const auto& values = set.conditions[c].values;
    for (std::size_t i = 0; i < n; ++i) set.inside[i] |= values[i] >= 0 ? bit : 0;
  }
  return set;
}

}  // namespace strielad
