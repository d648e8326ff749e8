// SPDX-License-Identifier: Apache-2.0
#include "panel/range_widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "panel/item_probe.h"

namespace strielad::panel {
namespace {

bool bounded_slider(const char* label, double& value, AxisRange extent, const std::string& key) {
  ImGui::SetNextItemWidth(120);
  ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &extent.lo, &extent.hi, "%.4g");
  note_item(key);
  return ImGui::IsItemDeactivatedAfterEdit();
}

}  // namespace

bool optional_bound(const char* label, std::optional<double>& bound, double fallback,
                    const std::string& key) {
  bool changed = false;
  bool on = bound.has_value();
  ImGui::PushID(label);
  if (ImGui::Checkbox("##on", &on)) {
    bound = on ? std::optional<double>(fallback) : std::nullopt;
    changed = true;
  }
  note_item(key + " on");
  ImGui::SameLine();
  if (on) {
    double v = *bound;
    ImGui::SetNextItemWidth(110);
    if (ImGui::InputDouble(label, &v, 0, 0, "%.4g")) {
      if (std::isfinite(v)) bound = v;
    }
    note_item(key);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  } else {
    ImGui::TextDisabled("%s: open", label);
  }
  ImGui::PopID();
  return changed;
}

bool range_sliders(AxisRange& range, AxisRange extent, const std::string& key) {
  bool changed = bounded_slider("##lo", range.lo, extent, key + " lo");
  ImGui::SameLine();
  changed |= bounded_slider("##hi", range.hi, extent, key + " hi");
  if (range.lo > range.hi) {
    // The bound dragged past the other one takes it along.
    if (ImGui::IsItemActive() || ImGui::IsItemDeactivated()) {
      range.lo = range.hi;
    } else {
      range.hi = range.lo;
    }
  }
  return changed;
}

bool optional_range(const char* label, std::optional<AxisRange>& range, AxisRange extent,
                    const std::string& key) {
  bool changed = false;
  ImGui::PushID(label);
  bool on = range.has_value();
  if (ImGui::Checkbox(label, &on)) {
    range = on ? std::optional<AxisRange>(extent) : std::nullopt;
    changed = true;
  }
  note_item(key + " on");
  if (range) {
    ImGui::SameLine();
    changed |= range_sliders(*range, extent, key);
  }
  ImGui::PopID();
  return changed;
}

}  // namespace strielad::panel
