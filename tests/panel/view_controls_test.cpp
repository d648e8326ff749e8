// SPDX-License-Identifier: Apache-2.0
// The panel's time and view controls, driven with synthetic input: each raises its flag
// and changes its value within the control's range.
#include <gtest/gtest.h>

#include "panel/panel_driver.h"

namespace strielad::testing {
namespace {

TEST(PanelViewControlsTest, LodThresholdSliderSetsThresholdAndFlag) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.slide("lod threshold", 0.98f);
  EXPECT_TRUE(panel.state().lod_changed);
  EXPECT_GT(panel.state().lod_threshold_sr, 0.1f);
  EXPECT_LE(panel.state().lod_threshold_sr, 0.2f);
  panel.state().lod_changed = false;
  panel.slide("lod threshold", 0.0f);
  EXPECT_TRUE(panel.state().lod_changed);
  EXPECT_NEAR(panel.state().lod_threshold_sr, 0.0005f, 1e-4f);
}

TEST(PanelViewControlsTest, MaxNodesSliderSetsLimit) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.slide("max nodes", 0.0f);
  EXPECT_TRUE(panel.state().lod_changed);
  EXPECT_EQ(panel.state().max_nodes, 1);
}

TEST(PanelViewControlsTest, LodFadeSliderSetsTheFadeTime) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  EXPECT_EQ(panel.state().lod_fade_ms, 300.0f);
  panel.slide("lod fade", 0.0f);
  EXPECT_EQ(panel.state().lod_fade_ms, 0.0f);
  panel.slide("lod fade", 1.0f);
  EXPECT_GT(panel.state().lod_fade_ms, 1900.0f);
  EXPECT_LE(panel.state().lod_fade_ms, 2000.0f);
}

TEST(PanelViewControlsTest, ExaggerationSliderSetsExaggeration) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.slide("exaggeration", 1.0f);
  EXPECT_TRUE(panel.state().exaggeration_changed);
  EXPECT_GT(panel.state().exaggeration, 500.0f);
  EXPECT_LE(panel.state().exaggeration, 1000.0f);
}

TEST(PanelViewControlsTest, TimeStepSliderAndPlay) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.slide("time step", 1.0f);
  EXPECT_TRUE(panel.state().time_changed);
  EXPECT_EQ(panel.state().time_step, 1);
  panel.click("play");
  EXPECT_TRUE(panel.state().playing);
  panel.slide("play fps", 1.0f);
  EXPECT_NEAR(panel.state().play_fps, 20.0f, 0.5f);
}

TEST(PanelViewControlsTest, NodeBoxesAndHome) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  panel.click("node boxes");
  EXPECT_TRUE(panel.state().boxes);
  panel.click("home view");
  EXPECT_TRUE(panel.state().home);
}

TEST(PanelViewControlsTest, TerrainAndDrapeSwitchesOnlyWithTerrain) {
  const auto m = panel_manifest();
  {
    PanelDriver panel(m, panel_state(m));
    EXPECT_FALSE(panel.has("terrain"));
    EXPECT_FALSE(panel.has("drape"));
  }
  auto state = panel_state(m);
  state.terrain_available = state.drape_available = true;
  PanelDriver panel(m, state);
  panel.click("drape");
  EXPECT_FALSE(panel.state().drape_shown);
  EXPECT_TRUE(panel.state().terrain_shown);
  panel.click("terrain");
  EXPECT_FALSE(panel.state().terrain_shown);
  // The drape switch is disabled while the terrain is off.
  panel.click("drape");
  EXPECT_FALSE(panel.state().drape_shown);
  panel.click("terrain");
  EXPECT_TRUE(panel.state().terrain_shown);
}

TEST(PanelViewControlsTest, TrackSwitchAndMinutesOnlyWithTracks) {
  const auto m = panel_manifest();
  {
    PanelDriver panel(m, panel_state(m));
    EXPECT_FALSE(panel.has("tracks"));
  }
  auto state = panel_state(m);
  state.tracks_available = true;
  state.scene.trajectories = Trajectories{.file = "tracks.csv", .minutes = 2};
  PanelDriver panel(m, state);
  panel.slide("track minutes", 1.0f);
  EXPECT_TRUE(panel.state().tracks_changed);
  EXPECT_NEAR(panel.state().track_minutes, 600.0f, 10.0f);
  // Saved with the scene, which is not sent again for it.
  EXPECT_EQ(panel.state().scene.trajectories->minutes, panel.state().track_minutes);
  EXPECT_FALSE(panel.state().scene_changed);
  panel.click("tracks");
  EXPECT_FALSE(panel.state().tracks_shown);
}

TEST(PanelViewControlsTest, WindControlsOnlyWithWind) {
  const auto m = panel_manifest();
  {
    PanelDriver panel(m, panel_state(m));
    EXPECT_FALSE(panel.has("advect"));
  }
  auto state = panel_state(m);
  state.advect_available = true;
  panel::PanelInfo info;
  info.step_seconds = 3600;
  PanelDriver panel(m, state, info);
  panel.click("advect");
  EXPECT_TRUE(panel.state().advect);
  panel.slide("advect seconds", 1.0f);
  EXPECT_NEAR(panel.state().advect_seconds, 3600.0f, 1.0f);
}

TEST(PanelViewControlsTest, ShaderButtons) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  EXPECT_FALSE(panel.has("compile shader"));  // the section starts closed
  panel.click("header Shader");
  panel.click("compile shader");
  EXPECT_TRUE(panel.state().shader_compile);
  panel.click("reload shader");
  EXPECT_TRUE(panel.state().shader_reload);
  panel.click("built-in scalar on surface");
  EXPECT_EQ(panel.state().builtin_look, panel::PanelState::BuiltinLook::kScalarOnSurface);
  panel.click("built-in clouds");
  EXPECT_EQ(panel.state().builtin_look, panel::PanelState::BuiltinLook::kClouds);
}

TEST(PanelViewControlsTest, TheScalarLooksColourBarIsInTheLegendOnlyWhenShown) {
  const auto m = panel_manifest();
  EXPECT_FALSE(PanelDriver(m, panel_state(m)).has("scalar legend"));
  panel::PanelInfo info;
  info.scalar_legend = panel::ScalarLegend{"wind speed (m s-1)", 0, 50, {{0, 0, 0}, {1, 1, 0}}};
  PanelDriver panel(m, panel_state(m), info);
  EXPECT_TRUE(panel.has("scalar legend"));
}

TEST(PanelViewControlsTest, LegendNamesEachSubVolume) {
  const auto m = panel_manifest();
  PanelDriver panel(m, panel_state(m));
  for (const auto& s : panel.state().scene.subvolumes) {
    EXPECT_TRUE(panel.has("legend " + std::to_string(s.id))) << s.name;
  }
  panel.click("add subvolume");
  EXPECT_TRUE(panel.has("legend " + std::to_string(panel.state().scene.subvolumes.back().id)));
}

}  // namespace
}  // namespace strielad::testing
