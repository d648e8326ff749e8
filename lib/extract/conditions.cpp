// SPDX-License-Identifier: Apache-2.0
#include "extract/conditions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

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

// Builds one condition after another into a set, reusing its buffers.
class Builder {
 public:
  Builder(ConditionSet& set, std::size_t n) : set_(set), n_(n) {}

  // A value buffer of n samples (contents undefined).
  std::vector<double> buffer() {
    std::vector<double> v;
    if (!set_.spare.empty()) {
      v = std::move(set_.spare.back());
      set_.spare.pop_back();
    }
    v.resize(n_);
    return v;
  }

  // Adds the condition unless it holds at every sample (its buffer is then kept for
  // later); returns false when it holds nowhere (the region is empty). `in(i)`: whether
  // it holds at sample i. Sets the condition's bit in set.inside on the way.
  template <class In>
  bool add(Condition condition, In in) {
    const std::size_t index = set_.conditions.size();
    unsigned some = 0, every = 1;  // holds at some sample, at every sample
    with_masks([&](auto* inside) {
      using Mask = std::remove_pointer_t<decltype(inside)>;
      if (index == 0) {
        for (std::size_t i = 0; i < n_; ++i) {
          const Mask b = in(i) ? 1 : 0;
          inside[i] = b;
          some |= b;
          every &= b;
        }
      } else if (index < kBits<Mask>) {
        for (std::size_t i = 0; i < n_; ++i) {
          const Mask b = in(i) ? 1 : 0;
          inside[i] |= static_cast<Mask>(b << index);
          some |= b;
          every &= b;
        }
      } else {
        for (std::size_t i = 0; i < n_; ++i) {
          const unsigned b = in(i) ? 1 : 0;
          some |= b;
          every &= b;
        }
      }
    });
    return finish(std::move(condition), index, some != 0, every != 0);
  }

  // Keeps the condition unless it holds nowhere or everywhere (then its bit goes).
  // (Whether it holds somewhere and everywhere, as OR and AND over the samples: no
  // counters, whose 64-bit sums would cost the vectorized loops a widening each.)
  bool finish(Condition condition, std::size_t index, bool somewhere, bool everywhere) {
    if (everywhere) {
      with_masks([&](auto* inside) {
        using Mask = std::remove_pointer_t<decltype(inside)>;
        if (index >= kBits<Mask>) return;
        const auto keep = static_cast<Mask>(~(Mask{1} << index));
        for (std::size_t i = 0; i < n_; ++i) inside[i] &= keep;
      });
    }
    if (somewhere && !everywhere) {
      set_.conditions.push_back(std::move(condition));
    } else if (!condition.values.empty()) {
      set_.spare.push_back(std::move(condition.values));
    }
    return somewhere;
  }

  bool add(Condition condition) {
    const double* v = condition.values.data();
    return add(std::move(condition), [v](std::size_t i) { return v[i] >= 0; });
  }

  // A limit on float samples: `value >= bound` (is_min) or `value <= bound`, and
  // missing (non-finite) samples, where the limit's value is 0, count as inside.
  // Compared in float against the float bound that decides the same for every float
  // (branch-free, so that the loop vectorizes). Sets `missing` when a sample is
  // missing.
  bool add_limit(Condition condition, bool is_min, bool& missing) {
    const std::size_t index = set_.conditions.size();
    const float* f = condition.samples;
    const float t = is_min ? float_at_or_above(condition.bound) : float_at_or_below(condition.bound);
    constexpr float kMax = std::numeric_limits<float>::max();
    const std::size_t n = n_;  // a local: stores to inside[] could alias n_
    unsigned some = 0, every = 1, any_absent = 0;
    auto run = [&](auto op) {
      for (std::size_t i = 0; i < n; ++i) {
        const float v = f[i];
        const auto absent = static_cast<unsigned>(!(std::fabs(v) <= kMax));
        const auto in = absent | static_cast<unsigned>(is_min ? v >= t : v <= t);
        op(i, in);
        some |= in;
        every &= in;
        any_absent |= absent;
      }
    };
    with_masks([&](auto* inside) {
      using Mask = std::remove_pointer_t<decltype(inside)>;
      if (index == 0) {
        run([&](std::size_t i, unsigned in) { inside[i] = static_cast<Mask>(in); });
      } else if (index < kBits<Mask>) {
        run([&](std::size_t i, unsigned in) {
          inside[i] |= static_cast<Mask>(static_cast<Mask>(in) << index);
        });
      } else {
        run([](std::size_t, unsigned) {});
      }
    });
    missing = missing || any_absent != 0;
    return finish(std::move(condition), index, some != 0, every != 0);
  }

