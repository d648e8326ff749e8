// SPDX-License-Identifier: Apache-2.0
// The panel's sections (panel/panel.h draws them in order). The scene editors return
// whether they completed an edit of state.scene; draw_panel checks the edited scene
// before it is applied.
#pragma once

#include "format/manifest.h"
#include "panel/panel_state.h"

namespace strielad::panel {

void time_section(PanelState& state, const PanelInfo& info, const format::Manifest& manifest);
void view_section(PanelState& state, const PanelInfo& info);
void legend_section(const PanelState& state, const PanelInfo& info);
// Sub-volumes: name, limits, axis box, geographic box (on the Earth only), add, remove.
bool subvolume_section(PanelState& state, const PanelInfo& info,
                       const format::Manifest& manifest);
bool attribute_section(PanelState& state, const format::Manifest& manifest);
bool slice_section(PanelState& state, const format::Manifest& manifest);
// Save and load the scene and camera (panel/scene_files.h).
void files_section(PanelState& state, const format::Manifest& manifest);
void shader_section(PanelState& state);
void statistics_section(const PanelInfo& info);

}  // namespace strielad::panel
