// SPDX-License-Identifier: Apache-2.0
// Small helpers for tests of brick chunk codecs: sample bit types, dtypes and byte views.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad::testing {

// The unsigned integer of a sample's width (its IEEE 754 bits).
template <typename T>
using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

constexpr DType dtype_of(float) { return DType::kFloat32; }
constexpr DType dtype_of(double) { return DType::kFloat64; }

inline std::size_t count(BrickDims d) { return d[0] * d[1] * d[2]; }

template <typename T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
  return {reinterpret_cast<const std::byte*>(v.data()), v.size() * sizeof(T)};
}

}  // namespace strielad::testing
