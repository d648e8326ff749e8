// SPDX-License-Identifier: Apache-2.0
// Writing RGBA8 PNG images (stb_image_write, Debian libstb).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace strielad::render {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // rows top first, 4 bytes per pixel
  std::array<std::uint8_t, 4> at(int x, int y) const {
    const auto i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
  }
};

// Encoded in memory, then written atomically (core/file_io.h write_file_atomically).
// \error kInvalidArgument for an image whose size does not match its pixels; kIo
// naming the file.
void write_png(const std::filesystem::path& path, const RgbaImage& image);

}  // namespace strielad::render
