// SPDX-License-Identifier: Apache-2.0
// The sub-volume palette (lib/view/subvolume_palette.h): its 32 colours stay apart even
// when one is in shadow and the other in the sun, only the first is grey, none is too
// dark for the background, and the legend gives each sub-volume its slot's colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "view/subvolume_palette.h"

namespace strielad::view {
namespace {

using Lab = std::array<double, 3>;

// CIE L*a*b* (D65) of an sRGB colour.
Lab to_lab(const PaletteColor& c, double shade = 1.0) {
  std::array<double, 3> lin{};
  for (int i = 0; i < 3; ++i) {
    const double v = std::min(1.0, c[i] * shade);
    lin[i] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  const double x = (0.4124 * lin[0] + 0.3576 * lin[1] + 0.1805 * lin[2]) / 0.95047;
  const double y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
  const double z = (0.0193 * lin[0] + 0.1192 * lin[1] + 0.9505 * lin[2]) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

double distance(const Lab& a, const Lab& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The nearest two shadings (50 to 100% of the brightness) of two colours come.
double shaded_distance(const PaletteColor& a, const PaletteColor& b) {
  double d = INFINITY;
  for (const double sa : {0.5, 0.65, 0.8, 1.0}) {
    for (const double sb : {0.5, 0.65, 0.8, 1.0}) d = std::min(d, distance(to_lab(a, sa), to_lab(b, sb)));
  }
  return d;
}

double nearest_pair(std::size_t count) {
  double d = INFINITY;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count; ++j) {
      d = std::min(d, shaded_distance(kSubVolumePalette[i], kSubVolumePalette[j]));
    }
  }
  return d;
}

TEST(SubVolumePaletteTest, EveryViewerSlotHasItsOwnColour) {
  ASSERT_EQ(kSubVolumePaletteSize, kMaxViewSubVolumes);
  std::set<PaletteColor> distinct(kSubVolumePalette.begin(), kSubVolumePalette.end());
  EXPECT_EQ(distinct.size(), kMaxViewSubVolumes);
}

TEST(SubVolumePaletteTest, ColoursStayApartInSunAndShadow) {
  EXPECT_GE(nearest_pair(3), 25.0);   // the default scene's cloud water, ice and rain
  EXPECT_GE(nearest_pair(16), 19.0);
  EXPECT_GE(nearest_pair(kSubVolumePaletteSize), 14.0);
}

TEST(SubVolumePaletteTest, OnlyTheFirstIsGreyAndNoneIsDark) {
  for (std::size_t i = 0; i < kSubVolumePaletteSize; ++i) {
    const Lab lab = to_lab(kSubVolumePalette[i]);
    EXPECT_GE(lab[0], 45.0) << i;
    const double chroma = std::hypot(lab[1], lab[2]);
    if (i == 0) {
      EXPECT_LT(chroma, 2.0);
      EXPECT_GT(lab[0], 95.0);  // white: cloud water looks like cloud
    } else {
      EXPECT_GE(chroma, 25.0) << i;
    }
  }
}

TEST(SubVolumePaletteTest, SlotsBeyondThePaletteRepeatIt) {
  EXPECT_EQ(subvolume_palette_color(0), kSubVolumePalette[0]);
  EXPECT_EQ(subvolume_palette_color(31), kSubVolumePalette[31]);
  EXPECT_EQ(subvolume_palette_color(32), kSubVolumePalette[0]);
  EXPECT_EQ(subvolume_palette_color(45), kSubVolumePalette[13]);
}

TEST(SubVolumePaletteTest, LegendGivesEachSubVolumeItsSlotsColour) {
  Scene scene;
  for (std::uint32_t i = 0; i < 34; ++i) {
    SubVolume s;
    s.id = 100 - i;  // ids in any order: the slot (scene order) picks the colour
    if (i != 1) s.name = "layer " + std::to_string(i);
    scene.subvolumes.push_back(s);
  }
  const auto legend = subvolume_legend(scene);
  ASSERT_EQ(legend.size(), 34u);
  EXPECT_EQ(legend[0].id, 100u);
  EXPECT_EQ(legend[0].label, "layer 0");
  EXPECT_EQ(legend[0].color, kSubVolumePalette[0]);
  EXPECT_EQ(legend[1].label, "sub-volume 99");
  EXPECT_EQ(legend[2].color, kSubVolumePalette[2]);
  EXPECT_TRUE(legend[31].drawn);
  EXPECT_EQ(legend[31].color, kSubVolumePalette[31]);
  EXPECT_FALSE(legend[32].drawn);  // beyond the viewer's 32 slots
  EXPECT_FALSE(legend[33].drawn);
}

}  // namespace
}  // namespace strielad::view
