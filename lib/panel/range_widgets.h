// SPDX-License-Identifier: Apache-2.0
// Small ImGui widgets the panel's scene editors share. Each returns true when an edit is
// complete (a checkbox toggled, a slider or field let go after a change).
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace strielad::panel {

// An optional bound: a checkbox (open or not) and the value; turned on, it starts at
// `fallback`. `key` names it to the item probe (panel/item_probe.h).
bool optional_bound(const char* label, std::optional<double>& bound, double fallback,
                    const std::string& key);

// An optional range with sliders bounded by `extent`: a checkbox ("present"; turned on,
// the whole extent) and lo and hi sliders; lo stays <= hi.
bool optional_range(const char* label, std::optional<AxisRange>& range, AxisRange extent,
                    const std::string& key);

// lo and hi sliders bounded by `extent`, lo kept <= hi.
bool range_sliders(AxisRange& range, AxisRange extent, const std::string& key);

}  // namespace strielad::panel
