// SPDX-License-Identifier: Apache-2.0
// What the viewer's legends show: the sub-volume palette entries (view/subvolume_palette.h)
// and the value ranges of the shown slices (view/slice_ranges.h).
#include "view/subvolume_palette.h"
#include "view/slice_ranges.h"

#include <algorithm>

#include <fmt/format.h>

#include "view/node_geometry.h"

namespace strielad::view {

PaletteColor subvolume_palette_color(std::size_t slot) {
  return kSubVolumePalette[slot % kSubVolumePaletteSize];
}

std::vector<LegendEntry> subvolume_legend(const Scene& scene) {
  std::vector<LegendEntry> legend;
  legend.reserve(scene.subvolumes.size());
  for (std::size_t slot = 0; slot < scene.subvolumes.size(); ++slot) {
    const auto& s = scene.subvolumes[slot];
    legend.push_back({s.id, s.name.empty() ? fmt::format("sub-volume {}", s.id) : s.name,
                      subvolume_palette_color(slot), slot < kMaxViewSubVolumes});
  }
  return legend;
}

std::vector<std::optional<SliceRange>> shown_slice_ranges(const ProgressiveMeshes& meshes,
                                                          std::size_t slice_count) {
  std::vector<std::optional<SliceRange>> ranges(slice_count);
  const std::size_t slots = std::min(slice_count, kMaxViewSlices);
  for (const auto& [node, entry] : meshes.entries()) {
    if (!entry.mesh) continue;
    for (std::size_t s = 0; s < slots; ++s) {
      const auto& node_range = entry.mesh->slice_value_ranges[s];
      if (!(node_range[0] <= node_range[1])) continue;  // no finite value in this node
      auto& r = ranges[s];
      r = r ? SliceRange{std::min((*r)[0], node_range[0]), std::max((*r)[1], node_range[1])}
            : SliceRange{node_range[0], node_range[1]};
    }
  }
  return ranges;
}

}  // namespace strielad::view
