// SPDX-License-Identifier: Apache-2.0
#include "panel/scene_files.h"

#include <span>
#include <string>

#include "core/error.h"
#include "core/file_io.h"

namespace strielad::panel {
namespace {

void write_text(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace

std::filesystem::path camera_file_for(const std::filesystem::path& scene_file) {
  std::filesystem::path camera = scene_file;
  if (camera.extension() == ".json") camera.replace_extension();
  camera += ".camera.json";
  return camera;
}

void save_scene_files(const std::filesystem::path& scene_file, const Scene& scene,
                      const std::optional<lod::Keyframe>& camera) {
  const std::string scene_text = scene_to_json(scene);
  std::string camera_text;
  if (camera) {
    lod::CameraPath path;
    path.name = scene_file.stem().string();
    path.keyframes.push_back(*camera);
    camera_text = lod::camera_path_to_json(path);
  }
  write_text(scene_file, scene_text + "\n");
  if (camera) write_text(camera_file_for(scene_file), camera_text + "\n");
}

LoadedScene load_scene_files(const std::filesystem::path& scene_file,
                             const format::Manifest& manifest) {
  LoadedScene loaded;
  loaded.scene = load_scene_file(scene_file);
  (void)resolve_scene(loaded.scene, manifest, scene_file.string());
  const auto camera_file = camera_file_for(scene_file);
  if (std::filesystem::exists(camera_file)) {
    const lod::CameraPath path = lod::load_camera_path_file(camera_file);
    if (!path.keyframes.empty()) loaded.camera = path.keyframes.front();
  }
  return loaded;
}

}  // namespace strielad::panel
