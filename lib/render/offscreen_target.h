// SPDX-License-Identifier: Apache-2.0
// A framebuffer object with an RGBA8 colour texture, for rendering without a window.
#pragma once

#include "render/gl_handles.h"

namespace strielad::render {

class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height);
  GLuint framebuffer() const { return framebuffer_.get(); }
  GLuint color_texture() const { return color_.get(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  GlTexture color_;
  GlFramebuffer framebuffer_;
};

}  // namespace strielad::render
