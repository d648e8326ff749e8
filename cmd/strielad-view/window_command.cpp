// SPDX-License-Identifier: Apache-2.0
// `strielad-view STORE` / `--connect`: the interactive window (GLFW, OpenGL 4.5 core,
// Dear ImGui panel). The frame loop never waits on the network: the link thread
// receives and places meshes, each frame takes what arrived and uploads at most
// kUploadBytesPerFrame of it.
#include <epoxy/gl.h>
// epoxy before GLFW: GLFW must not include a GL header of its own.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli/image_size.h"
#include "core/error.h"
#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "render/png_file.h"
#include "render/volume_renderer.h"
#include "shader_file_watch.h"
#include "view/advection_playback.h"
#include "view/default_scene.h"
#include "view/orbit_camera.h"
#include "view/sun_direction.h"
#include "view/view_controller.h"
#include "viewer_args.h"
#include "viewer_panel.h"
#include "viewer_session.h"

namespace strielad::view_cmd {
namespace {

using clock_type = std::chrono::steady_clock;

// Mesh bytes uploaded to the GPU per frame at most (a burst of results spreads over
// frames instead of stalling one).
constexpr std::size_t kUploadBytesPerFrame = 48u << 20;

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

struct Mouse {
  double x = 0, y = 0;
  bool left = false, pan = false;
};

void apply_shader(render::VolumeRenderer& renderer, PanelState& state, const std::string& text,
                  const std::string& name) {
  const auto update = renderer.set_user_shader(text, name);
  if (update.ok) {
    state.shader_error.clear();
    state.shader_error_line = 0;
    spdlog::info("{}: shader compiled", name);
  } else {
    state.shader_error = update.error;
    state.shader_error_line = update.error_line;
    spdlog::warn("{} (the last good shader keeps running)", update.error);
  }
}

}  // namespace

int run_window(const ViewerArgs& args) {
  const auto [width0, height0] = cli::parse_image_size(args.size);
  GlfwLibrary glfw;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)> window(
      glfwCreateWindow(width0, height0, "strielad-view", nullptr, nullptr), glfwDestroyWindow);
  if (!window) {
    throw make_error(ErrorCode::kUnsupported,
                     "no OpenGL 4.5 core window (the renderer needs it; Mesa's llvmpipe gives it)");
  }
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(1);
  spdlog::info("window: {}", render::current_gl_description());

  ViewerSession session = open_session(args);
  const auto& manifest = session.link->manifest();
  render::RenderSettings settings;
  settings.max_fragment_bytes = static_cast<std::size_t>(args.max_fragment_mib * 1048576.0);
  render::VolumeRenderer renderer(settings);
  PanelState state;
  state.shader_name = session.shader_name;
  state.shader_text = session.shader_source.empty() ? renderer.user_shader_source()
                                                    : session.shader_source;
  if (!session.shader_source.empty()) {
    apply_shader(renderer, state, session.shader_source, session.shader_name);
  }
  std::optional<ShaderFileWatch> watch;
  if (!args.shader_file.empty()) watch.emplace(args.shader_file);

  view::ViewOptions options;
  options.vertical_exaggeration = session.exaggeration;
  options.lod.split_solid_angle_sr = args.lod_threshold_sr;
  options.lod.max_nodes = args.max_nodes;
  view::ViewController controller(*session.link, session.scene, options);
  const auto set_layout = [&](const Scene& scene) {
    std::vector<std::uint32_t> ids;
    for (const auto& s : scene.subvolumes) ids.push_back(s.id);
    const auto update = renderer.set_scene_layout(ids, scene.attributes);
    if (!update.ok) state.shader_error = update.error;
  };
  set_layout(session.scene);
  state.scene = session.scene;
  state.time_step = static_cast<int>(session.scene.time);
  state.exaggeration = static_cast<float>(session.exaggeration);
  state.lod_threshold_sr = static_cast<float>(args.lod_threshold_sr);
  state.max_nodes = static_cast<int>(args.max_nodes);
  state.boxes = args.boxes;
  view::OrbitCamera camera(controller.frame().domain());
  std::optional<view::AdvectionPlayback> playback;
  if (session.advection) {
    playback.emplace(*session.advection);
    playback->set_step(controller.time_step());
    state.advect_available = true;
    state.advect = args.advect;
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.get(), true);
  ImGui_ImplOpenGL3_Init("#version 450");

