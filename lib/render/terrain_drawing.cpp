// SPDX-License-Identifier: Apache-2.0
#include "render/terrain_drawing.h"

#include <string>
#include <vector>

#include "render/shader_program.h"
#include "render/wgs84_glsl.h"

namespace strielad::render {
namespace {

std::string vertex_source() {
  return std::string(R"(#version 450 core
layout(location = 0) in vec3 a_position;  // x, y km; height km
layout(location = 1) in vec2 a_gradient;  // dh/dx, dh/dy
layout(location = 2) in vec2 a_uv;
layout(location = 3) in float a_water;  // 1: no value or below sea level (at 0 m)
layout(location = 4) in vec2 a_clip;    // clip coordinates (view/terrain_tiles.h)
uniform mat4 u_view_projection;
uniform float u_vertical_exaggeration;
uniform bool u_globe;             // positions ECEF km, placed at u_gradient_scale
uniform float u_gradient_scale;   // the exaggeration the globe's tiles were placed at
uniform float u_globe_ratio;      // the exaggeration drawn over u_gradient_scale
out vec3 v_world;
out vec3 v_normal;
out float v_height_m;
out vec2 v_uv;
out float v_water;
out vec2 v_clip;
)") + kWgs84Glsl + R"(
void main() {
  if (u_globe) {
    // The local east/north/up frame (up along the radius: within 0.2 degrees of the
    // ellipsoid normal), the height above the WGS84 ellipsoid along the radius.
    vec3 unused = vec3(0.0);
    v_world = globe_redrawn(a_position, unused, u_globe_ratio);
    vec3 up = normalize(a_position);
    vec3 east = cross(vec3(0.0, 0.0, 1.0), up);
    east = length(east) > 1e-6 ? normalize(east) : vec3(1.0, 0.0, 0.0);
    vec3 north = cross(up, east);
    vec2 g = a_gradient * (u_gradient_scale * u_globe_ratio);
    v_normal = normalize(up - g.x * east - g.y * north);
    float r = inversesqrt(dot(up.xy, up.xy) / (WGS84_A * WGS84_A) + up.z * up.z / (WGS84_B * WGS84_B));
    v_height_m = (length(a_position) - r) / u_gradient_scale * 1000.0;
  } else {
    v_world = vec3(a_position.xy, a_position.z * u_vertical_exaggeration);
    v_normal = normalize(vec3(-a_gradient * u_vertical_exaggeration, 1.0));
    v_height_m = a_position.z * 1000.0;
  }
  v_uv = a_uv;
  v_water = a_water;
  v_clip = a_clip;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
)";
}

constexpr const char* kFragment = R"(#version 450 core
in vec3 v_world;
in vec3 v_normal;
in float v_height_m;
in vec2 v_uv;
in float v_water;
in vec2 v_clip;
uniform vec3 u_sun;
uniform vec4 u_clip;  // clip coordinates: x lo, y lo, x hi, y hi
uniform bool u_has_drape;
layout(binding = 0) uniform sampler2D u_drape;
out vec4 o_color;
// Hypsometric tints: lowland green, hills yellow-brown, mountains brown, rock grey, snow.
vec3 hypsometric(float h) {
  const float stops[6] = float[](0.0, 300.0, 800.0, 1500.0, 2500.0, 3500.0);
  const vec3 colors[6] = vec3[](vec3(0.31, 0.52, 0.30), vec3(0.55, 0.65, 0.38),
                                vec3(0.74, 0.68, 0.47), vec3(0.60, 0.48, 0.36),
                                vec3(0.62, 0.60, 0.58), vec3(0.95, 0.95, 0.97));
  if (h <= stops[0]) return colors[0];
  for (int i = 1; i < 6; ++i) {
    if (h < stops[i]) return mix(colors[i - 1], colors[i], (h - stops[i - 1]) / (stops[i] - stops[i - 1]));
  }
  return colors[5];
}
void main() {
  // Written so that NaN clip coordinates (no place in the store's axes) are cut too.
  if (!(v_clip.x >= u_clip.x && v_clip.y >= u_clip.y && v_clip.x <= u_clip.z &&
        v_clip.y <= u_clip.w)) {
    discard;
  }
  vec3 base;
  if (u_has_drape && all(greaterThanEqual(v_uv, vec2(0.0))) && all(lessThanEqual(v_uv, vec2(1.0)))) {
    base = texture(u_drape, v_uv).rgb;
  } else if (v_water > 0.5) {  // the coastline halfway between a land and a water sample
    base = vec3(0.22, 0.36, 0.55);
  } else {
    base = hypsometric(v_height_m);
  }
  vec3 n = normalize(v_normal);
  float lambert = max(dot(n, normalize(u_sun)), 0.0);
  o_color = vec4(base * (0.3 + 0.7 * lambert), 1.0);
}
)";

}  // namespace

TerrainDrawing::TerrainDrawing() {
  program_ = compile_builtin_program(vertex_source(), kFragment, "terrain");
}

TerrainDrawStats TerrainDrawing::draw(const view::TerrainFrame& frame,
                                      const lod::Mat4& view_projection,
                                      double vertical_exaggeration, const Vec3& sun,
                                      bool drape) {
  TerrainDrawStats stats;
  ++frame_;
  const GLuint p = program_.get();
  glUseProgram(p);
  glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_view_projection"), 1, GL_FALSE,
                            view_projection.data());
  glProgramUniform1f(p, glGetUniformLocation(p, "u_vertical_exaggeration"),
                     static_cast<float>(vertical_exaggeration));
  glProgramUniform1i(p, glGetUniformLocation(p, "u_globe"), frame.globe ? 1 : 0);
  glProgramUniform1f(p, glGetUniformLocation(p, "u_gradient_scale"),
                     static_cast<float>(frame.gradient_scale));
  glProgramUniform1f(p, glGetUniformLocation(p, "u_globe_ratio"),
                     static_cast<float>(frame.globe ? frame.globe_ratio : 1.0));
  const Vec3 s = normalize(sun);
  glProgramUniform3f(p, glGetUniformLocation(p, "u_sun"), float(s[0]), float(s[1]), float(s[2]));
  glProgramUniform4f(p, glGetUniformLocation(p, "u_clip"), float(frame.clip.lo[0]),
                     float(frame.clip.lo[1]), float(frame.clip.hi[0]), float(frame.clip.hi[1]));
  const GLint has_drape = glGetUniformLocation(p, "u_has_drape");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  constexpr GLsizei kStride = view::kTerrainVertexFloats * sizeof(float);
  for (const auto& mesh : frame.tiles) {
    auto [it, inserted] = tiles_.try_emplace(mesh->serial);
    GpuTile& tile = it->second;
    if (inserted) {
      tile.vertex_array = make_vertex_array();
      tile.vertices = make_buffer();
      glNamedBufferStorage(tile.vertices.get(), GLsizeiptr(mesh->vertices.size() * sizeof(float)),
                           mesh->vertices.data(), 0);
      tile.indices = make_buffer();
      glNamedBufferStorage(tile.indices.get(),
                           GLsizeiptr(mesh->indices.size() * sizeof(std::uint32_t)),
                           mesh->indices.data(), 0);
      const GLuint vao = tile.vertex_array.get();
      glVertexArrayVertexBuffer(vao, 0, tile.vertices.get(), 0, kStride);
      glVertexArrayElementBuffer(vao, tile.indices.get());
      const std::pair<int, int> attributes[5] = {{3, 0}, {2, 3}, {2, 5}, {1, 7}, {2, 8}};
      for (GLuint a = 0; a < 5; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, attributes[a].first, GL_FLOAT, GL_FALSE,
                                  GLuint(attributes[a].second * sizeof(float)));
        glVertexArrayAttribBinding(vao, a, 0);
      }
      tile.index_count = static_cast<GLsizei>(mesh->indices.size());
      if (mesh->drape.width > 0 && mesh->drape.height > 0) {
        tile.drape = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(tile.drape.get(), 1, GL_RGBA8, mesh->drape.width, mesh->drape.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(tile.drape.get(), 0, 0, 0, mesh->drape.width, mesh->drape.height,
                            GL_RGBA, GL_UNSIGNED_BYTE, mesh->drape.rgba.data());
        glTextureParameteri(tile.drape.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(tile.drape.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(tile.drape.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(tile.drape.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      }
    }
    tile.last_frame = frame_;
    const bool draped = drape && tile.drape;
    glProgramUniform1i(p, has_drape, draped ? 1 : 0);
    if (draped) glBindTextureUnit(0, tile.drape.get());
    glBindVertexArray(tile.vertex_array.get());
    glDrawElements(GL_TRIANGLES, tile.index_count, GL_UNSIGNED_INT, nullptr);
    ++stats.tiles;
    stats.triangles += mesh->triangles();
  }
  glDepthMask(GL_FALSE);
  // Tiles not drawn for a few hundred frames leave the GPU (the CPU cache keeps them).
  if (tiles_.size() > 2 * frame.tiles.size() + 256) {
    std::erase_if(tiles_, [&](const auto& t) { return t.second.last_frame + 300 < frame_; });
    if (tiles_.size() > 4 * frame.tiles.size() + 1024) {
      std::erase_if(tiles_, [&](const auto& t) { return t.second.last_frame != frame_; });
    }
  }
  return stats;
}

}  // namespace strielad::render
