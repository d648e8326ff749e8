// SPDX-License-Identifier: Apache-2.0
// The interactive window's mouse and keyboard, once per frame: the camera moves with
// the mouse (orbit, pan, zoom) and the keys (fly), and the keys play, pause and step
// through time. The panel takes the input it wants first (Dear ImGui's WantCapture*).
#pragma once

#include <imgui.h>

#include "view/orbit_camera.h"
#include "panel/panel_state.h"

struct GLFWwindow;

namespace strielad::view_cmd {

// The mouse as seen in the previous frame.
struct Mouse {
  double x = 0, y = 0;
  bool left = false, pan = false;
};

// Left drag orbits, right or middle drag pans (by the fraction of the framebuffer's
// `height` moved), the wheel zooms; nothing while the panel takes the mouse.
void apply_mouse(GLFWwindow* window, const ImGuiIO& io, int height, Mouse& mouse,
                 view::OrbitCamera& camera);

// W/S, D/A and E/Q fly forward, right and up at a speed that follows the camera's
// distance over `dt` seconds; space plays or pauses, the arrows step through the
// `time_steps` steps. Nothing while the panel takes the keyboard.
void apply_keys(GLFWwindow* window, const ImGuiIO& io, double dt, int time_steps,
                view::OrbitCamera& camera, panel::PanelState& state);

}  // namespace strielad::view_cmd
