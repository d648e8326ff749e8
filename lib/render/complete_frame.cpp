// SPDX-License-Identifier: Apache-2.0
#include "render/complete_frame.h"

#include <thread>

#include "core/error.h"

namespace strielad::render {

FrameInputs frame_inputs(const view::ViewController& controller, const lod::Camera& camera) {
  FrameInputs inputs;
  inputs.camera = camera;
  inputs.vertical_exaggeration = controller.renderer_vertical_scale();
  inputs.globe_exaggeration =
      controller.frame().globe() ? controller.frame().vertical_exaggeration() : 0.0;
  inputs.globe_placed_exaggeration =
      controller.frame().globe() ? controller.link().placer().placed_exaggeration() : 0.0;
  inputs.mirrored = controller.link().placer().mirrored();
  const Scene& scene = controller.scene();
  if (!scene.slices.empty()) {
    inputs.slice_styles =
        slice_styles(scene, view::shown_slice_ranges(controller.meshes(), scene.slices.size()));
  }
  return inputs;
}

CompleteFrame render_complete_frame(view::ViewController& controller, VolumeRenderer& renderer,
                                    OffscreenTarget& target, FrameInputs inputs,
                                    const CompleteFrameOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  CompleteFrame frame;
  while (true) {
    const auto counters = controller.update(inputs.camera);
    if (controller.connection_lost()) {
      throw make_error(ErrorCode::kIo, "{}",
                       controller.last_error().value_or("connection to the server lost"));
    }
    if (counters.cut_changes == 0 && controller.complete()) break;
    if (clock::now() - start > options.timeout) {
      throw make_error(ErrorCode::kCancelled,
                       "the view was not complete after {} s: {} of {} nodes answered",
                       std::chrono::duration_cast<std::chrono::seconds>(options.timeout).count(),
                       controller.meshes().size() - controller.meshes().pending(),
                       controller.meshes().size());
    }
    if (counters.events == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  frame.wait_ms = std::chrono::duration<double, std::milli>(clock::now() - start).count();
  if (options.outline_cut) {
    inputs.outline_boxes.clear();
    inputs.outline_colors.clear();
    for (const auto& n : controller.cut().nodes()) {
      inputs.outline_boxes.push_back(controller.cut().box(n.node));
    }
  }
  if (options.fade) {
    options.fade->sync(renderer.meshes(), controller.meshes(), SIZE_MAX, options.fade_seconds);
  } else {
    renderer.meshes().sync(controller.meshes(), SIZE_MAX);
  }
  // Slices without a range span the values shown: now that every node has arrived.
  if (!controller.scene().slices.empty()) {
    inputs.slice_styles = slice_styles(
        controller.scene(),
        view::shown_slice_ranges(controller.meshes(), controller.scene().slices.size()));
  }
  frame.slice_styles = inputs.slice_styles;
  const auto t0 = clock::now();
  if (options.fade) {
    frame.stats = options.fade->render(renderer, inputs, target.framebuffer(), target.width(),
                                       target.height());
    frame.fade_weight = options.fade->last_weight();
  } else {
    frame.stats = renderer.render(inputs, target.framebuffer(), target.width(), target.height());
  }
  frame.image = RgbaImage{target.width(), target.height(),
                          VolumeRenderer::read_pixels(target.framebuffer(), target.width(),
                                                      target.height())};
  frame.render_ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  frame.cut_nodes = controller.meshes().size();
  frame.nodes_with_mesh = renderer.meshes().meshes().size();
  return frame;
}

}  // namespace strielad::render
