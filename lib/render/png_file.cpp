// SPDX-License-Identifier: Apache-2.0
#include "render/png_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <system_error>

#include "core/error.h"

namespace strielad::render {

void write_png(const std::filesystem::path& path, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: image {}x{} with {} bytes of pixels",
                     path.string(), image.width, image.height, image.pixels.size());
  }
  auto temporary = path;
  temporary += ".partial";
  if (!stbi_write_png(temporary.c_str(), image.width, image.height, 4, image.pixels.data(),
                      image.width * 4)) {
    throw make_error(ErrorCode::kIo, "{}: cannot write the PNG image", path.string());
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw make_error(ErrorCode::kIo, "{}: cannot rename the written image into place",
                     path.string());
  }
}

RgbaImage read_png(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such image", path.string());
  }
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) {
    throw make_error(ErrorCode::kInvalidInput, "{}: not a readable image: {}", path.string(),
                     stbi_failure_reason());
  }
  RgbaImage image{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
  stbi_image_free(data);
  return image;
}

}  // namespace strielad::render
