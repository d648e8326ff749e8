// SPDX-License-Identifier: Apache-2.0
// The time, view and legend sections of the panel.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "panel/item_probe.h"
#include "panel/panel_sections.h"
#include "view/simulation_time.h"
#include "view/subvolume_palette.h"

namespace strielad::panel {

void time_section(PanelState& state, const PanelInfo& info, const format::Manifest& manifest) {
  const int steps = static_cast<int>(manifest.time.values.size());
  if (ImGui::SliderInt("step", &state.time_step, 0, std::max(steps - 1, 0))) {
    state.time_changed = true;
  }
  note_item("time step");
  ImGui::Checkbox("play", &state.playing);
  note_item("play");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("steps/s", &state.play_fps, 0.2f, 20.0f, "%.1f");
  note_item("play fps");
  if (state.advect_available) {
    ImGui::Checkbox("move with the wind", &state.advect);
    note_item("advect");
    if (state.advect) {
      if (info.step_seconds > 0) {
        ImGui::SliderFloat("s after step", &state.advect_seconds, 0.0f,
                           static_cast<float>(info.step_seconds), "%.0f");
        note_item("advect seconds");
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

void view_section(PanelState& state, const PanelInfo& info) {
  if (ImGui::SliderFloat("LOD threshold (sr)", &state.lod_threshold_sr, 0.0005f, 0.2f, "%.4f",
                         ImGuiSliderFlags_Logarithmic)) {
    state.lod_changed = true;
  }
  note_item("lod threshold");
  if (ImGui::SliderInt("max nodes", &state.max_nodes, 1, 16384, "%d",
                       ImGuiSliderFlags_Logarithmic)) {
    state.lod_changed = true;
  }
  note_item("max nodes");
  ImGui::SliderFloat("LOD fade (ms)", &state.lod_fade_ms, 0.0f, 2000.0f, "%.0f");
  note_item("lod fade");
  if (ImGui::SliderFloat("vertical exaggeration", &state.exaggeration, 1.0f, 1000.0f, "%.1f",
                         ImGuiSliderFlags_Logarithmic)) {
    state.exaggeration_changed = true;
  }
  note_item("exaggeration");
  if (!info.vertical_placement.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", info.vertical_placement.c_str());
    ImGui::PopTextWrapPos();
  }
  if (state.terrain_available) {
    ImGui::Checkbox("terrain", &state.terrain_shown);
    note_item("terrain");
    if (state.drape_available) {
      ImGui::SameLine();
      ImGui::BeginDisabled(!state.terrain_shown);
      ImGui::Checkbox("drape image", &state.drape_shown);
      note_item("drape");
      ImGui::EndDisabled();
    }
  }
  if (state.tracks_available) {
    ImGui::Checkbox("flight tracks", &state.tracks_shown);
    note_item("tracks");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::BeginDisabled(!state.tracks_shown);
    ImGui::SliderFloat("minutes", &state.track_minutes, 0.1f, 600.0f, "%.1f",
                       ImGuiSliderFlags_Logarithmic);
    note_item("track minutes");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      state.track_minutes = std::max(state.track_minutes, 0.1f);
      state.tracks_changed = true;
      // Saved with the scene; the server does not use it, so the scene is not re-sent.
      if (state.scene.trajectories) state.scene.trajectories->minutes = state.track_minutes;
    }
    ImGui::EndDisabled();
  }
  ImGui::Checkbox("node boxes", &state.boxes);
  note_item("node boxes");
  ImGui::SameLine();
  if (ImGui::Button("home view")) state.home = true;
  note_item("home view");
  ImGui::TextDisabled("drag: orbit, right/middle drag: pan, wheel: zoom, WASD/QE: fly");
}

// Each sub-volume's name in its palette colour (view/subvolume_palette.h): the colours
// the built-in shader draws, and user shaders through subvolume_color(id).
void legend_section(const PanelState& state, const PanelInfo& info) {
  if (const auto& legend = info.scalar_legend; legend && legend->colours.size() >= 2) {
    // The colour bar: one rectangle per pair of neighbouring colours, shaded between them.
    ImGui::TextUnformatted(legend->title.c_str());
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = std::max(ImGui::GetContentRegionAvail().x - 8.0f, 40.0f), height = 14.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const std::size_t n = legend->colours.size();
    const auto colour = [&](std::size_t k) {
      const auto& c = legend->colours[k];
      return ImGui::GetColorU32(ImVec4(c[0], c[1], c[2], 1.0f));
    };
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const float x0 = origin.x + width * float(k) / float(n - 1);
      const float x1 = origin.x + width * float(k + 1) / float(n - 1);
      draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height),
                                    colour(k), colour(k + 1), colour(k + 1), colour(k));
    }
    ImGui::Dummy(ImVec2(width, height));
    note_item("scalar legend");
    ImGui::Text("%.4g", legend->lo);
    ImGui::SameLine(width * 0.5f - 10.0f);
    ImGui::Text("%.4g", 0.5 * (legend->lo + legend->hi));
    ImGui::SameLine(std::max(width - 30.0f, 0.0f));
    ImGui::Text("%.4g", legend->hi);
  }
  for (const auto& entry : view::subvolume_legend(state.scene)) {
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
    note_item("legend " + std::to_string(entry.id));
    ImGui::PopID();
  }
  if (state.shader_name.rfind("built-in", 0) != 0) {
    ImGui::TextDisabled("palette colours: %s draws them where it calls subvolume_color(id)",
                        state.shader_name.c_str());
  }
}

}  // namespace strielad::panel
