// SPDX-License-Identifier: Apache-2.0
#include "viewer_panel.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

#include "render/surface_scalar_look.h"
#include "render/volume_shaders.h"
#include "view/default_scene.h"
#include "view/simulation_time.h"
#include "view/subvolume_palette.h"

namespace strielad::view_cmd {
namespace {

std::string bytes_text(std::uint64_t bytes) {
  if (bytes >= (1ull << 30)) return fmt::format("{:.2f} GiB", bytes / double(1ull << 30));
  if (bytes >= (1ull << 20)) return fmt::format("{:.1f} MiB", bytes / double(1ull << 20));
  return fmt::format("{:.0f} KiB", bytes / 1024.0);
}

// One limit's bound: a checkbox (open or not) and the value.
bool bound_editor(const char* label, std::optional<double>& bound, double fallback) {
  bool changed = false;
  bool on = bound.has_value();
  ImGui::PushID(label);
  if (ImGui::Checkbox("##on", &on)) {
    bound = on ? std::optional<double>(fallback) : std::nullopt;
    changed = true;
  }
  ImGui::SameLine();
  if (on) {
    double v = *bound;
    ImGui::SetNextItemWidth(110);
    if (ImGui::InputDouble(label, &v, 0, 0, "%.4g")) {
      if (std::isfinite(v)) bound = v;
    }
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  } else {
    ImGui::TextDisabled("%s: open", label);
  }
  ImGui::PopID();
  return changed;
}

// Each sub-volume's name in its palette colour (view/subvolume_palette.h): the colours
// the built-in shader draws, and user shaders through subvolume_color(id).
void legend(const Scene& scene) {
  for (const auto& entry : view::subvolume_legend(scene)) {
    const auto& c = entry.color;
    ImGui::PushID(static_cast<int>(entry.id));
    ImGui::ColorButton("##colour", ImVec4(c[0], c[1], c[2], 1.0f),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                       ImVec2(14, 14));
    ImGui::SameLine();
    if (entry.drawn) {
      ImGui::Text("%s", entry.label.c_str());
    } else {
      ImGui::TextDisabled("%s (not drawn: the viewer draws %zu sub-volumes)", entry.label.c_str(),
                          view::kMaxViewSubVolumes);
    }
    ImGui::PopID();
  }
}

void subvolume_editor(PanelState& state, const format::Manifest& manifest) {
  auto& subs = state.scene.subvolumes;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    auto& s = subs[i];
    ImGui::PushID(static_cast<int>(s.id));
    ImGui::Separator();
    ImGui::Text("id %u", s.id);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    ImGui::InputText("##name", &s.name);
    ImGui::SameLine();
    if (ImGui::SmallButton("remove") && subs.size() > 1) {
      subs.erase(subs.begin() + static_cast<std::ptrdiff_t>(i));
      state.scene_changed = true;
      ImGui::PopID();
      return;
    }
    for (std::size_t l = 0; l < s.limits.size(); ++l) {
      auto& limit = s.limits[l];
      ImGui::PushID(static_cast<int>(l));
      ImGui::SetNextItemWidth(90);
      if (ImGui::BeginCombo("##var", limit.var.c_str())) {
        for (const auto& v : manifest.variables) {
          if (ImGui::Selectable(v.name.c_str(), v.name == limit.var)) {
            limit.var = v.name;
            state.scene_changed = true;
          }
        }
        ImGui::EndCombo();
      }
      const auto range = view::variable_range(manifest, limit.var);
      ImGui::SameLine();
      if (range) {
        ImGui::TextDisabled("data %.3g .. %.3g", range->first, range->second);
      } else {
        ImGui::TextDisabled("data range unknown");
      }
      const double lo = range ? range->first : 0.0, hi = range ? range->second : 1.0;
      state.scene_changed |= bound_editor("min", limit.min, lo + 0.25 * (hi - lo));
      ImGui::SameLine();
      state.scene_changed |= bound_editor("max", limit.max, lo + 0.75 * (hi - lo));
      if (s.limits.size() > 1) {
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) {
          s.limits.erase(s.limits.begin() + static_cast<std::ptrdiff_t>(l));
          state.scene_changed = true;
          ImGui::PopID();
          break;
        }
      }
      ImGui::PopID();
    }
    if (ImGui::SmallButton("+ limit") && !manifest.variables.empty()) {
      s.limits.push_back(Limit{.var = manifest.variables.front().name, .min = std::nullopt,
                               .max = std::nullopt});
      const auto range = view::variable_range(manifest, s.limits.back().var);
      s.limits.back().min = range ? 0.5 * (range->first + range->second) : 0.0;
      state.scene_changed = true;
    }
    if (!s.domain.empty()) {
      ImGui::SameLine();
      ImGui::TextDisabled("(domain limits from the scene file)");
    }
    ImGui::PopID();
  }
  if (ImGui::Button("+ sub-volume") && !manifest.variables.empty() && subs.size() < 32) {
    std::uint32_t id = 1;
    for (const auto& s : subs) id = std::max(id, s.id + 1);
    SubVolume s;
    s.id = id;
    s.name = fmt::format("sub-volume {}", id);
    const auto& var = manifest.variables.front().name;
    const auto range = view::variable_range(manifest, var);
    s.limits.push_back(Limit{.var = var,
                             .min = range ? 0.5 * (range->first + range->second) : 0.0,
                             .max = std::nullopt});
    subs.push_back(std::move(s));
    state.scene_changed = true;
  }
}

