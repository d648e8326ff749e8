// SPDX-License-Identifier: Apache-2.0
// Terrain in the opaque pass: the tiles a view::TerrainTiles
// selected for the frame, drawn with depth writes so that the A-buffer's sub-volumes
// composite in front of and behind it correctly. Lambert plus ambient shading by the
// sun, with normals from the height field's gradients at the current vertical
// exaggeration; coloured by a hypsometric ramp of the height, by the tile's drape
// image where it covers the tile, and as water where the DEM has no value or lies below
// sea level (drawn flat at height 0, view/terrain_tiles.h). Fragments outside the frame's clip box (the store's
// domain) are discarded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include "lod/camera.h"
#include "lod/geometry.h"
#include "render/gl_handles.h"
#include "view/terrain_tiles.h"

namespace strielad::render {

struct TerrainDrawStats {
  std::size_t tiles = 0, triangles = 0;
};

class TerrainDrawing {
 public:
  // Needs a current context; compiles its program. \error kInternal when it does not.
  TerrainDrawing();
  // Draws into the bound framebuffer with depth test and depth writes on; uploads tiles
  // it has not seen and forgets those unused for a while. Without `drape`, tiles with a
  // drape image are coloured as those without one.
  TerrainDrawStats draw(const view::TerrainFrame& frame, const lod::Mat4& view_projection,
                        double vertical_exaggeration, const Vec3& sun_direction,
                        bool drape = true);

 private:
  struct GpuTile {
    GlVertexArray vertex_array;
    GlBuffer vertices, indices;
    GlTexture drape;
    GLsizei index_count = 0;
    std::uint64_t last_frame = 0;
  };
  GlProgram program_;
  std::unordered_map<std::uint64_t, GpuTile> tiles_;  // by TerrainTileMesh::serial
  std::uint64_t frame_ = 0;
};

}  // namespace strielad::render
