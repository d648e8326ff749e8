// SPDX-License-Identifier: Apache-2.0
// Rendering a view once everything it shows has arrived: the headless path of
// strielad-view (--offscreen), the render tests and the view benchmark. The cut for the
// camera is sent, results are applied as they come, and the frame is rendered when the
// cut no longer changes and the current request is answered for every node of it
// (view::ViewController::complete).
#pragma once

#include <chrono>
#include <cstddef>

#include "render/lod_fade.h"
#include "render/offscreen_target.h"
#include "render/png_file.h"
#include "render/volume_renderer.h"
#include "view/view_controller.h"

namespace strielad::render {

struct CompleteFrameOptions {
  std::chrono::milliseconds timeout{std::chrono::minutes(10)};
  // Outline the boxes of the cut that was complete (replacing inputs.outline_boxes).
  bool outline_cut = false;
  // Level-of-detail cross-fade (render/lod_fade.h); null: the new cut is drawn at once.
  // `fade_seconds` pass before the frame (a camera path: 1 / fps).
  LodCrossFade* fade = nullptr;
  double fade_seconds = 0;
};

struct CompleteFrame {
  RgbaImage image;
  FrameStats stats;           // of the last render
  double wait_ms = 0;         // from the call to the cut being complete
  double render_ms = 0;       // wall time of the last render, read-back included
  std::size_t cut_nodes = 0;
  std::size_t nodes_with_mesh = 0;
  std::vector<SliceStyle> slice_styles;  // the slices' colour maps and ranges drawn
  double fade_weight = 1;     // the incoming set's weight in a cross-fade (1: none)
};

// \error kCancelled when the cut is not complete within the timeout; kIo when the
// connection to the server is lost (the message says why).
CompleteFrame render_complete_frame(view::ViewController& controller, VolumeRenderer& renderer,
                                    OffscreenTarget& target, FrameInputs inputs,
                                    const CompleteFrameOptions& options = {});

// The inputs a frame needs from a controller (exaggeration, mirroring, sub-volume
// slots are set on the renderer by the caller) for `camera`.
FrameInputs frame_inputs(const view::ViewController& controller, const lod::Camera& camera);

}  // namespace strielad::render
