// SPDX-License-Identifier: Apache-2.0
// The colours sub-volumes get by default (docs/view.md "User shaders"): the n-th
// sub-volume of the scene (its slot, view/node_geometry.h) gets the n-th colour of a
// qualitative palette of kMaxViewSubVolumes = 32 colours, so no two sub-volumes the viewer
// shows share a colour. The built-in shader (examples/shaders/clouds.glsl) and the
// panel's legend both take them from here; user shaders get them as subvolume_color(id).
//
// The palette: white first (cloud water in the default scene looks like cloud), then the
// colour-blind-safe qualitative colours of Okabe and Ito (2008) without their black and
// their blue (too close to sky blue once shaded), then colours chosen one by one, each
// the sRGB colour (on a lattice of steps of 1/12, CIE L* >= 45 so that shaded sides stay
// visible on the dark background, chroma >= 25 so that only the first is grey) farthest
// from all before it. Distances are CIE76 colour differences between the colours shaded
// to 50, 65, 80 and 100 percent of their brightness, the nearest pair of shadings
// counting, so that a colour in shadow does not pass for a darker one in the sun: at
// least 25.8 among the first 3, 19.5 among the first 16 and 14.2 among all 32
// (tests/view/subvolume_palette_test.cpp). Earlier colours are the more distinct ones.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "view/node_geometry.h"

namespace strielad::view {

inline constexpr std::size_t kSubVolumePaletteSize = kMaxViewSubVolumes;

// sRGB components in 0..1, as the shaders write them.
using PaletteColor = std::array<float, 3>;

inline constexpr std::array<PaletteColor, kSubVolumePaletteSize> kSubVolumePalette{{
    {0.950f, 0.950f, 0.950f},  //  0 #f2f2f2
    {0.337f, 0.706f, 0.914f},  //  1 #56b4e9
    {0.902f, 0.624f, 0.000f},  //  2 #e69f00
    {0.000f, 0.620f, 0.451f},  //  3 #009e73
    {0.941f, 0.894f, 0.259f},  //  4 #f0e442
    {0.835f, 0.369f, 0.000f},  //  5 #d55e00
    {0.800f, 0.475f, 0.655f},  //  6 #cc79a7
    {0.667f, 0.000f, 1.000f},  //  7 #aa00ff
    {0.000f, 1.000f, 0.000f},  //  8 #00ff00
    {1.000f, 0.000f, 0.333f},  //  9 #ff0055
    {0.000f, 0.417f, 1.000f},  // 10 #006aff
    {1.000f, 0.000f, 0.750f},  // 11 #ff00bf
    {0.833f, 0.583f, 0.417f},  // 12 #d4956a
    {0.833f, 1.000f, 0.667f},  // 13 #d4ffaa
    {0.750f, 0.417f, 0.917f},  // 14 #bf6aea
    {1.000f, 0.000f, 0.000f},  // 15 #ff0000
    {0.667f, 1.000f, 0.333f},  // 16 #aaff55
    {0.417f, 1.000f, 1.000f},  // 17 #6affff
    {0.417f, 0.417f, 0.667f},  // 18 #6a6aaa
    {1.000f, 0.417f, 0.417f},  // 19 #ff6a6a
    {0.000f, 1.000f, 0.417f},  // 20 #00ff6a
    {1.000f, 0.250f, 0.583f},  // 21 #ff4095
    {1.000f, 0.083f, 1.000f},  // 22 #ff15ff
    {0.833f, 1.000f, 0.000f},  // 23 #d4ff00
    {0.500f, 0.333f, 1.000f},  // 24 #8055ff
    {1.000f, 0.833f, 1.000f},  // 25 #ffd4ff
    {0.917f, 0.833f, 0.500f},  // 26 #ead480
    {1.000f, 0.417f, 0.833f},  // 27 #ff6ad4
    {0.500f, 0.917f, 0.500f},  // 28 #80ea80
    {0.000f, 0.583f, 1.000f},  // 29 #0095ff
    {0.583f, 0.917f, 0.750f},  // 30 #95eabf
    {1.000f, 0.667f, 0.667f},  // 31 #ffaaaa
}};

// The colour of slot `slot`; slots beyond the palette (which the viewer never draws:
// it keeps kMaxViewSubVolumes slots) take its colours again from the start.
PaletteColor subvolume_palette_color(std::size_t slot);

// One line of the panel's legend.
struct LegendEntry {
  std::uint32_t id = 0;
  std::string label;   // the sub-volume's name, or "sub-volume <id>" when it has none
  PaletteColor color{};
  bool drawn = true;   // false beyond the viewer's kMaxViewSubVolumes slots
};

// The legend of `scene`'s sub-volumes, in scene order.
std::vector<LegendEntry> subvolume_legend(const Scene& scene);

}  // namespace strielad::view
