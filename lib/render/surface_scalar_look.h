// SPDX-License-Identifier: Apache-2.0
// The built-in "scalar on surface" look (examples/shaders/surface_scalar.glsl): every
// sub-volume an opaque surface coloured by one attribute, or by the magnitude of a vector
// of two or three attributes (the wind speed of ua, va), through a colour map over a
// value range, as in the paper's wind-speed figure.
#pragma once

#include <string>
#include <vector>

namespace strielad::render {

struct SurfaceScalarLook {
  // Positions in the scene's attributes: one, the value itself; two or three, the
  // magnitude of the vector they form.
  std::vector<int> components;
  std::string colormap = "viridis";  // one of scene::kSliceColormaps
  double lo = 0, hi = 1;             // the colour map's ends; lo < hi
};

// The user shader of `look`: definitions of its value, range and colour map (the map's
// control points sampled from render::colormap_color, so surfaces and slices agree)
// followed by the built-in surface_scalar.glsl. \error kInvalidArgument for no or more
// than three components, a component outside the attribute slots, or !(lo < hi).
std::string surface_scalar_shader(const SurfaceScalarLook& look);

// The built-in surface_scalar.glsl as it stands (colours by the first attribute over
// [0, 1] with viridis).
const std::string& surface_scalar_source();

}  // namespace strielad::render
