// SPDX-License-Identifier: Apache-2.0
// Saving and loading the scene and camera from the panel: the Save button writes
// canonical scene JSON and a one-keyframe camera path that read back to what was shown;
// Load replaces the scene only with one the store accepts, and shows why not.
#include <gtest/gtest.h>

#include <fstream>

#include "lod/camera_path.h"
#include "panel/panel_driver.h"
#include "panel/scene_files.h"
#include "support/temp_dir.h"

namespace strielad::testing {
namespace {

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

lod::Keyframe camera() {
  lod::Keyframe key;
  key.eye = {5, 30, 20000};
  key.target = {5, 45, 0};
  return key;
}

TEST(PanelSceneFilesTest, CameraFileBesideTheScene) {
  EXPECT_EQ(panel::camera_file_for("views/a.json"), "views/a.camera.json");
  EXPECT_EQ(panel::camera_file_for("a"), "a.camera.json");
}

TEST(PanelSceneFilesTest, SaveWritesSceneAndCameraThatReadBack) {
  const auto m = panel_manifest();
  TempDir dir;
  auto state = panel_state(m);
  state.camera = camera();
  PanelDriver panel(m, state);
  panel.click("add slice");
  const std::string path = (dir / "view.json").string();
  panel.type("scene path", path);
  EXPECT_EQ(panel.state().scene_path, path);
  panel.click("save scene");
  EXPECT_TRUE(panel.state().file_error.empty()) << panel.state().file_error;
  EXPECT_EQ(load_scene_file(path), panel.state().scene);
  const auto saved_camera = lod::load_camera_path_file(dir / "view.camera.json");
  ASSERT_EQ(saved_camera.keyframes.size(), 1u);
  EXPECT_EQ(saved_camera.keyframes[0], camera());
  // Canonical: the file is the scene's canonical form.
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, scene_to_json(panel.state().scene) + "\n");
}

TEST(PanelSceneFilesTest, LoadReplacesSceneAndMovesCamera) {
  const auto m = panel_manifest();
  TempDir dir;
  auto other = panel_state(m).scene;
  other.time = 1;
  other.attributes.clear();
  other.slices.push_back(Slice{.id = 3, .name = "ground", .axis = "height", .value = 100,
                               .var = "ta"});
  other.trajectories = Trajectories{.file = "tracks.csv", .minutes = 7};
  panel::save_scene_files(dir / "other.json", other, camera());
  PanelDriver panel(m, panel_state(m));
  panel.state().scene_path = (dir / "other.json").string();
  panel.click("load scene");
  EXPECT_TRUE(panel.state().file_error.empty()) << panel.state().file_error;
  EXPECT_EQ(panel.state().scene, other);
  EXPECT_TRUE(panel.state().scene_changed);
  EXPECT_EQ(panel.state().time_step, 1);
  EXPECT_TRUE(panel.state().time_changed);
  ASSERT_TRUE(panel.state().camera_loaded.has_value());
  EXPECT_EQ(*panel.state().camera_loaded, camera());
  EXPECT_EQ(panel.state().track_minutes, 7.0f);
  EXPECT_TRUE(panel.state().tracks_changed);
}

TEST(PanelSceneFilesTest, BadFilesShowAnErrorAndLeaveTheScene) {
  const auto m = panel_manifest();
  TempDir dir;
  write(dir / "broken.json", "{\"format_version\": 1, \"subvolumes\": [");
  write(dir / "other_store.json",
        R"({"format_version": 1, "time": 0, "subvolumes": [{"id": 1, "name": "q",
            "limits": [{"var": "qv", "min": 0.001}]}]})");
  PanelDriver panel(m, panel_state(m));
  const Scene before = panel.state().scene;
  for (const auto& [name, expected] :
       {std::pair<std::string, std::string>{"missing.json", "missing.json"},
        {"broken.json", "broken.json"},
        {"other_store.json", "qv"}}) {
    panel.state().scene_path = (dir / name).string();
    panel.click("load scene");
    EXPECT_NE(panel.state().file_error.find(expected), std::string::npos)
        << name << ": " << panel.state().file_error;
    EXPECT_EQ(panel.state().scene, before);
    EXPECT_FALSE(panel.state().scene_changed);
  }
}

TEST(PanelSceneFilesTest, SaveToAMissingDirectoryShowsAnError) {
  const auto m = panel_manifest();
  TempDir dir;
  PanelDriver panel(m, panel_state(m));
  panel.state().scene_path = (dir / "no" / "such" / "dir.json").string();
  panel.click("save scene");
  EXPECT_FALSE(panel.state().file_error.empty());
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
}

}  // namespace
}  // namespace strielad::testing
