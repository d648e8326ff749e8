// SPDX-License-Identifier: Apache-2.0
// Slices in the opaque pass (formats/scene.md "Slices"): every node's
// slice triangles (render/gpu_meshes.h, view::NodeGeometry::slice_*) as opaque,
// depth-writing, two-sided geometry coloured by the slice's colour map over its range
// (NaN values, i.e. missing data, in a neutral grey) and lit lightly by the sun, so the
// A-buffer's sub-volumes composite in front of and behind them correctly.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "lod/camera.h"
#include "lod/geometry.h"
#include "render/gl_handles.h"
#include "render/gpu_meshes.h"
#include "scene/scene.h"
#include "view/slice_ranges.h"

namespace strielad::render {

// The colour of colour map `name` (one of kSliceColormaps, formats/scene.md "Colour
// maps") at t in [0, 1] (clamped; NaN gives kMissingSliceColor): linear interpolation
// between the map's published control points. Unknown names give viridis.
std::array<float, 3> colormap_color(std::string_view name, double t);

// Drawn for a missing value (NaN).
inline constexpr std::array<float, 3> kMissingSliceColor{0.5f, 0.5f, 0.5f};

// How one slice (by its position in the scene) is coloured. lo < hi.
struct SliceStyle {
  std::string colormap = "viridis";
  float lo = 0, hi = 1;
};

// The styles of a scene's slices by slot: the slice's colour map over its `range`, or
// else over the range of its values shown now (view/slice_ranges.h), or [0, 1] while
// none is shown; a range with lo == hi is widened to lo < hi.
std::vector<SliceStyle> slice_styles(const Scene& scene,
                                     const std::vector<std::optional<view::SliceRange>>& shown);

class SliceDrawing {
 public:
  // Needs a current context; compiles its program and builds the colour map texture.
  SliceDrawing();
  // Draws into the bound framebuffer with depth test (GL_LESS) and depth writes on,
  // culling off; leaves depth writes off, as TrackDrawing does. `styles[slot]` colours
  // the slice of that slot (view::kSliceVertexSlot); slots without a style are drawn
  // with viridis over [0, 1]. `sun` points towards the sun (world frame, need not be
  // unit; zero: lit from straight above). Binds texture unit kTextureUnit.
  // On the globe `globe_ratio` is the exaggeration drawn over the one the slices were
  // placed at (render/wgs84_glsl.h globe_redrawn), and `vertical_exaggeration` 1; on the
  // plane `globe_ratio` is 1.
  void draw(const GpuMeshes& meshes, const lod::Mat4& view_projection,
            double vertical_exaggeration, double globe_ratio,
            const std::vector<SliceStyle>& styles, const Vec3& sun);

  static constexpr GLuint kTextureUnit = 15;

 private:
  GlProgram program_;
  GlTexture colormaps_;
};

}  // namespace strielad::render