 private:
  template <class Mask>
  static constexpr std::size_t kBits = 8 * sizeof(Mask);

  // Calls op with the set's mask array (narrow or wide).
  template <class Op>
  void with_masks(Op op) {
    if (set_.narrow) {
      op(set_.inside16.data());
    } else {
      op(set_.inside64.data());
    }
  }

  // The smallest float >= t: for every float v, v >= it exactly when v >= t.
  static float float_at_or_above(double t) {
    constexpr double kMax = std::numeric_limits<float>::max();
    if (t > kMax) return std::numeric_limits<float>::infinity();
    if (t < -kMax) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(t);
    if (static_cast<double>(f) < t) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  }
  // The largest float <= t.
  static float float_at_or_below(double t) { return -float_at_or_above(-t); }

  ConditionSet& set_;
  std::size_t n_;
};

void check_lattice(const std::array<std::size_t, 3>& dims) {
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "extraction needs at least 2 samples along axis {} (has {})", a, dims[a]);
    }
  }
}

// Forgets the set's conditions, keeping their value buffers as spares.
void recycle_conditions(ConditionSet& set) {
  for (Condition& c : set.conditions) {
    if (!c.values.empty()) set.spare.push_back(std::move(c.values));
  }
  set.conditions.clear();
}

// Narrow (16-bit) masks when the request can make no more conditions than they hold:
// at most two per limit, one validity condition, two per bounded box axis and the
// sample conditions.
void size_masks(const ExtractRequest& request, std::size_t n, ConditionSet& set) {
  std::size_t most = 1;
  for (const ExtractLimit& limit : request.limits) {
    most += (limit.min > -kUnbounded ? 1 : 0) + (limit.max < kUnbounded ? 1 : 0);
  }
  for (const auto& [lo, hi] : request.box) most += lo == -kUnbounded && hi == kUnbounded ? 0 : 2;
  most += request.sample_conditions.size();
  set.narrow = most <= kNarrowMaskConditions;
  if (set.narrow) {
    set.inside16.resize(n);
  } else {
    set.inside64.resize(n);
  }
}

void check_limits(const NodeSamples& samples, const ExtractRequest& request) {
  const std::size_t n = samples.sample_count();
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
  }
}

// The limits' conditions. Missing samples (NaN or infinite) in any limit field make a
// validity condition; the limit conditions take the neutral value 0 there (so hold
// there: x - min >= 0 exactly when x >= min). Returns false when one holds nowhere.
bool add_limit_conditions(const NodeSamples& samples, const ExtractRequest& request, Builder& builder) {
  bool any_missing = false;
  auto add_limit = [&](const ExtractLimit& limit, bool is_min) {
    Condition c;
    c.kind = is_min ? ConditionKind::kLimitMin : ConditionKind::kLimitMax;
    c.field = limit.field;
    c.samples = samples.fields[limit.field].data();
    c.bound = is_min ? limit.min : limit.max;
    return builder.add_limit(std::move(c), is_min, any_missing);
  };
  auto has_missing = [&](const ExtractLimit& limit) {
    for (float v : samples.fields[limit.field]) {
      if (!std::isfinite(v)) return true;
    }
    return false;
  };

  bool empty = false;
  for (const ExtractLimit& limit : request.limits) {
    const bool has_min = limit.min > -kUnbounded, has_max = limit.max < kUnbounded;
    if (!empty && has_min) empty = !add_limit(limit, true);
    if (!empty && has_max) empty = !add_limit(limit, false);
    if (!empty && !has_min && !has_max) any_missing |= has_missing(limit);
  }
  if (!empty && any_missing) {
    const std::size_t n = samples.sample_count();
    Condition c;
    c.kind = ConditionKind::kValidity;
    c.values = builder.buffer();
    std::fill(c.values.begin(), c.values.end(), 1.0);
    for (const ExtractLimit& limit : request.limits) {
      const float* field = samples.fields[limit.field].data();
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(field[i])) c.values[i] = -1.0;
      }
    }
    empty = !builder.add(std::move(c));
  }
  return !empty;
}

