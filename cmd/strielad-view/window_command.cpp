// SPDX-License-Identifier: Apache-2.0
// `strielad-view STORE` / `--connect`: the interactive window (GLFW, OpenGL 4.5 core,
// Dear ImGui panel). The frame loop never waits on the network: the link thread
// receives and places meshes, each frame takes what arrived and uploads at most
// kUploadBytesPerFrame of it (window_viewer.cpp).
#include <epoxy/gl.h>
// epoxy before GLFW: GLFW must not include a GL header of its own.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <spdlog/spdlog.h>

#include <memory>

#include "cli/image_size.h"
#include "core/error.h"
#include "render/headless_context.h"
#include "render/volume_renderer.h"
#include "look_choice.h"
#include "viewer_args.h"
#include "viewer_session.h"
#include "window_viewer.h"

namespace strielad::view_cmd {
namespace {

class GlfwLibrary {
 public:
  GlfwLibrary() {
    glfwSetErrorCallback([](int code, const char* text) {
      spdlog::error("GLFW error {:#x}: {}", code, text);
    });
    if (!glfwInit()) {
      throw make_error(ErrorCode::kUnsupported,
                       "cannot open a window (no display? use --offscreen, or run under "
                       "xvfb-run)");
    }
  }
  ~GlfwLibrary() { glfwTerminate(); }
};

using WindowHandle = std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)>;

// A window with an OpenGL 4.5 core context, current, swapping at the display's rate.
// \error kUnsupported when the system gives no such context.
WindowHandle open_gl_window(int width, int height) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  WindowHandle window(glfwCreateWindow(width, height, "strielad-view", nullptr, nullptr),
                      glfwDestroyWindow);
  if (!window) {
    throw make_error(ErrorCode::kUnsupported,
                     "no OpenGL 4.5 core window (the renderer needs it; Mesa's llvmpipe gives it)");
  }
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(1);
  spdlog::info("window: {}", render::current_gl_description());
  return window;
}

void start_imgui(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

void stop_imgui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

}  // namespace

int run_window(const ViewerArgs& args) {
  const auto [width0, height0] = cli::parse_image_size(args.size);
  GlfwLibrary glfw;
  const WindowHandle window = open_gl_window(width0, height0);
  ViewerSession session = open_session(args);
  const auto legend = apply_look(args, session);
  render::RenderSettings settings;
  settings.max_fragment_bytes = static_cast<std::size_t>(args.max_fragment_mib * 1048576.0);
  render::VolumeRenderer renderer(settings);
  WindowViewer viewer(window.get(), args, session, renderer);
  if (legend) viewer.show_colour_bar(*legend);  // in the panel's legend
  start_imgui(window.get());
  while (!glfwWindowShouldClose(window.get())) viewer.frame();
  stop_imgui();
  return 0;
}

}  // namespace strielad::view_cmd
