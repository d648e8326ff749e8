// SPDX-License-Identifier: Apache-2.0
#include "panel/item_probe.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <utility>

namespace strielad::panel {
namespace {

ItemRecorder& recorder() {
  static ItemRecorder r;
  return r;
}

}  // namespace

void set_item_recorder(ItemRecorder r) { recorder() = std::move(r); }

bool recording_items() { return static_cast<bool>(recorder()); }

void note_item(const std::string& key) {
  if (!recorder()) return;
  // The interactive part (a slider's frame without its label).
  const ImRect& r = GImGui->LastItemData.NavRect;
  recorder()(key, ItemRect{r.Min.x, r.Min.y, r.Max.x, r.Max.y});
}

}  // namespace strielad::panel
