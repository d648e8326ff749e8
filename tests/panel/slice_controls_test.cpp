// SPDX-License-Identifier: Apache-2.0
// The panel's attribute and slice controls, driven with synthetic input.
#include <gtest/gtest.h>

#include "panel/panel_driver.h"

namespace strielad::testing {
namespace {

TEST(PanelSliceControlsTest, AddSliceWithDefaults) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  ASSERT_TRUE(panel.state().scene.slices.empty());
  panel.click("add slice");
  ASSERT_EQ(panel.state().scene.slices.size(), 1u);
  const Slice& s = panel.state().scene.slices[0];
  EXPECT_EQ(s.id, 1u);
  EXPECT_EQ(s.axis, "height");
  EXPECT_DOUBLE_EQ(s.value, 5000);
  EXPECT_EQ(s.var, "clw");
  EXPECT_EQ(s.colormap, "viridis");
  EXPECT_FALSE(s.range.has_value());
  EXPECT_TRUE(panel.state().scene_changed);
}

TEST(PanelSliceControlsTest, MoveSliceWithinItsAxis) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.click("add slice");
  panel.state().scene_changed = false;
  panel.slide("slice 1 value", 0.0f);
  EXPECT_TRUE(panel.state().scene_changed);
  EXPECT_DOUBLE_EQ(panel.state().scene.slices[0].value, 0);
  panel.pick("slice 1 axis", "slice 1 axis lon");
  EXPECT_EQ(panel.state().scene.slices[0].axis, "lon");
  EXPECT_DOUBLE_EQ(panel.state().scene.slices[0].value, 5);
  panel.slide("slice 1 value", 1.0f);
  EXPECT_DOUBLE_EQ(panel.state().scene.slices[0].value, 10);
}

TEST(PanelSliceControlsTest, VariableColourMapAndRange) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.click("add slice");
  panel.pick("slice 1 variable", "slice 1 variable ta");
  EXPECT_EQ(panel.state().scene.slices[0].var, "ta");
  panel.pick("slice 1 colormap", "slice 1 colormap turbo");
  EXPECT_EQ(panel.state().scene.slices[0].colormap, "turbo");
  panel.click("slice 1 range on");
  EXPECT_EQ(panel.state().scene.slices[0].range, (AxisRange{200, 300}));
  panel.type("slice 1 range lo", "250");
  EXPECT_EQ(panel.state().scene.slices[0].range, (AxisRange{250, 300}));
  EXPECT_TRUE(panel.state().scene_changed);
  // lo >= hi is refused, shown, not applied.
  panel.state().scene_changed = false;
  panel.type("slice 1 range lo", "400");
  EXPECT_FALSE(panel.state().scene_changed);
  EXPECT_FALSE(panel.state().scene_error.empty());
  panel.click("slice 1 range on");
  EXPECT_FALSE(panel.state().scene.slices[0].range.has_value());
  EXPECT_TRUE(panel.state().scene_changed);
}

TEST(PanelSliceControlsTest, RemoveSlice) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.click("add slice");
  panel.click("add slice");
  ASSERT_EQ(panel.state().scene.slices.size(), 2u);
  EXPECT_EQ(panel.state().scene.slices[1].id, 2u);
  panel.click("slice 1 remove");
  ASSERT_EQ(panel.state().scene.slices.size(), 1u);
  EXPECT_EQ(panel.state().scene.slices[0].id, 2u);
}

TEST(PanelSliceControlsTest, AddAndRemoveAttributes) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  ASSERT_EQ(panel.state().scene.attributes, std::vector<std::string>{"ta"});
  panel.click("attribute ta remove");
  EXPECT_TRUE(panel.state().scene.attributes.empty());
  EXPECT_TRUE(panel.state().scene_changed);
  panel.pick("add attribute", "add attribute clw");
  EXPECT_EQ(panel.state().scene.attributes, std::vector<std::string>{"clw"});
}

}  // namespace
}  // namespace strielad::testing
