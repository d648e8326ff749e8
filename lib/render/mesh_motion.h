// SPDX-License-Identifier: Apache-2.0
// Meshes moved with the wind on the GPU: the keyframes of a
// view::DisplacementMap as 3D textures (RGB32F, linear filtering), and per draw the two
// keyframes around the mesh's time with the weight between them. The geometry vertex
// shader adds the displacement (trilinear in space, linear between the keyframes) to
// each vertex; view::DisplacementMap::displacement_at is the same on the CPU. On the
// globe it moves the vertex in longitude, latitude and height and places it back on the
// ellipsoid (view::DisplacementMap::moved_on_globe on the CPU).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/gl_handles.h"
#include "view/displacement_map.h"

namespace strielad::render {

using view::MeshMotion;

// What one draw needs: two keyframe textures and the weight of the second.
struct MotionBinding {
  GLuint from = 0, to = 0;
  float weight = 0;
  const view::DisplacementMap* map = nullptr;
};

class MotionTextures {
 public:
  // Uploads the keyframes of maps not seen before and frees those of maps no longer in
  // `motions`. Returns the bytes uploaded.
  std::size_t sync(const std::vector<MeshMotion>& motions);
  // The binding for meshes of `step` (map null: they do not move).
  MotionBinding binding(std::uint32_t step) const;
  std::size_t bytes() const { return bytes_; }

 private:
  struct Entry {
    MeshMotion motion;
    std::vector<GlTexture> keyframes;
  };
  std::vector<Entry> entries_;
  std::size_t bytes_ = 0;
};

}  // namespace strielad::render
