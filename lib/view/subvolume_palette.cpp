// SPDX-License-Identifier: Apache-2.0
#include "view/subvolume_palette.h"

#include <fmt/format.h>

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

}  // namespace strielad::view
