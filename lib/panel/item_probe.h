// SPDX-License-Identifier: Apache-2.0
// Where the panel's controls are on screen, for tests that drive the panel with
// synthetic mouse and keyboard input: with a recorder set, the panel reports each
// control's key ("add slice", "slice 1 value", ...) and rectangle as it draws it.
#pragma once

#include <functional>
#include <string>

namespace strielad::panel {

struct ItemRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

using ItemRecorder = std::function<void(const std::string& key, const ItemRect& rect)>;

// Sets the recorder (an empty one: none, the default).
void set_item_recorder(ItemRecorder recorder);
bool recording_items();
// Reports the last ImGui item (its interactive rectangle) under `key` (nothing without a recorder).
void note_item(const std::string& key);

}  // namespace strielad::panel
