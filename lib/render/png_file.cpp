// SPDX-License-Identifier: Apache-2.0
#include "render/png_file.h"

#include <stb_image_write.h>

#include "core/error.h"
#include "core/file_io.h"

namespace strielad::render {

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