  std::shared_ptr<const view::TrackLines> tracks;
  std::uint32_t tracks_step = ~0u;
  double tracks_seconds = -1;
  Mouse mouse;
  PanelInfo info;
  info.advect_status = session.advection_status;
  info.vertical_placement = "heights: " + session.vertical_placement;
  info.dataset = session.dataset_name;
  auto last_frame = clock_type::now();
  auto last_stats = last_frame;
  auto last_step = last_frame;
  double frame_s_smoothed = 0;
  std::size_t frames = 0;
  while (!glfwWindowShouldClose(window.get())) {
    glfwPollEvents();
    const auto now = clock_type::now();
    const double dt = std::chrono::duration<double>(now - last_frame).count();
    last_frame = now;
    // Frame time smoothed over about ten frames.
    frame_s_smoothed = frame_s_smoothed == 0 ? dt : 0.9 * frame_s_smoothed + 0.1 * dt;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();

    // Camera input (when the panel does not take it).
    double mx = 0, my = 0;
    glfwGetCursorPos(window.get(), &mx, &my);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window.get(), &width, &height);
    if (!io.WantCaptureMouse) {
      const bool left = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
      const bool pan = glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                       glfwGetMouseButton(window.get(), GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
      if (left && mouse.left) camera.orbit(-(mx - mouse.x) * 0.3, (my - mouse.y) * 0.3);
      if (pan && mouse.pan && height > 0) {
        camera.pan(-(mx - mouse.x) / height, (my - mouse.y) / height);
      }
      mouse.left = left;
      mouse.pan = pan;
      if (io.MouseWheel != 0) camera.zoom(std::pow(0.88, io.MouseWheel));
    } else {
      mouse.left = mouse.pan = false;
    }
    mouse.x = mx;
    mouse.y = my;
    if (!io.WantCaptureKeyboard) {
      const double speed = camera.distance() * 0.6 * dt;
      const auto key = [&](int k) { return glfwGetKey(window.get(), k) == GLFW_PRESS; };
      camera.fly((key(GLFW_KEY_W) - key(GLFW_KEY_S)) * speed, (key(GLFW_KEY_D) - key(GLFW_KEY_A)) * speed,
                 (key(GLFW_KEY_E) - key(GLFW_KEY_Q)) * speed);
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space))) state.playing = !state.playing;
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) {
        state.time_step = std::min(state.time_step + 1, int(manifest.time.values.size()) - 1);
        state.time_changed = true;
      }
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) {
        state.time_step = std::max(state.time_step - 1, 0);
        state.time_changed = true;
      }
    }

    // Playback: the next step once the current one is complete, at most play_fps; with
    // advection, once the meshes have moved to the step's end (view/advection_playback.h).
    auto tick = view::AdvectionPlayback::Tick::kNoMap;
    if (playback && state.advect) {
      playback->set_seconds(state.advect_seconds);
      tick = playback->tick(dt, state.playing, state.play_fps, controller.complete());
      state.advect_seconds = static_cast<float>(playback->seconds());
    }
    const bool plain_step_due =
        tick == view::AdvectionPlayback::Tick::kNoMap && controller.complete() &&
        std::chrono::duration<double>(now - last_step).count() >= 1.0 / state.play_fps;
    if (state.playing && (tick == view::AdvectionPlayback::Tick::kNextStep || plain_step_due)) {
      state.time_step = (state.time_step + 1) % int(manifest.time.values.size());
      state.time_changed = true;
    }

    // Apply what the panel and keys changed (errors are shown, nothing stops).
    try {
      if (state.time_changed) {
        state.time_changed = false;
        controller.set_time(static_cast<std::uint32_t>(state.time_step));
        state.scene.time = controller.time_step();
        last_step = now;
        if (playback) playback->set_step(controller.time_step());
        state.advect_seconds = 0;
      }
      if (state.scene_changed) {
        state.scene_changed = false;
        state.scene.time = controller.time_step();
        controller.set_scene(state.scene);
        set_layout(state.scene);
        info.error.clear();
      }
      if (state.lod_changed) {
        state.lod_changed = false;
        auto lod = controller.options().lod;
        lod.split_solid_angle_sr = state.lod_threshold_sr;
        lod.max_nodes = static_cast<std::size_t>(std::max(state.max_nodes, 1));
        controller.set_lod_options(lod);
      }
      if (state.exaggeration_changed) {
        state.exaggeration_changed = false;
        const double ratio = state.exaggeration / controller.options().vertical_exaggeration;
        controller.set_vertical_exaggeration(state.exaggeration);
        camera.rescale_vertical(ratio, controller.frame().domain());
      }
    } catch (const Error& e) {
      info.error = e.what();
    }
    if (state.home) {
      state.home = false;
      camera.home();
    }
    if (watch) {
      if (auto text = watch->poll()) {
        state.shader_text = *text;
        apply_shader(renderer, state, *text, state.shader_name);
      }
    }
    if (state.shader_reload && watch) {
      state.shader_reload = false;
      try {
        state.shader_text = read_text_file(args.shader_file);
        apply_shader(renderer, state, state.shader_text, state.shader_name);
      } catch (const Error& e) {
        state.shader_error = e.what();
      }
    }
    if (state.shader_compile) {
      state.shader_compile = false;
      apply_shader(renderer, state, state.shader_text, state.shader_name);
    }

    // The cut, the results that arrived, the uploads, the frame.
    const double aspect = height > 0 ? double(width) / double(height) : 1.0;
    const lod::Camera cam = camera.camera(aspect);
    const auto counters = controller.update(cam);
    renderer.meshes().sync(controller.meshes(), kUploadBytesPerFrame);
    render::FrameInputs inputs = render::frame_inputs(controller, cam);
    inputs.time_seconds = view::seconds_since_first_step(manifest, controller.time_step());
    if (playback && state.advect) {
      inputs.motions = playback->motions();
      inputs.time_seconds += playback->seconds();
    }
    const double seconds_after = playback && state.advect ? playback->seconds() : 0.0;
    if (session.tracks) {
      // Windowed again only when the time moved.
      if (controller.time_step() != tracks_step || seconds_after != tracks_seconds) {
        tracks = tracks_at(session, args, controller.time_step(), seconds_after);
        tracks_step = controller.time_step();
        tracks_seconds = seconds_after;
      }
      inputs.tracks = tracks;
    }
    if (args.sun_fixed_direction) inputs.sun_direction = *args.sun_fixed_direction;
    if (args.sun == "time") {
      const double after = seconds_after;
      if (const auto sun = view::sun_at_step(controller.link().placer().frame(), manifest,
                                             controller.time_step(), after)) {
        inputs.sun_direction = sun->direction;
        info.sun_elevation_deg = sun->position.elevation_deg;
        info.sun_viewpoint = sun->viewpoint == view::SunViewpoint::kDomainCentre
                                 ? "over the domain centre"
                                 : fmt::format("over the domain's sunniest point ({:.1f}, {:.1f})",
                                               sun->latitude_deg, sun->longitude_deg);
      }
    }
    if (session.terrain) {
      inputs.terrain = session.terrain->update(cam, controller.options().vertical_exaggeration,
                                               height);
      const auto t = session.terrain->status();
      info.terrain = fmt::format("terrain: {} tiles, {} triangles; {} loaded ({:.1f} ms each), {} "
                                 "pending, cache {:.0f} MiB{}",
                                 t.selected, t.triangles, t.loads,
                                 t.loads ? t.load_ms / double(t.loads) : 0.0, t.pending,
                                 double(t.cache_bytes) / 1048576.0,
                                 t.error.empty() ? "" : "; " + t.error);
    }
    info.step_seconds = playback ? playback->step_seconds() : 0;
    if (state.boxes) {
      for (const auto& n : controller.cut().nodes()) {
        inputs.outline_boxes.push_back(controller.cut().box(n.node));
        const bool current = controller.meshes().entries().contains(n.node) &&
                             controller.meshes().entries().at(n.node).current;
        inputs.outline_colors.push_back(current ? std::array<float, 4>{0.95f, 0.85f, 0.3f, 0.5f}
                                                : std::array<float, 4>{0.9f, 0.3f, 0.3f, 0.6f});
      }
    }
    info.frame = renderer.render(inputs, 0, width, height);

    // Statistics.
    if (std::chrono::duration<double>(now - last_stats).count() > 1.0) {
      last_stats = now;
      controller.link().request_stats();
    }
    const auto link = controller.link().counters();
    info.fps = frame_s_smoothed > 0 ? 1.0 / frame_s_smoothed : 0;
    info.frame_ms = frame_s_smoothed * 1000;
    info.cut_update_ms = counters.cut_update_ms;
    info.cut_nodes = controller.meshes().size();
    info.pending = controller.meshes().pending();
    info.stale_shown = controller.meshes().stale_shown();
    info.complete = controller.complete();
    info.results = link.results;
    info.failed = link.failed;
    info.bytes_received = link.bytes_received;
    info.nodes_moved = info.frame.nodes_moved;
    info.gpu_triangles = renderer.meshes().triangles();
    info.gpu_bytes = renderer.meshes().bytes();
    if (controller.last_error()) info.error = *controller.last_error();
    if (!controller.server_stats_json().empty()) {
      try {
        const auto stats = nlohmann::json::parse(controller.server_stats_json());
        info.cache_hit_rate = stats.at("cache").at("hit_rate").get<double>();
      } catch (const std::exception&) {
        info.cache_hit_rate = -1;
      }
    }
    draw_panel(state, info, manifest);
    ImGui::Render();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    ++frames;
    const bool last = args.frames > 0 && frames >= args.frames;
    if (last && !args.screenshot.empty()) {
      glFinish();
      render::write_png(args.screenshot,
                        render::RgbaImage{width, height,
                                          render::VolumeRenderer::read_pixels(0, width, height)});
      spdlog::info("{}: screenshot of frame {}", args.screenshot, frames);
    }
    glfwSwapBuffers(window.get());
    if (last) glfwSetWindowShouldClose(window.get(), GLFW_TRUE);
    if (controller.connection_lost()) {
      glfwSetWindowTitle(window.get(), "strielad-view: connection to the server lost");
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace strielad::view_cmd
