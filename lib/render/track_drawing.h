// SPDX-License-Identifier: Apache-2.0
// Flight tracks in the opaque pass: the windowed track lines
// (view/track_window.h) as depth-writing lines and the aircraft as points, so the
// A-buffer's sub-volumes composite in front of and behind them correctly.
#pragma once

#include <array>
#include <memory>

#include "lod/camera.h"
#include "render/gl_handles.h"
#include "view/track_window.h"

namespace strielad::render {

class TrackDrawing {
 public:
  // Needs a current context; compiles its program.
  TrackDrawing();
  // Draws into the bound framebuffer with depth test and depth writes on.
  void draw(const view::TrackLines& tracks, const lod::Mat4& view_projection,
            double vertical_exaggeration, const std::array<float, 4>& color);

 private:
  GlProgram program_;
  GlVertexArray vertex_array_;
  GlBuffer buffer_;
};

}  // namespace strielad::render
