// SPDX-License-Identifier: Apache-2.0
// The panel's sub-volume controls, driven with synthetic input: add and remove, limits,
// the axis box (sliders bounded by the axes) and the geographic box; an edit the store
// would refuse is shown and not applied.
#include <gtest/gtest.h>

#include "panel/panel_driver.h"

namespace strielad::testing {
namespace {

std::string sv(std::uint32_t id, const std::string& rest) {
  return "subvolume " + std::to_string(id) + " " + rest;
}

TEST(PanelSubVolumeControlsTest, AddAndRemoveSubVolume) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  const std::size_t before = panel.state().scene.subvolumes.size();
  panel.click("add subvolume");
  auto& subs = panel.state().scene.subvolumes;
  ASSERT_EQ(subs.size(), before + 1);
  EXPECT_TRUE(panel.state().scene_changed);
  const auto added = subs.back();
  EXPECT_EQ(added.limits.size(), 1u);
  EXPECT_EQ(added.limits[0].var, "clw");
  EXPECT_DOUBLE_EQ(*added.limits[0].min, 0.0005);
  panel.state().scene_changed = false;
  panel.click(sv(added.id, "remove"));
  EXPECT_EQ(panel.state().scene.subvolumes.size(), before);
  EXPECT_TRUE(panel.state().scene_changed);
}

TEST(PanelSubVolumeControlsTest, TypedNameIsApplied) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.type(sv(id, "name"), "thick cloud");
  EXPECT_EQ(panel.state().scene.subvolumes[0].name, "thick cloud");
  EXPECT_TRUE(panel.state().scene_changed);
}

TEST(PanelSubVolumeControlsTest, TypedLimitIsApplied) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.type(sv(id, "limit 0 min"), "0.0002");
  EXPECT_TRUE(panel.state().scene_changed);
  EXPECT_DOUBLE_EQ(*panel.state().scene.subvolumes[0].limits[0].min, 0.0002);
}

TEST(PanelSubVolumeControlsTest, LimitVariableAndAddedLimit) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.click(sv(id, "add limit"));
  ASSERT_EQ(panel.state().scene.subvolumes[0].limits.size(), 2u);
  panel.pick(sv(id, "limit 1 variable"), sv(id, "limit 1 variable ta"));
  EXPECT_EQ(panel.state().scene.subvolumes[0].limits[1].var, "ta");
  panel.click(sv(id, "limit 1 max on"));
  EXPECT_DOUBLE_EQ(*panel.state().scene.subvolumes[0].limits[1].max, 275.0);
  panel.click(sv(id, "limit 1 remove"));
  EXPECT_EQ(panel.state().scene.subvolumes[0].limits.size(), 1u);
}

TEST(PanelSubVolumeControlsTest, AxisBoxSlidersStayWithinTheAxis) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.click(sv(id, "box height on"));
  auto domain = [&] { return panel.state().scene.subvolumes[0].domain; };
  ASSERT_TRUE(domain().contains("height"));
  EXPECT_EQ(domain().at("height"), (AxisRange{0, 10000}));
  EXPECT_TRUE(panel.state().scene_changed);
  panel.state().scene_changed = false;
  panel.slide(sv(id, "box height lo"), 0.5f);
  EXPECT_TRUE(panel.state().scene_changed);
  EXPECT_GT(domain().at("height").lo, 3000);
  EXPECT_LT(domain().at("height").lo, 7000);
  EXPECT_EQ(domain().at("height").hi, 10000);
  // Beyond the slider's end: held at the axis's end.
  panel.slide(sv(id, "box height hi"), 1.5f);
  EXPECT_EQ(domain().at("height").hi, 10000);
  EXPECT_FALSE(panel.has(sv(id, "box lon hi")));  // not on: no slider
  EXPECT_FALSE(domain().contains("lon"));
  panel.click(sv(id, "box height on"));
  EXPECT_FALSE(domain().contains("height"));
}

TEST(PanelSubVolumeControlsTest, GeographicBoxOnlyOnTheEarth) {
  const auto m = panel_manifest();
  {
    PanelDriver panel(m, panel_state(m));
    EXPECT_FALSE(panel.has(sv(panel.state().scene.subvolumes[0].id, "geographic on")));
  }
  panel::PanelInfo info;
  info.on_earth = true;
  PanelDriver panel(m, panel_state(m), info);
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.click(sv(id, "geographic on"));
  const auto& geo = panel.state().scene.subvolumes[0].geographic;
  ASSERT_TRUE(geo.has_value());
  EXPECT_EQ(geo->lon, (AxisRange{0, 10}));
  EXPECT_EQ(geo->lat, (AxisRange{40, 50}));
  EXPECT_TRUE(panel.state().scene_changed);
  panel.click(sv(id, "geographic height on"));
  EXPECT_EQ(geo->height, (AxisRange{0, 10000}));
  panel.slide(sv(id, "geographic lat hi"), 0.0f);
  EXPECT_EQ(geo->lat, (AxisRange{40, 40}));
}

TEST(PanelSubVolumeControlsTest, InvalidEditIsShownNotApplied) {
  const auto m = panel_manifest();
  panel::PanelInfo info;
  info.on_earth = true;
  PanelDriver panel(m, panel_state(m), info);
  const auto id = panel.state().scene.subvolumes[0].id;
  panel.click(sv(id, "geographic on"));
  panel.click(sv(id, "geographic lon on"));
  EXPECT_TRUE(panel.state().scene_changed);
  panel.state().scene_changed = false;  // applied by the viewer
  // A geographic box with neither longitude, latitude nor height is refused.
  panel.click(sv(id, "geographic lat on"));
  EXPECT_FALSE(panel.state().scene_changed);
  EXPECT_NE(panel.state().scene_error.find("geographic"), std::string::npos)
      << panel.state().scene_error;
  panel.click(sv(id, "geographic lat on"));
  EXPECT_TRUE(panel.state().scene_changed);
  EXPECT_TRUE(panel.state().scene_error.empty());
}

}  // namespace
}  // namespace strielad::testing
