// SPDX-License-Identifier: Apache-2.0
#include "window_input.h"

#include <epoxy/gl.h>
// epoxy before GLFW: GLFW must not include a GL header of its own.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace strielad::view_cmd {

void apply_mouse(GLFWwindow* window, const ImGuiIO& io, int height, Mouse& mouse,
                 view::OrbitCamera& camera) {
  double mx = 0, my = 0;
  glfwGetCursorPos(window, &mx, &my);
  if (!io.WantCaptureMouse) {
    const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool pan = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                     glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    const double drag = 0.3 * camera.drag_scale();
    if (left && mouse.left) camera.orbit(-(mx - mouse.x) * drag, (my - mouse.y) * drag);
    if (pan && mouse.pan && height > 0) {
      camera.pan(-(mx - mouse.x) / height, (my - mouse.y) / height);
    }
    mouse.left = left;
    mouse.pan = pan;
    if (io.MouseWheel != 0 && height > 0) {
      // The cursor in window coordinates, as fractions of the window's height.
      int w = 0, h = 0;
      glfwGetWindowSize(window, &w, &h);
      if (h > 0) {
        camera.zoom_at(std::pow(0.88, io.MouseWheel), (mx - 0.5 * w) / h, (0.5 * h - my) / h);
      }
    }
  } else {
    mouse.left = mouse.pan = false;
  }
  mouse.x = mx;
  mouse.y = my;
}

void apply_keys(GLFWwindow* window, const ImGuiIO& io, double dt, int time_steps,
                view::OrbitCamera& camera, panel::PanelState& state) {
  if (io.WantCaptureKeyboard) return;
  const double speed = camera.distance() * 0.6 * dt;
  const auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS; };
  camera.fly((key(GLFW_KEY_W) - key(GLFW_KEY_S)) * speed, (key(GLFW_KEY_D) - key(GLFW_KEY_A)) * speed,
             (key(GLFW_KEY_E) - key(GLFW_KEY_Q)) * speed);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space))) state.playing = !state.playing;
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) {
    state.time_step = std::min(state.time_step + 1, time_steps - 1);
    state.time_changed = true;
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) {
    state.time_step = std::max(state.time_step - 1, 0);
    state.time_changed = true;
  }
}

}  // namespace strielad::view_cmd
