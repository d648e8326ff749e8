// SPDX-License-Identifier: Apache-2.0
#include "view/slice_ranges.h"

#include <algorithm>
#include <cmath>

#include "view/node_geometry.h"

namespace strielad::view {

std::vector<std::optional<SliceRange>> shown_slice_ranges(const ProgressiveMeshes& meshes,
                                                          std::size_t slice_count) {
  std::vector<std::optional<SliceRange>> ranges(slice_count);
  for (const auto& [node, entry] : meshes.entries()) {
    if (!entry.mesh) continue;
    const auto& v = entry.mesh->slice_vertices;
    for (std::size_t i = 0; i + kSliceVertexFloats <= v.size(); i += kSliceVertexFloats) {
      const float value = v[i + kSliceVertexValue];
      const float slot = v[i + kSliceVertexSlot];
      if (!std::isfinite(value) || !(slot >= 0) || slot >= float(slice_count)) continue;
      auto& r = ranges[static_cast<std::size_t>(slot)];
      if (!r) r = SliceRange{value, value};
      else r = SliceRange{std::min((*r)[0], value), std::max((*r)[1], value)};
    }
  }
  return ranges;
}

}  // namespace strielad::view
