// SPDX-License-Identifier: Apache-2.0
// The sub-volume and attribute sections of the panel.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "panel/item_probe.h"
#include "panel/panel_sections.h"
#include "panel/range_widgets.h"
#include "panel/scene_edits.h"
#include "view/default_scene.h"

namespace strielad::panel {
namespace {

// A variable chooser; true when another variable was picked.
bool variable_combo(const char* id, std::string& var, const format::Manifest& manifest,
                    const std::string& key) {
  bool changed = false;
  ImGui::SetNextItemWidth(90);
  const bool open = ImGui::BeginCombo(id, var.c_str());
  note_item(key);
  if (open) {
    for (const auto& v : manifest.variables) {
      if (ImGui::Selectable(v.name.c_str(), v.name == var)) {
        changed = v.name != var;
        var = v.name;
      }
      note_item(key + " " + v.name);
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool limits_editor(SubVolume& s, const format::Manifest& manifest) {
  bool edited = false;
  const std::string key = fmt::format("subvolume {}", s.id);
  for (std::size_t l = 0; l < s.limits.size(); ++l) {
    auto& limit = s.limits[l];
    const std::string limit_key = fmt::format("{} limit {}", key, l);
    ImGui::PushID(static_cast<int>(l));
    edited |= variable_combo("##var", limit.var, manifest, limit_key + " variable");
    const auto range = view::variable_range(manifest, limit.var);
    ImGui::SameLine();
    if (range) {
      ImGui::TextDisabled("data %.3g .. %.3g", range->first, range->second);
    } else {
      ImGui::TextDisabled("data range unknown");
    }
    const double lo = range ? range->first : 0.0, hi = range ? range->second : 1.0;
    edited |= optional_bound("min", limit.min, lo + 0.25 * (hi - lo), limit_key + " min");
    ImGui::SameLine();
    edited |= optional_bound("max", limit.max, lo + 0.75 * (hi - lo), limit_key + " max");
    if (s.limits.size() > 1) {
      ImGui::SameLine();
      const bool remove = ImGui::SmallButton("x");
      note_item(limit_key + " remove");
      if (remove) {
        s.limits.erase(s.limits.begin() + static_cast<std::ptrdiff_t>(l));
        ImGui::PopID();
        return true;
      }
    }
    ImGui::PopID();
  }
  const bool add = ImGui::SmallButton("+ limit");
  note_item(key + " add limit");
  if (add && !manifest.variables.empty() && s.limits.size() < kMaxLimitsPerSubVolume) {
    const auto& var = manifest.variables.front().name;
    const auto range = view::variable_range(manifest, var);
    s.limits.push_back(Limit{.var = var,
                             .min = range ? 0.5 * (range->first + range->second) : 0.0,
                             .max = std::nullopt});
    edited = true;
  }
  return edited;
}

// The axis box: per axis of the store, a range bounded by the axis.
bool axis_box_editor(SubVolume& s, const format::Manifest& manifest) {
  bool edited = false;
  ImGui::PushID("axis box");
  ImGui::TextDisabled("box in the store's axes");
  for (const Axis* axis : {&manifest.x, &manifest.y, &manifest.z}) {
    std::optional<AxisRange> range;
    if (const auto it = s.domain.find(axis->name); it != s.domain.end()) range = it->second;
    const std::string key = fmt::format("subvolume {} box {}", s.id, axis->name);
    if (optional_range(axis->name.c_str(), range, axis_extent(*axis), key)) edited = true;
    if (range) {
      s.domain[axis->name] = *range;
    } else {
      s.domain.erase(axis->name);
    }
  }
  ImGui::PopID();
  return edited;
}

// The geographic box (longitude, latitude, height), for stores on the Earth.
bool geographic_box_editor(SubVolume& s, const format::Manifest& manifest) {
  bool edited = false;
  const std::string key = fmt::format("subvolume {} geographic", s.id);
  bool on = s.geographic.has_value();
  if (ImGui::Checkbox("geographic box", &on)) {
    if (on) {
      GeographicBox box;
      box.lon = geographic_extent(manifest, GeographicCoordinate::kLongitude);
      box.lat = geographic_extent(manifest, GeographicCoordinate::kLatitude);
      s.geographic = box;
    } else {
      s.geographic.reset();
    }
    edited = true;
  }
  note_item(key + " on");
  if (!s.geographic) return edited;
  auto& box = *s.geographic;
  ImGui::PushID("geographic");
  edited |= optional_range("lon", box.lon,
                           geographic_extent(manifest, GeographicCoordinate::kLongitude),
                           key + " lon");
  edited |= optional_range("lat", box.lat,
                           geographic_extent(manifest, GeographicCoordinate::kLatitude),
                           key + " lat");
  edited |= optional_range("height (m)", box.height,
                           geographic_extent(manifest, GeographicCoordinate::kHeight),
                           key + " height");
  ImGui::PopID();
  return edited;
}

}  // namespace

bool subvolume_section(PanelState& state, const PanelInfo& info,
                       const format::Manifest& manifest) {
  bool edited = false;
  auto& subs = state.scene.subvolumes;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    auto& s = subs[i];
    const std::string key = fmt::format("subvolume {}", s.id);
    ImGui::PushID(static_cast<int>(s.id));
    ImGui::Separator();
    ImGui::Text("id %u", s.id);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    ImGui::InputText("##name", &s.name);
    note_item(key + " name");
    edited |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton("remove");
    note_item(key + " remove");
    if (remove && subs.size() > 1) {
      subs.erase(subs.begin() + static_cast<std::ptrdiff_t>(i));
      ImGui::PopID();
      return true;
    }
    edited |= limits_editor(s, manifest);
    edited |= axis_box_editor(s, manifest);
    if (info.on_earth) edited |= geographic_box_editor(s, manifest);
    ImGui::PopID();
  }
  const bool add = ImGui::Button("+ sub-volume");
  note_item("add subvolume");
  if (add && !manifest.variables.empty() && subs.size() < kMaxSubVolumes) {
    subs.push_back(new_subvolume(state.scene, manifest));
    edited = true;
  }
  return edited;
}

bool attribute_section(PanelState& state, const format::Manifest& manifest) {
  auto& attributes = state.scene.attributes;
  ImGui::TextDisabled("variables carried by each vertex (for shaders)");
  for (std::size_t a = 0; a < attributes.size(); ++a) {
    ImGui::PushID(static_cast<int>(a));
    const bool remove = ImGui::SmallButton("x");
    note_item("attribute " + attributes[a] + " remove");
    ImGui::SameLine();
    ImGui::TextUnformatted(attributes[a].c_str());
    ImGui::PopID();
    if (remove) {
      attributes.erase(attributes.begin() + static_cast<std::ptrdiff_t>(a));
      return true;
    }
  }
  bool edited = false;
  ImGui::SetNextItemWidth(160);
  const bool open = ImGui::BeginCombo("##add attribute", "+ attribute");
  note_item("add attribute");
  if (open) {
    for (const auto& v : manifest.variables) {
      if (std::find(attributes.begin(), attributes.end(), v.name) != attributes.end()) continue;
      if (ImGui::Selectable(v.name.c_str(), false) && attributes.size() < kMaxSceneAttributes) {
        attributes.push_back(v.name);
        edited = true;
      }
      note_item("add attribute " + v.name);
    }
    ImGui::EndCombo();
  }
  return edited;
}

}  // namespace strielad::panel
