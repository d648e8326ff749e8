// SPDX-License-Identifier: Apache-2.0
// The slice section of the panel: add and remove slices; per slice its plane (the axis,
// and the position bounded by the axis; a level slice's value), the variable that
// colours it, its colour map and colour range.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "panel/item_probe.h"
#include "panel/panel_sections.h"
#include "panel/range_widgets.h"
#include "panel/scene_edits.h"
#include "view/default_scene.h"

namespace strielad::panel {
namespace {

// A combo over `names`; true when another one was picked.
template <typename Names>
bool name_combo(const char* id, std::string& value, const Names& names, const std::string& key) {
  bool changed = false;
  ImGui::SetNextItemWidth(110);
  const bool open = ImGui::BeginCombo(id, value.c_str());
  note_item(key);
  if (open) {
    for (const auto& n : names) {
      const std::string name(n);
      if (ImGui::Selectable(name.c_str(), name == value)) {
        changed = name != value;
        value = name;
      }
      note_item(key + " " + name);
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool plane_editor(Slice& slice, const format::Manifest& manifest, const std::string& key) {
  bool edited = false;
  if (slice.is_level()) {
    ImGui::Text("level of %s", slice.level_var.c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    ImGui::InputDouble("value", &slice.value, 0, 0, "%.4g");
    note_item(key + " value");
    return ImGui::IsItemDeactivatedAfterEdit();
  }
  const std::vector<std::string> axes = {manifest.x.name, manifest.y.name, manifest.z.name};
  if (name_combo("##axis", slice.axis, axes, key + " axis")) {
    // The plane moves to the middle of its new axis.
    if (const auto* axis = axis_named(manifest, slice.axis)) {
      const AxisRange extent = axis_extent(*axis);
      slice.value = 0.5 * (extent.lo + extent.hi);
    }
    edited = true;
  }
  if (const auto* axis = axis_named(manifest, slice.axis)) {
    AxisRange extent = axis_extent(*axis);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    ImGui::SliderScalar("position", ImGuiDataType_Double, &slice.value, &extent.lo, &extent.hi,
                        "%.4g");
    note_item(key + " value");
    edited |= ImGui::IsItemDeactivatedAfterEdit();
  }
  return edited;
}

bool colour_editor(Slice& slice, const format::Manifest& manifest, const std::string& key) {
  std::vector<std::string> variables;
  for (const auto& v : manifest.variables) variables.push_back(v.name);
  bool edited = name_combo("##var", slice.var, variables, key + " variable");
  ImGui::SameLine();
  edited |= name_combo("##colormap", slice.colormap, kSliceColormaps, key + " colormap");
  bool fixed = slice.range.has_value();
  if (ImGui::Checkbox("colour range", &fixed)) {
    if (fixed) {
      const auto data = view::variable_range(manifest, slice.var);
      slice.range = data && data->first < data->second ? AxisRange{data->first, data->second}
                                                       : AxisRange{0, 1};
    } else {
      slice.range.reset();
    }
    edited = true;
  }
  note_item(key + " range on");
  if (slice.range) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("##lo", &slice.range->lo, 0, 0, "%.4g");
    note_item(key + " range lo");
    edited |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("##hi", &slice.range->hi, 0, 0, "%.4g");
    note_item(key + " range hi");
    edited |= ImGui::IsItemDeactivatedAfterEdit();
  } else {
    ImGui::SameLine();
    ImGui::TextDisabled("the viewer's");
  }
  return edited;
}

}  // namespace

bool slice_section(PanelState& state, const format::Manifest& manifest) {
  bool edited = false;
  auto& slices = state.scene.slices;
  for (std::size_t i = 0; i < slices.size(); ++i) {
    auto& slice = slices[i];
    const std::string key = fmt::format("slice {}", slice.id);
    ImGui::PushID(static_cast<int>(slice.id));
    ImGui::Separator();
    ImGui::Text("slice %u", slice.id);
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton("remove");
    note_item(key + " remove");
    if (remove) {
      slices.erase(slices.begin() + static_cast<std::ptrdiff_t>(i));
      ImGui::PopID();
      return true;
    }
    edited |= plane_editor(slice, manifest, key);
    edited |= colour_editor(slice, manifest, key);
    ImGui::PopID();
  }
  const bool add = ImGui::Button("+ slice");
  note_item("add slice");
  if (add && !manifest.variables.empty() && slices.size() < kMaxSlices) {
    slices.push_back(new_slice(state.scene, manifest));
    edited = true;
  }
  return edited;
}

}  // namespace strielad::panel