void shader_editor(PanelState& state) {
  ImGui::TextUnformatted(state.shader_name.c_str());
  if (ImGui::Button("Compile (Ctrl+Enter)")) state.shader_compile = true;
  ImGui::SameLine();
  if (ImGui::Button("Reload file")) state.shader_reload = true;
  // The built-in looks into the editor (docs/view.md "Looks"); the scalar one colours by
  // the first attribute over [0, 1] until its SCALAR_ defines are edited.
  if (ImGui::Button("Built-in clouds")) {
    state.shader_text = render::default_user_shader();
    state.shader_compile = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Built-in scalar on surface")) {
    state.shader_text = render::surface_scalar_source();
    state.shader_compile = true;
  }
  if (!state.shader_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", state.shader_error.c_str());
    ImGui::PopStyleColor();
    ImGui::TextDisabled("the last good shader keeps running");
  }
  ImGui::InputTextMultiline("##shader", &state.shader_text, ImVec2(-1, 260),
                            ImGuiInputTextFlags_AllowTabInput);
  if (ImGui::IsItemFocused() && ImGui::GetIO().KeyCtrl &&
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
    state.shader_compile = true;
  }
}

void statistics(const PanelInfo& info) {
  ImGui::Text("%.1f FPS, %.1f ms a frame (cut update %.3f ms)", info.fps, info.frame_ms,
              info.cut_update_ms);
  ImGui::Text("cut: %zu nodes, %zu pending, %zu stale shown%s", info.cut_nodes, info.pending,
              info.stale_shown, info.complete ? ", complete" : "");
  ImGui::Text("received: %llu results (%llu failed), %s", static_cast<unsigned long long>(info.results),
              static_cast<unsigned long long>(info.failed), bytes_text(info.bytes_received).c_str());
  ImGui::Text("GPU: %zu triangles in %s", info.gpu_triangles, bytes_text(info.gpu_bytes).c_str());
  if (!info.terrain.empty()) ImGui::TextWrapped("%s", info.terrain.c_str());
  const auto& f = info.frame;
  ImGui::Text("A-buffer: %.1f fragments per covered pixel, max %u", f.fragments_per_covered_pixel(),
              f.max_fragments_per_pixel);
  ImGui::Text("  pool %s, %llu dropped, %llu pixels over 32", bytes_text(f.fragment_capacity * 16).c_str(),
              static_cast<unsigned long long>(f.dropped_fragments),
              static_cast<unsigned long long>(f.truncated_pixels));
  ImGui::Text("  GPU ms: geometry %.1f, sort+resolve %.1f", f.geometry_ms, f.resolve_ms);
  if (info.cache_hit_rate >= 0) {
    ImGui::Text("server brick cache hit rate: %.1f%%", info.cache_hit_rate * 100);
  } else {
    ImGui::TextDisabled("server brick cache hit rate: n/a");
  }
  if (!info.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("server: %s", info.error.c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace

void draw_panel(PanelState& state, const PanelInfo& info, const format::Manifest& manifest) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 680), ImGuiCond_FirstUseEver);
  ImGui::Begin("STRIELAD");
  ImGui::TextWrapped("%s", info.dataset.c_str());
  if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
    const int steps = static_cast<int>(manifest.time.values.size());
    if (ImGui::SliderInt("step", &state.time_step, 0, std::max(steps - 1, 0))) {
      state.time_changed = true;
    }
    ImGui::Checkbox("play", &state.playing);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::SliderFloat("steps/s", &state.play_fps, 0.2f, 20.0f, "%.1f");
    if (state.advect_available) {
      ImGui::Checkbox("move with the wind", &state.advect);
      if (state.advect) {
        if (info.step_seconds > 0) {
          ImGui::SliderFloat("s after step", &state.advect_seconds, 0.0f,
                             static_cast<float>(info.step_seconds), "%.0f");
          ImGui::TextDisabled("%zu nodes moved", info.nodes_moved);
        } else {
          ImGui::TextDisabled("computing the step's trajectories...");
        }
      }
    }
    ImGui::TextDisabled("%s", info.advect_status.c_str());
    if (info.sun_elevation_deg) {
      ImGui::TextDisabled("sun %.1f deg above the horizon %s", *info.sun_elevation_deg,
                          info.sun_viewpoint.c_str());
    }
    if (state.time_step >= 0 && state.time_step < steps) {
      // The raw value, then its date in the store's calendar (or why it has none).
      const std::string time_text =
          view::step_time_text(manifest, static_cast<std::uint32_t>(state.time_step));
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", time_text.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::SliderFloat("LOD threshold (sr)", &state.lod_threshold_sr, 0.0005f, 0.2f, "%.4f",
                           ImGuiSliderFlags_Logarithmic)) {
      state.lod_changed = true;
    }
    if (ImGui::SliderInt("max nodes", &state.max_nodes, 1, 16384, "%d",
                         ImGuiSliderFlags_Logarithmic)) {
      state.lod_changed = true;
    }
    if (ImGui::SliderFloat("vertical exaggeration", &state.exaggeration, 1.0f, 1000.0f, "%.1f",
                           ImGuiSliderFlags_Logarithmic)) {
      state.exaggeration_changed = true;
    }
    if (!info.vertical_placement.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", info.vertical_placement.c_str());
      ImGui::PopTextWrapPos();
    }
    ImGui::Checkbox("node boxes", &state.boxes);
    ImGui::SameLine();
    if (ImGui::Button("home view")) state.home = true;
    ImGui::TextDisabled("drag: orbit, right/middle drag: pan, wheel: zoom, WASD/QE: fly");
  }
  if (ImGui::CollapsingHeader("Legend", ImGuiTreeNodeFlags_DefaultOpen)) {
    legend(state.scene);
    if (state.shader_name.rfind("built-in", 0) != 0) {
      ImGui::TextDisabled("palette colours: %s draws them where it calls subvolume_color(id)",
                          state.shader_name.c_str());
    }
  }
  if (ImGui::CollapsingHeader("Sub-volumes", ImGuiTreeNodeFlags_DefaultOpen)) {
    subvolume_editor(state, manifest);
  }
  if (ImGui::CollapsingHeader("Shader")) shader_editor(state);
  if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) statistics(info);
  ImGui::End();
}

}  // namespace strielad::view_cmd
