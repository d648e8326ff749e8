// SPDX-License-Identifier: Apache-2.0
// Raw netCDF samples to values, the CF way: a sample is missing (NaN) when it equals
// _FillValue (or, without one, the netCDF default fill), any missing_value, or lies
// outside valid_min/valid_max; all compared in the raw (packed) type before unpacking.
// Then value * scale_factor + add_offset in double, stored in the output type (a value
// beyond that type's range is reported). NaN/Inf that is not declared missing is
// reported (or masked when nan_as_fill), and so is a 64-bit integer that a double cannot
// hold exactly (beyond 2^53). `raw` and `out` may be the same memory when Raw is Out
// (in-place conversion of a buffer that netCDF filled).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "ingest/variable_meta.h"

namespace strielad::ingest {

struct ConversionResult {
  // First sample that is NaN/Inf without being declared missing (only reported when
  // nan_as_fill is false; it is set to NaN in the output either way).
  std::optional<std::size_t> first_non_finite;
  double non_finite_value = 0;
  // First sample whose unpacked value (raw * scale_factor + add_offset) lies beyond the
  // output type's range: set to NaN in the output, and always an error for the caller
  // (the store holds only finite values; --nan-as-fill does not apply).
  std::optional<std::size_t> first_overflow;
  double overflow_raw = 0, overflow_value = 0;
  // First valid sample of a 64-bit integer type that a double cannot hold exactly (its
  // significant bits span more than 53): set to NaN in the output, and always an error
  // for the caller (the store keeps values exactly or not at all).
  std::optional<std::size_t> first_inexact;
  std::string inexact_raw;  // its value in decimal
};

namespace detail {

// `v` as a Raw value when a Raw can hold it exactly (integers), or rounded (floats).
template <typename Raw>
std::optional<Raw> as_raw(long double v) {
  if constexpr (std::is_floating_point_v<Raw>) {
    return static_cast<Raw>(v);
  } else {
    if (!std::isfinite(v) || v != std::floor(v)) return std::nullopt;
    if (v < static_cast<long double>(std::numeric_limits<Raw>::min()) ||
        v > static_cast<long double>(std::numeric_limits<Raw>::max())) {
      return std::nullopt;
    }
    return static_cast<Raw>(v);
  }
}

template <typename Raw>
inline constexpr Raw kNaNRawImpl = std::numeric_limits<Raw>::quiet_NaN();

// Whether the integer `r` is exactly a double: its significant bits span at most 53.
template <typename Int>
bool exact_in_double(Int r) {
  using U = std::make_unsigned_t<Int>;
  U magnitude = static_cast<U>(r);
  if constexpr (std::is_signed_v<Int>) {
    if (r < 0) magnitude = static_cast<U>(U{0} - magnitude);  // INT64_MIN: 2^63, exact
  }
  if (magnitude == 0) return true;
  return std::bit_width(magnitude) - static_cast<unsigned>(std::countr_zero(magnitude)) <=
         static_cast<unsigned>(std::numeric_limits<double>::digits);
}

}  // namespace detail

// A NaN of a floating raw type: compares unequal to everything, so an absent fill value
// never matches.
template <typename Raw>
inline constexpr Raw kNaNRaw = detail::kNaNRawImpl<Raw>;

namespace detail {

// Which raw samples are missing: fill values (and NaN, when declared), and the valid range,
// compared in Cmp: integers of 64 bits in long double (exact), the rest in double.
template <typename Raw>
struct MissingRule {
  using Cmp = std::conditional_t<std::is_integral_v<Raw> && sizeof(Raw) == 8, long double, double>;
  std::vector<Raw> fills;
  bool nan_is_missing = false;
  bool has_min = false, has_max = false;
  Cmp vmin{}, vmax{};

  explicit MissingRule(const CfValueAttributes& attrs) {
    if (attrs.fill_value) add_fill(*attrs.fill_value);
    if (attrs.default_fill) add_fill(*attrs.default_fill);
    for (long double m : attrs.missing_values) add_fill(m);
    has_min = attrs.valid_min.has_value() && !std::isnan(*attrs.valid_min);
    has_max = attrs.valid_max.has_value() && !std::isnan(*attrs.valid_max);
    if (has_min) vmin = static_cast<Cmp>(*attrs.valid_min);
    if (has_max) vmax = static_cast<Cmp>(*attrs.valid_max);
  }

  bool is_missing(Raw r) const {
    bool missing = false;
    for (Raw f : fills) missing = missing || r == f;
    if constexpr (std::is_floating_point_v<Raw>) missing = missing || (nan_is_missing && std::isnan(r));
    if (has_min && static_cast<Cmp>(r) < vmin) missing = true;
    if (has_max && static_cast<Cmp>(r) > vmax) missing = true;
    return missing;
  }

