// SPDX-License-Identifier: Apache-2.0
// The panel's scene files: the scene as canonical scene JSON (formats/scene.md) at PATH,
// and the camera as a one-keyframe camera path (formats/camera-path.md) beside it, at
// PATH with ".json" replaced by ".camera.json". Both are written atomically.
#pragma once

#include <filesystem>
#include <optional>

#include "format/manifest.h"
#include "lod/camera_path.h"
#include "scene/scene.h"

namespace strielad::panel {

// The camera file beside a scene file: "views/a.json" -> "views/a.camera.json".
std::filesystem::path camera_file_for(const std::filesystem::path& scene_file);

// Writes the scene and, when given, the camera.
// \error kInvalidInput for a scene or camera that fails validation (nothing written);
// kIo naming the file that cannot be written.
void save_scene_files(const std::filesystem::path& scene_file, const Scene& scene,
                      const std::optional<lod::Keyframe>& camera);

struct LoadedScene {
  Scene scene;
  std::optional<lod::Keyframe> camera;  // the first keyframe of the camera file, if any
};

// Reads a scene file and checks it against the store (resolve_scene), and its camera
// file when there is one.
// \error as load_scene_file, resolve_scene and load_camera_path_file, naming the file.
LoadedScene load_scene_files(const std::filesystem::path& scene_file,
                             const format::Manifest& manifest);

}  // namespace strielad::panel
