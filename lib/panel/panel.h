// SPDX-License-Identifier: Apache-2.0
// The Dear ImGui panel of strielad-view: time, view (level of detail, exaggeration,
// terrain, tracks), legend, sub-volumes (limits, axis and geographic boxes), attributes,
// slices, scene files, the shader editor and live statistics. Draws into the current
// ImGui frame and edits a PanelState (panel/panel_state.h); an edited scene is checked
// against the store's manifest first, and an invalid one is shown, not applied.
#pragma once

#include "format/manifest.h"
#include "panel/panel_state.h"

namespace strielad::panel {

void draw_panel(PanelState& state, const PanelInfo& info, const format::Manifest& manifest);

}  // namespace strielad::panel