 private:
  void add_fill(long double v) {
    if (std::isnan(v)) {
      nan_is_missing = true;
    } else if (auto r = as_raw<Raw>(v)) {
      fills.push_back(*r);
    }
  }
};

// The fast path for the common case (model output): unpacked floating-point data with at
// most two fill values and no valid range. Same result as convert_each_sample.
template <typename Raw, typename Out>
ConversionResult convert_unpacked_floats(std::span<const Raw> raw, const MissingRule<Raw>& rule,
                                         bool nan_as_fill, std::span<Out> out) {
  constexpr Out kNaN = std::numeric_limits<Out>::quiet_NaN();
  ConversionResult result;
  const Raw f0 = rule.fills.empty() ? kNaNRawImpl<Raw> : rule.fills[0];
  const Raw f1 = rule.fills.size() < 2 ? f0 : rule.fills[1];
  // Branch-free passes over blocks that stay in L1: one finds whether the block holds
  // an undeclared NaN/Inf (then it is located while the block is still intact), the
  // next writes the block. Both written with bitwise operators on unsigned flags, not
  // && and ||: GCC 12 vectorizes them only so (short-circuit operators are control
  // flow, and the loop stays scalar at 3x the cost). `raw` and `out` may be the same
  // memory (in-place conversion).
  const Raw* src = raw.data();
  Out* dst = out.data();
  const std::size_t n = raw.size();
  const unsigned nan_missing = rule.nan_is_missing ? 1u : 0u;
  auto finite = [](Raw r) -> unsigned { return r - r == Raw(0) ? 1u : 0u; };  // 0: NaN, +-Inf
  auto missing = [f0, f1, nan_missing](Raw r) -> unsigned {
    return static_cast<unsigned>(r == f0) | static_cast<unsigned>(r == f1) |
           (nan_missing & static_cast<unsigned>(r != r));
  };
  constexpr std::size_t kBlock = 2048;
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t e = std::min(n, b + kBlock);
    if (!nan_as_fill && !result.first_non_finite) {
      unsigned undeclared = 0;
      for (std::size_t i = b; i < e; ++i) undeclared |= (missing(src[i]) ^ 1u) & (finite(src[i]) ^ 1u);
      for (std::size_t i = b; undeclared != 0 && i < e; ++i) {
        if (((missing(src[i]) ^ 1u) & (finite(src[i]) ^ 1u)) != 0) {
          result.first_non_finite = i;
          result.non_finite_value = static_cast<double>(src[i]);
          break;
        }
      }
    }
    for (std::size_t i = b; i < e; ++i) {
      const Raw r = src[i];
      dst[i] = (missing(r) | (finite(r) ^ 1u)) != 0 ? kNaN : static_cast<Out>(r);
    }
  }
  return result;
}

// The general path: any raw type, packed or not, with any fill values and valid range.
template <typename Raw, typename Out>
ConversionResult convert_each_sample(std::span<const Raw> raw, const MissingRule<Raw>& rule,
                                     const CfValueAttributes& attrs, bool nan_as_fill,
                                     std::span<Out> out) {
  constexpr bool kWideInteger = std::is_integral_v<Raw> && sizeof(Raw) == 8;
  constexpr Out kNaN = std::numeric_limits<Out>::quiet_NaN();
  const bool packed = attrs.packed();
  const double scale = attrs.scale_factor.value_or(1.0);
  const double offset = attrs.add_offset.value_or(0.0);
  ConversionResult result;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const Raw r = raw[i];
    if (rule.is_missing(r)) {
      out[i] = kNaN;
      continue;
    }
    if constexpr (std::is_floating_point_v<Raw>) {
      if (!std::isfinite(r)) {
        out[i] = kNaN;
        if (!nan_as_fill && !result.first_non_finite) {
          result.first_non_finite = i;
          result.non_finite_value = static_cast<double>(r);
        }
        continue;
      }
    }
    if constexpr (kWideInteger) {
      // Unpacking starts from the raw value as a double: one it cannot hold would be
      // rounded (2^53 + 1 stored as 2^53), packed or not.
      if (!exact_in_double(r)) {
        out[i] = kNaN;
        if (!result.first_inexact) {
          result.first_inexact = i;
          result.inexact_raw = std::to_string(r);
        }
        continue;
      }
    }
    if (packed) {
      const double unpacked = static_cast<double>(r) * scale + offset;
      out[i] = static_cast<Out>(unpacked);
      if (!std::isfinite(out[i])) {
        out[i] = kNaN;
        if (!result.first_overflow) {
          result.first_overflow = i;
          result.overflow_raw = static_cast<double>(r);
          result.overflow_value = unpacked;
        }
      }
    } else {
      out[i] = static_cast<Out>(r);
    }
  }
  return result;
}

}  // namespace detail

template <typename Raw, typename Out>
ConversionResult convert_samples(std::span<const Raw> raw, const CfValueAttributes& attrs,
                                 bool nan_as_fill, std::span<Out> out) {
  check_usable(attrs);  // throws: scale_factor 0, an empty valid range...
  const detail::MissingRule<Raw> rule(attrs);
  if constexpr (std::is_floating_point_v<Raw>) {
    if (!attrs.packed() && !rule.has_min && !rule.has_max && rule.fills.size() <= 2) {
      return detail::convert_unpacked_floats<Raw, Out>(raw, rule, nan_as_fill, out);
    }
  }
  return detail::convert_each_sample<Raw, Out>(raw, rule, attrs, nan_as_fill, out);
}

}  // namespace strielad::ingest
