// SPDX-License-Identifier: Apache-2.0
#include "render/track_drawing.h"

#include <vector>

#include "render/colored_vertices.h"
#include "render/shader_program.h"
#include "render/volume_shaders.h"

namespace strielad::render {

TrackDrawing::TrackDrawing() {
  program_ = compile_builtin_program(line_vertex_source(), line_fragment_source(), "track");
  vertex_array_ = make_vertex_array();
}

void TrackDrawing::draw(const view::TrackLines& tracks, const lod::Mat4& view_projection,
                        double vertical_exaggeration, const std::array<float, 4>& color) {
  const std::size_t lines = tracks.segments.size() / 3, heads = tracks.heads.size() / 3;
  if (lines + heads == 0) return;
  // x, y, z (exaggerated), r, g, b, a per vertex; heads brighter.
  std::vector<float> data;
  data.reserve((lines + heads) * 7);
  const auto append = [&](const std::vector<float>& points, float brightness) {
    for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
      data.insert(data.end(), {points[i], points[i + 1],
                               static_cast<float>(points[i + 2] * vertical_exaggeration),
                               color[0] * brightness, color[1] * brightness,
                               color[2] * brightness, color[3]});
    }
  };
  append(tracks.segments, 0.8f);
  append(tracks.heads, 1.0f);
  const GLuint vao = vertex_array_.get();
  upload_colored_vertices(vao, buffer_, data);
  glUseProgram(program_.get());
  glProgramUniformMatrix4fv(program_.get(), glGetUniformLocation(program_.get(), "u_view_projection"),
                            1, GL_FALSE, view_projection.data());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glBindVertexArray(vao);
  glLineWidth(1.0f);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines));
  glPointSize(5.0f);
  glDrawArrays(GL_POINTS, static_cast<GLint>(lines), static_cast<GLsizei>(heads));
  glDepthMask(GL_FALSE);
}

}  // namespace strielad::render
