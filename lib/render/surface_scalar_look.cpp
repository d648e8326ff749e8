// SPDX-License-Identifier: Apache-2.0
#include "render/surface_scalar_look.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "core/error.h"
#include "render/scalar_surface_shader.h"  // generated from examples/shaders/surface_scalar.glsl
#include "render/slice_drawing.h"
#include "view/node_geometry.h"

namespace strielad::render {
namespace {

// Control points of the map: 65 evenly spaced samples. Every map's published points
// lie at multiples of 1/8 or 1/4, so linear interpolation between these samples is
// render::colormap_color exactly.
constexpr int kColormapSamples = 65;

std::string value_expression(const std::vector<int>& components) {
  std::vector<std::string> parts;
  for (const int c : components) parts.push_back(fmt::format("a[{}]", c));
  if (parts.size() == 1) return "(" + parts[0] + ")";
  return fmt::format("length(vec{}({}))", parts.size(), fmt::join(parts, ", "));
}

}  // namespace

std::string surface_scalar_shader(const SurfaceScalarLook& look) {
  if (look.components.empty() || look.components.size() > 3) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "scalar look: {} attributes to colour by; give one, or two or three "
                     "vector components",
                     look.components.size());
  }
  for (const int c : look.components) {
    if (c < 0 || c >= static_cast<int>(view::kViewAttributeSlots)) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "scalar look: attribute slot {} outside 0..{}", c,
                       view::kViewAttributeSlots - 1);
    }
  }
  if (!(look.lo < look.hi) || !std::isfinite(look.lo) || !std::isfinite(look.hi)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "scalar look: range {} .. {}: needs finite low < high", look.lo, look.hi);
  }
  std::string s = fmt::format("#define SCALAR_VALUE(a) {}\n", value_expression(look.components));
  s += fmt::format("#define SCALAR_RANGE vec2({:.9g}, {:.9g})\n", look.lo, look.hi);
  s += "#define SCALAR_COLORMAP_GIVEN\nconst vec3 kColormap[] = vec3[](";
  for (int i = 0; i < kColormapSamples; ++i) {
    const auto c = colormap_color(look.colormap, double(i) / (kColormapSamples - 1));
    s += fmt::format("{}vec3({:.6f}, {:.6f}, {:.6f})", i ? ", " : "", c[0], c[1], c[2]);
  }
  s += ");\n";
  return s + surface_scalar_source();
}

const std::string& surface_scalar_source() {
  static const std::string source(kScalarSurfaceShader);
  return source;
}

}  // namespace strielad::render
