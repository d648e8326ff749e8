// SPDX-License-Identifier: Apache-2.0
#include "render/mesh_motion.h"

#include <algorithm>
#include <cmath>

namespace strielad::render {
namespace {

std::size_t keyframe_bytes(const view::DisplacementMap& map) {
  return map.points() * 3 * sizeof(float);
}

}  // namespace

std::size_t MotionTextures::sync(const std::vector<MeshMotion>& motions) {
  std::vector<Entry> kept;
  std::size_t uploaded = 0;
  bytes_ = 0;
  for (const MeshMotion& motion : motions) {
    if (!motion.map || motion.map->keyframes < 2) continue;
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) {
      return e.motion.map == motion.map;
    });
    Entry entry;
    if (it != entries_.end()) {
      entry = std::move(*it);
      entries_.erase(it);
    } else {
      const auto& map = *motion.map;
      const auto& n = map.lattice;
      for (std::size_t k = 0; k < map.keyframes; ++k) {
        GlTexture texture = make_texture(GL_TEXTURE_3D);
        const GLuint id = texture.get();
        glTextureStorage3D(id, 1, GL_RGB32F, static_cast<GLsizei>(n[0]), static_cast<GLsizei>(n[1]),
                           static_cast<GLsizei>(n[2]));
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage3D(id, 0, 0, 0, 0, static_cast<GLsizei>(n[0]), static_cast<GLsizei>(n[1]),
                            static_cast<GLsizei>(n[2]), GL_RGB, GL_FLOAT, map.keyframe(k));
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
          glTextureParameteri(id, wrap, GL_CLAMP_TO_EDGE);
        }
        entry.keyframes.push_back(std::move(texture));
        uploaded += keyframe_bytes(map);
      }
    }
    entry.motion = motion;
    bytes_ += keyframe_bytes(*motion.map) * motion.map->keyframes;
    kept.push_back(std::move(entry));
  }
  entries_ = std::move(kept);  // maps no longer in `motions` are freed here
  return uploaded;
}

MotionBinding MotionTextures::binding(std::uint32_t step) const {
  for (const Entry& e : entries_) {
    const auto& map = *e.motion.map;
    if (map.step != step) continue;
    const double fraction = map.seconds > 0 ? std::clamp(e.motion.seconds / map.seconds, 0.0, 1.0) : 0.0;
    const double k_real = fraction * static_cast<double>(map.keyframes - 1);
    const std::size_t k0 = std::min(static_cast<std::size_t>(k_real), map.keyframes - 2);
    return MotionBinding{e.keyframes[k0].get(), e.keyframes[k0 + 1].get(),
                         static_cast<float>(k_real - static_cast<double>(k0)), &map};
  }
  return {};
}

}  // namespace strielad::render
