// SPDX-License-Identifier: Apache-2.0
// Drives the viewer's panel (panel/panel.h) headless: an ImGui context without a
// renderer, frames drawn with synthetic mouse and keyboard input, and the controls found
// by the keys the panel reports them under (panel/item_probe.h).
#pragma once

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cfloat>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "format/manifest.h"
#include "panel/item_probe.h"
#include "panel/panel.h"
#include "view/default_scene.h"

namespace strielad::testing {

class PanelDriver {
 public:
  static constexpr int kEnter = 13, kA = 'A';

  PanelDriver(format::Manifest manifest, panel::PanelState state, panel::PanelInfo info = {})
      : manifest_(std::move(manifest)), state_(std::move(state)), info_(std::move(info)) {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1400, 4000);
    io.DeltaTime = 1.0f / 60;
    io.KeyMap[ImGuiKey_Enter] = kEnter;
    io.KeyMap[ImGuiKey_A] = kA;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    panel::set_item_recorder(
        [this](const std::string& key, const panel::ItemRect& rect) { rects_[key] = rect; });
    frame();
    frame();
  }
  ~PanelDriver() {
    panel::set_item_recorder({});
    ImGui::DestroyContext(context_);
  }
  PanelDriver(const PanelDriver&) = delete;
  PanelDriver& operator=(const PanelDriver&) = delete;

  panel::PanelState& state() { return state_; }
  panel::PanelInfo& info() { return info_; }
  bool has(const std::string& key) const { return rects_.contains(key); }

  // One frame: the panel in a window tall enough that nothing scrolls out of view.
  void frame() {
    rects_.clear();
    ImGui::NewFrame();
    if (ImGui::FindWindowByName("STRIELAD")) {
      ImGui::SetWindowSize("STRIELAD", ImVec2(1300, 3900));
    }
    panel::draw_panel(state_, info_, manifest_);
    ImGui::Render();
  }

  panel::ItemRect rect(const std::string& key) const {
    const auto it = rects_.find(key);
    if (it == rects_.end()) throw std::runtime_error("the panel drew no control '" + key + "'");
    return it->second;
  }

  // Presses and lets go of the left button at `fraction` across the control (and half
  // way down it).
  void click(const std::string& key, float fraction = 0.5f) {
    const auto r = rect(key);
    press_at(ImVec2(r.x0 + fraction * (r.x1 - r.x0), 0.5f * (r.y0 + r.y1)));
  }
  // A slider: pressed at `fraction` of its width (inside it), dragged to `fraction`
  // (beyond the slider where outside 0..1), then let go.
  void slide(const std::string& key, float fraction) {
    const auto r = rect(key);
    const float y = 0.5f * (r.y0 + r.y1);
    const float x = r.x0 + fraction * (r.x1 - r.x0);
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(std::clamp(x, r.x0 + 1, r.x1 - 1), y);
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MousePos = ImVec2(x, y);
    frame();
    io.MouseDown[0] = false;
    frame();
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    frame();
  }

  // Picks `item` from the combo `key` (opened first).
  void pick(const std::string& key, const std::string& item) {
    click(key);
    click(item);
  }

  // Clicks a text field, selects all its text, types `text` and presses Enter.
  void type(const std::string& key, const std::string& text) {
    click(key);
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    io.KeysDown[kA] = true;
    frame();
    io.KeysDown[kA] = false;
    io.KeyCtrl = false;
    frame();
    for (const char c : text) io.AddInputCharacter(static_cast<unsigned>(c));
    frame();
    io.KeysDown[kEnter] = true;
    frame();
    io.KeysDown[kEnter] = false;
    frame();
  }

 private:
  void press_at(ImVec2 at) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = at;
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    frame();
  }

  format::Manifest manifest_;
  panel::PanelState state_;
  panel::PanelInfo info_;
  ImGuiContext* context_ = nullptr;
  std::map<std::string, panel::ItemRect> rects_;
};

// A small store on the Earth: lon 0..10, lat 40..50, heights 0..10 km, two steps, the
// variables clw (0..1e-3) and ta (200..300) with their data ranges.
inline format::Manifest panel_manifest() {
  format::Manifest m;
  auto axis = [](std::string name, AxisKind kind, std::string units, double lo, double hi) {
    Axis a{std::move(name), kind, std::move(units), "", "", "", {}};
    for (int i = 0; i <= 10; ++i) a.values.push_back(lo + (hi - lo) * i / 10.0);
    return a;
  };
  m.x = axis("lon", AxisKind::kLongitude, "degrees_east", 0, 10);
  m.y = axis("lat", AxisKind::kLatitude, "degrees_north", 40, 50);
  m.z = axis("height", AxisKind::kHeight, "m", 0, 10000);
  m.time = TimeAxis{"time", "hours since 2024-06-21 00:00:00", "standard", {0, 1}};
  for (const char* name : {"clw", "ta"}) {
    format::StoreVariable v;
    v.name = name;
    m.variables.push_back(v);
  }
  m.summary = nlohmann::json::parse(
      R"({"variables": {"clw": {"min": 0, "max": 0.001}, "ta": {"min": 200, "max": 300}}})");
  return m;
}

// The panel's state for that store: its default scene.
inline panel::PanelState panel_state(const format::Manifest& manifest) {
  panel::PanelState state;
  state.scene = view::default_scene(manifest);
  state.shader_name = "built-in clouds.glsl";
  return state;
}

}  // namespace strielad::testing
