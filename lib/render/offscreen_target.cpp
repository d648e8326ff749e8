// SPDX-License-Identifier: Apache-2.0
#include "render/offscreen_target.h"

#include "core/error.h"

namespace strielad::render {

OffscreenTarget::OffscreenTarget(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "image size {}x{}: width and height must be 1 to 16384", width, height);
  }
  color_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(color_.get(), 1, GL_RGBA8, width, height);
  framebuffer_ = make_framebuffer();
  glNamedFramebufferTexture(framebuffer_.get(), GL_COLOR_ATTACHMENT0, color_.get(), 0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw make_error(ErrorCode::kUnsupported, "offscreen framebuffer {}x{} incomplete ({:#x})",
                     width, height, status);
  }
}

}  // namespace strielad::render
