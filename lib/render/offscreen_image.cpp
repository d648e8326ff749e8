// SPDX-License-Identifier: Apache-2.0
// Images rendered off screen: the framebuffer they are drawn into
// (render/offscreen_target.h) and the PNG file they are written to (render/png_file.h).
#include "render/offscreen_target.h"
#include "render/png_file.h"

#include <stb_image_write.h>

#include "core/error.h"
#include "core/file_io.h"

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

void write_png(const std::filesystem::path& path, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: image {}x{} with {} bytes of pixels",
                     path.string(), image.width, image.height, image.pixels.size());
  }
  std::vector<std::byte> encoded;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::byte>*>(context);
    const auto* bytes = static_cast<const std::byte*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(append, &encoded, image.width, image.height, 4,
                              image.pixels.data(), image.width * 4)) {
    throw make_error(ErrorCode::kIo, "{}: cannot encode the PNG image", path.string());
  }
  write_file_atomically(path, encoded);
}

}  // namespace strielad::render