// The domain box's conditions, two per bounded axis (none once `empty`); every axis's
// range is checked, and its ends on the node's first or last sample plane noted in
// set.box_sides. Sets `empty` when the box has no volume in the node or a condition
// holds nowhere.
void add_box_conditions(const NodeSamples& samples, const ExtractRequest& request, ConditionSet& set,
                        Builder& builder, bool& empty) {
  const auto dims = samples.dims();
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
    // lo = hi, or a box that only touches the node's face: no volume in the node, no
    // region (else the face would come out twice, as box face and node face).
    const double last_sample = static_cast<double>(coords.size() - 1);
    if (!(std::max(i_first, 0.0) < std::min(i_last, last_sample))) {
      empty = true;
      continue;
    }
    // A bound exactly on the node's first or last sample plane: the region ends on the
    // node's face there (fractional_index gives exactly 0 or the last index only for a
    // bound equal to that sample's coordinate).
    if (i_first == 0.0) set.box_sides |= static_cast<std::uint8_t>(1u << (2 * a));
    if (i_last == last_sample) set.box_sides |= static_cast<std::uint8_t>(1u << (2 * a + 1));
    for (int side = 0; side < 2 && !empty; ++side) {
      Condition c;
      c.kind = ConditionKind::kBox;
      c.axis = a;
      c.side = side;
      c.values = builder.buffer();
      std::size_t i = 0;
      for (std::size_t z = 0; z < dims[2]; ++z) {
        for (std::size_t y = 0; y < dims[1]; ++y) {
          for (std::size_t x = 0; x < dims[0]; ++x, ++i) {
            const double index = static_cast<double>(a == 0 ? x : a == 1 ? y : z);
            c.values[i] = side == 0 ? index - i_first : i_last - index;
          }
        }
      }
      empty = !builder.add(std::move(c));
    }
  }
}

// The request's per-sample conditions (none once `empty`).
void add_sample_conditions(const ExtractRequest& request, std::size_t n, Builder& builder, bool& empty) {
  for (std::size_t k = 0; k < request.sample_conditions.size() && !empty; ++k) {
    const auto& given = request.sample_conditions[k];
    if (given.size() != n) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "sample condition {} holds {} values, the node has {} samples", k,
                       given.size(), n);
    }
    Condition c;
    c.kind = ConditionKind::kSample;
    c.values = builder.buffer();
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(given[i])) {
        throw make_error(ErrorCode::kInvalidArgument, "sample condition {} is not finite at sample {}",
                         k, i);
      }
      c.values[i] = given[i];
    }
    empty = !builder.add(std::move(c));
  }
}

// The set's final state: empty (no conditions), every condition holding everywhere (no
// conditions, masks zero), or `all` with a bit per condition.
void finish_conditions(const ExtractRequest& request, std::size_t n, bool empty, ConditionSet& set) {
  if (set.conditions.size() > kMaxConditions) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sub-volume {} needs {} conditions in one node (at most {})",
                     request.subvolume_id, set.conditions.size(), kMaxConditions);
  }
  set.empty = empty;
  if (empty) {
    recycle_conditions(set);
    return;
  }
  if (set.conditions.empty()) {  // every condition holds everywhere
    std::fill_n(set.inside16.begin(), set.narrow ? n : 0, 0);
    std::fill_n(set.inside64.begin(), set.narrow ? 0 : n, 0);
    return;
  }
  set.all = set.conditions.size() >= 64 ? ~std::uint64_t{0}
                                        : (std::uint64_t{1} << set.conditions.size()) - 1;
}

}  // namespace

ConditionSet build_conditions(const NodeSamples& samples, const ExtractRequest& request) {
  ConditionSet set;
  build_conditions(samples, request, set);
  return set;
}

void build_conditions(const NodeSamples& samples, const ExtractRequest& request,
                      ConditionSet& set) {
  check_lattice(samples.dims());
  const std::size_t n = samples.sample_count();
  recycle_conditions(set);
  set.empty = false;
  set.all = 0;
  set.box_sides = 0;
  size_masks(request, n, set);
  Builder builder(set, n);
  check_limits(samples, request);
  bool empty = !add_limit_conditions(samples, request, builder);
  add_box_conditions(samples, request, set, builder, empty);
  add_sample_conditions(request, n, builder, empty);
  finish_conditions(request, n, empty, set);
}

}  // namespace strielad
