// SPDX-License-Identifier: Apache-2.0
#include "render/colour_bar_legend.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "render/slice_drawing.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace strielad::render {
namespace {

// Text rows of stb_easy_font (capitals and digits are 7 units high) per scale unit.
constexpr int kTextUnits = 7;

int scale_for(int height) { return std::max(1, (height + 359) / 360); }

// `c` over pixel (x, y) with opacity `a`; outside the image, nothing.
void blend(RgbaImage& image, int x, int y, const std::array<float, 3>& c, float a) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  auto* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
  for (int k = 0; k < 3; ++k) {
    p[k] = static_cast<std::uint8_t>(std::lround(p[k] * (1 - a) + c[k] * 255.0f * a));
  }
  p[3] = 255;
}

void fill(RgbaImage& image, int x0, int y0, int x1, int y1, const std::array<float, 3>& c,
          float a) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) blend(image, x, y, c, a);
  }
}

int text_width(const std::string& text, int scale) {
  std::vector<char> s(text.begin(), text.end());
  s.push_back('\0');
  return stb_easy_font_width(s.data()) * scale;
}

// `text` with its top left corner at (x, y), white.
void draw_text(RgbaImage& image, const std::string& text, int x, int y, int scale) {
  std::vector<char> s(text.begin(), text.end());
  s.push_back('\0');
  std::vector<char> quads(64 * 1024);  // 64 bytes per quad
  const int n = stb_easy_font_print(0, 0, s.data(), nullptr, quads.data(),
                                    static_cast<int>(quads.size()));
  for (int q = 0; q < n; ++q) {
    float v[4][4];
    std::memcpy(v, quads.data() + q * 64, sizeof v);  // x, y, z, colour per vertex
    const float qx0 = std::min(v[0][0], v[2][0]), qx1 = std::max(v[0][0], v[2][0]);
    const float qy0 = std::min(v[0][1], v[2][1]), qy1 = std::max(v[0][1], v[2][1]);
    fill(image, x + std::lround(qx0 * scale), y + std::lround(qy0 * scale),
         x + std::lround(qx1 * scale), y + std::lround(qy1 * scale), {1, 1, 1}, 1.0f);
  }
}

std::string value_label(double v) { return fmt::format("{:.3g}", v); }

}  // namespace

ColourBarPlacement colour_bar_placement(int width, int height) {
  const int s = scale_for(height);
  const int pad = 6 * s;
  ColourBarPlacement p;
  p.width = std::max(8, std::min(128 * s, width / 2));
  p.height = 8 * s;
  // The box, from the bottom: pad, labels, gap, bar, gap, title, pad.
  const int box_bottom = height - pad;
  p.x = width - pad - pad - p.width;
  p.y = box_bottom - pad - kTextUnits * s - s * 3 - p.height;
  return p;
}

void draw_colour_bar_legend(RgbaImage& image, const ColourBarLegend& legend) {
  const int s = scale_for(image.height);
  const int pad = 6 * s;
  const auto bar = colour_bar_placement(image.width, image.height);
  const int title_y = bar.y - s * 3 - kTextUnits * s;
  const int labels_y = bar.y + bar.height + s * 3;
  const int title_width = text_width(legend.title, s);
  const int box_x1 = bar.x + bar.width + pad;
  const int box_x0 = std::min(bar.x, box_x1 - pad - title_width) - pad;
  fill(image, box_x0, title_y - pad, box_x1, labels_y + kTextUnits * s + pad, {0, 0, 0}, 0.6f);
  for (int i = 0; i < bar.width; ++i) {
    const auto c = colormap_color(legend.colormap, (i + 0.5) / bar.width);
    fill(image, bar.x + i, bar.y, bar.x + i + 1, bar.y + bar.height, c, 1.0f);
  }
  draw_text(image, legend.title, box_x1 - pad - title_width, title_y, s);
  const std::string lo = value_label(legend.lo), hi = value_label(legend.hi);
  const std::string mid = value_label(0.5 * (legend.lo + legend.hi));
  draw_text(image, lo, bar.x, labels_y, s);
  draw_text(image, mid, bar.x + (bar.width - text_width(mid, s)) / 2, labels_y, s);
  draw_text(image, hi, bar.x + bar.width - text_width(hi, s), labels_y, s);
}

}  // namespace strielad::render
