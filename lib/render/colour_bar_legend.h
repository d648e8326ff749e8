// SPDX-License-Identifier: Apache-2.0
// A colour map's legend drawn into a rendered image: a title, the map as a horizontal
// bar from the range's low to its high end, and the values at its ends and middle,
// on a dark box in the image's lower right corner (stb_easy_font's built-in font).
#pragma once

#include <string>

#include "render/png_file.h"

namespace strielad::render {

struct ColourBarLegend {
  std::string title;                 // e.g. "wind speed |ua, va|"
  std::string colormap = "viridis";  // render::colormap_color
  double lo = 0, hi = 1;
};

// Where the bar itself lies (pixels, rows from the top): column x + i of the bar is
// the map at lo + (hi - lo) * (i + 0.5) / width, on every row y .. y + height - 1.
struct ColourBarPlacement {
  int x = 0, y = 0, width = 0, height = 0;
};

// The bar's place in an image of `width` x `height`: sizes grow with the image's height
// (text 7 pixels high up to 360 rows, 14 up to 720, ...), the bar at most half the
// image's width.
ColourBarPlacement colour_bar_placement(int width, int height);

// Draws `legend` into `image` (every pixel opaque afterwards as before).
void draw_colour_bar_legend(RgbaImage& image, const ColourBarLegend& legend);

}  // namespace strielad::render
