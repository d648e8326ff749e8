// SPDX-License-Identifier: Apache-2.0
// Vertices of x, y, z, r, g, b, a floats (lines and points of the outline and track
// drawings) uploaded into a fresh buffer and bound to a vertex array: attribute 0 the
// position, attribute 1 the colour (render/volume_shaders.h line program).
#pragma once

#include <vector>

#include "render/gl_handles.h"

namespace strielad::render {

inline constexpr int kColoredVertexFloats = 7;

inline void upload_colored_vertices(GLuint vertex_array, GlBuffer& buffer,
                                    const std::vector<float>& data) {
  buffer = make_buffer();
  glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                       data.data(), 0);
  glVertexArrayVertexBuffer(vertex_array, 0, buffer.get(), 0, kColoredVertexFloats * sizeof(float));
  glEnableVertexArrayAttrib(vertex_array, 0);
  glVertexArrayAttribFormat(vertex_array, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array, 0, 0);
  glEnableVertexArrayAttrib(vertex_array, 1);
  glVertexArrayAttribFormat(vertex_array, 1, 4, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(vertex_array, 1, 0);
}

}  // namespace strielad::render
