// SPDX-License-Identifier: Apache-2.0
// The scene-file, shader and statistics sections of the panel.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/error.h"
#include "panel/item_probe.h"
#include "panel/panel_sections.h"
#include "panel/scene_files.h"

namespace strielad::panel {
namespace {

std::string bytes_text(std::uint64_t bytes) {
  if (bytes >= (1ull << 30)) return fmt::format("{:.2f} GiB", bytes / double(1ull << 30));
  if (bytes >= (1ull << 20)) return fmt::format("{:.1f} MiB", bytes / double(1ull << 20));
  return fmt::format("{:.0f} KiB", bytes / 1024.0);
}

void error_text(const char* prefix, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  ImGui::TextWrapped("%s%s", prefix, text.c_str());
  ImGui::PopStyleColor();
}

void save(PanelState& state) {
  try {
    save_scene_files(state.scene_path, state.scene, state.camera);
    state.file_error.clear();
    state.file_status = state.camera
                            ? fmt::format("saved {} and {}", state.scene_path,
                                          camera_file_for(state.scene_path).string())
                            : fmt::format("saved {}", state.scene_path);
  } catch (const Error& e) {
    state.file_error = e.what();
    state.file_status.clear();
  }
}

// A loaded scene replaces the panel's (time step included) once the store accepts it.
void load(PanelState& state, const format::Manifest& manifest) {
  try {
    LoadedScene loaded = load_scene_files(state.scene_path, manifest);
    state.scene = std::move(loaded.scene);
    state.scene_changed = true;
    state.scene_error.clear();
    state.time_step = static_cast<int>(state.scene.time);
    state.time_changed = true;
    state.camera_loaded = loaded.camera;
    if (state.scene.trajectories) {
      state.track_minutes = static_cast<float>(state.scene.trajectories->minutes);
      state.tracks_changed = true;
    }
    state.file_error.clear();
    state.file_status = fmt::format("loaded {}{}", state.scene_path,
                                    loaded.camera ? " and its camera" : "");
  } catch (const Error& e) {
    state.file_error = e.what();
    state.file_status.clear();
  }
}

}  // namespace

void files_section(PanelState& state, const format::Manifest& manifest) {
  ImGui::SetNextItemWidth(220);
  ImGui::InputText("scene file", &state.scene_path);
  note_item("scene path");
  if (ImGui::Button("Save scene")) save(state);
  note_item("save scene");
  ImGui::SameLine();
  if (ImGui::Button("Load scene")) load(state, manifest);
  note_item("load scene");
  ImGui::TextDisabled("the camera is saved beside it, as NAME.camera.json");
  if (!state.file_error.empty()) error_text("", state.file_error);
  if (!state.file_status.empty()) ImGui::TextDisabled("%s", state.file_status.c_str());
}

void shader_section(PanelState& state) {
  ImGui::TextUnformatted(state.shader_name.c_str());
  if (ImGui::Button("Compile (Ctrl+Enter)")) state.shader_compile = true;
  note_item("compile shader");
  ImGui::SameLine();
  if (ImGui::Button("Reload file")) state.shader_reload = true;
  note_item("reload shader");
  // The built-in looks into the editor; the scalar one colours by the first attribute
  // over [0, 1] until its SCALAR_ defines are edited.
  if (ImGui::Button("Built-in clouds")) state.builtin_look = PanelState::BuiltinLook::kClouds;
  note_item("built-in clouds");
  ImGui::SameLine();
  if (ImGui::Button("Built-in scalar on surface")) {
    state.builtin_look = PanelState::BuiltinLook::kScalarOnSurface;
  }
  note_item("built-in scalar on surface");
  if (!state.shader_error.empty()) {
    error_text("", state.shader_error);
    ImGui::TextDisabled("the last good shader keeps running");
  }
  ImGui::InputTextMultiline("##shader", &state.shader_text, ImVec2(-1, 260),
                            ImGuiInputTextFlags_AllowTabInput);
  note_item("shader text");
  if (ImGui::IsItemFocused() && ImGui::GetIO().KeyCtrl &&
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
    state.shader_compile = true;
  }
}

void statistics_section(const PanelInfo& info) {
  ImGui::Text("%.1f FPS, %.1f ms a frame (cut update %.3f ms)", info.fps, info.frame_ms,
              info.cut_update_ms);
  ImGui::Text("cut: %zu nodes, %zu pending, %zu stale shown%s", info.cut_nodes, info.pending,
              info.stale_shown, info.complete ? ", complete" : "");
  ImGui::Text("received: %llu results (%llu failed), %s",
              static_cast<unsigned long long>(info.results),
              static_cast<unsigned long long>(info.failed),
              bytes_text(info.bytes_received).c_str());
  ImGui::Text("GPU: %zu triangles in %s", info.gpu_triangles, bytes_text(info.gpu_bytes).c_str());
  if (!info.terrain.empty()) ImGui::TextWrapped("%s", info.terrain.c_str());
  const auto& f = info.frame;
  ImGui::Text("A-buffer: %.1f fragments per covered pixel, max %u", f.fragments_per_covered_pixel,
              f.max_fragments_per_pixel);
  ImGui::Text("  pool %s, %llu dropped, %llu pixels over 32",
              bytes_text(f.fragment_capacity * 16).c_str(),
              static_cast<unsigned long long>(f.dropped_fragments),
              static_cast<unsigned long long>(f.truncated_pixels));
  ImGui::Text("  GPU ms: geometry %.1f, sort+resolve %.1f", f.geometry_ms, f.resolve_ms);
  if (info.cache_hit_rate >= 0) {
    ImGui::Text("server brick cache hit rate: %.1f%%", info.cache_hit_rate * 100);
  } else {
    ImGui::TextDisabled("server brick cache hit rate: n/a");
  }
  if (!info.error.empty()) error_text("server: ", info.error);
}

}  // namespace strielad::panel
