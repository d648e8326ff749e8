// SPDX-License-Identifier: Apache-2.0
// One node's brick of samples as read from a store (formats/store.md, "Brick kinds").
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#include "core/error.h"
#include "format/step_file_format.h"
#include "grid/axis.h"
#include "octree/octree_layout.h"

namespace strielad {

struct Brick {
  NodeId node = 0;
  IndexBox box;                        // samples in the node's level grid (inclusive)
  std::array<std::size_t, 3> dims{};   // samples along x, y, z
  DType dtype = DType::kFloat32;
  format::BrickKind kind = format::BrickKind::kEmpty;
  double constant = 0;                 // value of a constant brick
  std::vector<std::byte> bytes;        // samples of a data brick (x fastest); empty otherwise

  std::size_t sample_count() const { return dims[0] * dims[1] * dims[2]; }
  std::size_t memory_bytes() const { return sizeof(Brick) + bytes.capacity(); }

  // Sample i as double; NaN when missing. Works for every kind.
  double sample(std::size_t i) const {
    switch (kind) {
      case format::BrickKind::kEmpty: return std::nan("");
      case format::BrickKind::kConstant: return constant;
      case format::BrickKind::kData: break;
    }
    if (dtype == DType::kFloat32) {
      float v;
      std::memcpy(&v, bytes.data() + i * 4, 4);
      return v;
    }
    double v;
    std::memcpy(&v, bytes.data() + i * 8, 8);
    return v;
  }

  // All samples converted to T (missing = NaN), for every kind.
  template <typename T>
  std::vector<T> to_vector() const {
    std::vector<T> out(sample_count());
    if (kind == format::BrickKind::kData &&
        dtype == kDTypeOf<T>) {
      std::memcpy(out.data(), bytes.data(), bytes.size());
    } else {
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<T>(sample(i));
    }
    return out;
  }
};

}  // namespace strielad
