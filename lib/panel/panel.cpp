// SPDX-License-Identifier: Apache-2.0
#include "panel/panel.h"

#include <imgui.h>

#include <algorithm>

#include "panel/item_probe.h"
#include "panel/panel_sections.h"
#include "panel/scene_edits.h"

namespace strielad::panel {
namespace {

void error_text(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// An edited scene is sent only when the store accepts it; otherwise the panel shows why.
void check_edit(PanelState& state, const format::Manifest& manifest) {
  state.scene_error = scene_problem(state.scene, manifest);
  if (state.scene_error.empty()) state.scene_changed = true;
}

}  // namespace

void draw_panel(PanelState& state, const PanelInfo& info, const format::Manifest& manifest) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 680), ImGuiCond_FirstUseEver);
  ImGui::Begin("STRIELAD");
  ImGui::TextWrapped("%s", info.dataset.c_str());
  if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
    time_section(state, info, manifest);
  }
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) view_section(state, info);
  if (ImGui::CollapsingHeader("Legend", ImGuiTreeNodeFlags_DefaultOpen)) legend_section(state, info);
  bool edited = false;
  if (!state.scene_error.empty()) error_text("not applied: " + state.scene_error);
  if (ImGui::CollapsingHeader("Sub-volumes", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushID("subvolumes");
    edited |= subvolume_section(state, info, manifest);
    ImGui::PopID();
  }
  if (ImGui::CollapsingHeader("Attributes", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushID("attributes");
    edited |= attribute_section(state, manifest);
    ImGui::PopID();
  }
  if (ImGui::CollapsingHeader("Slices", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushID("slices");
    edited |= slice_section(state, manifest);
    ImGui::PopID();
  }
  if (edited) check_edit(state, manifest);
  if (ImGui::CollapsingHeader("Scene files", ImGuiTreeNodeFlags_DefaultOpen)) {
    files_section(state, manifest);
  }
  const bool shader_open = ImGui::CollapsingHeader("Shader");
  note_item("header Shader");
  if (shader_open) shader_section(state);
  if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
    statistics_section(info);
  }
  ImGui::End();
}

}  // namespace strielad::panel
