// SPDX-License-Identifier: Apache-2.0
#include "render/slice_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "render/shader_program.h"
#include "render/wgs84_glsl.h"
#include "view/node_geometry.h"

namespace strielad::render {
namespace {

// Control points at t = 0, 1/8, ..., 1 (9) or 0, 1/4, ..., 1 (5), from the published
// tables: matplotlib's viridis and magma (entries 0, 32, ..., 224, 255), Moreland's
// smooth cool-warm, Google's turbo; greys runs from black to white.
struct Map {
  std::string_view name;
  std::vector<std::array<float, 3>> points;
};

const std::vector<Map>& maps() {
  static const std::vector<Map> m{
      {"viridis",
       {{0.267004f, 0.004874f, 0.329415f}, {0.282327f, 0.140926f, 0.457517f},
        {0.253935f, 0.265254f, 0.529983f}, {0.206756f, 0.371758f, 0.553117f},
        {0.163625f, 0.471133f, 0.558148f}, {0.127568f, 0.566949f, 0.550556f},
        {0.134692f, 0.658636f, 0.517649f}, {0.266941f, 0.748751f, 0.440573f},
        {0.993248f, 0.906157f, 0.143936f}}},
      {"magma",
       {{0.001462f, 0.000466f, 0.013866f}, {0.078815f, 0.054184f, 0.211667f},
        {0.232077f, 0.059889f, 0.437695f}, {0.390384f, 0.100379f, 0.501864f},
        {0.550287f, 0.161158f, 0.505719f}, {0.716387f, 0.214982f, 0.475290f},
        {0.868793f, 0.287728f, 0.409303f}, {0.967671f, 0.439703f, 0.359810f},
        {0.987053f, 0.991438f, 0.749504f}}},
      {"coolwarm",
       {{0.2298f, 0.2987f, 0.7537f}, {0.5543f, 0.6900f, 0.9955f}, {0.8654f, 0.8654f, 0.8654f},
        {0.9567f, 0.5980f, 0.4773f}, {0.7057f, 0.0156f, 0.1502f}}},
      {"greys", {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}},
      {"turbo",
       {{0.18995f, 0.07176f, 0.23217f}, {0.27469f, 0.40702f, 0.85928f},
        {0.15327f, 0.68017f, 0.97813f}, {0.11001f, 0.89816f, 0.71042f},
        {0.64362f, 0.98999f, 0.23356f}, {0.91473f, 0.82479f, 0.22478f},
        {0.99420f, 0.54481f, 0.15326f}, {0.86006f, 0.24727f, 0.04030f},
        {0.47960f, 0.01583f, 0.01055f}}},
  };
  return m;
}

const Map& map_named(std::string_view name) {
  for (const Map& m : maps()) {
    if (m.name == name) return m;
  }
  return maps().front();
}

int map_index(std::string_view name) {
  for (std::size_t i = 0; i < maps().size(); ++i) {
    if (maps()[i].name == name) return static_cast<int>(i);
  }
  return 0;
}

constexpr int kTextureWidth = 256;

std::string vertex_source() {
  return std::string(R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_value;
layout(location = 3) in float a_slot;
uniform mat4 u_view_projection;
uniform float u_vertical_exaggeration;
uniform float u_globe_ratio;  // != 1 only on the globe (globe_redrawn)
out vec3 v_normal;
out float v_value;
flat out int v_slot;
)") + kWgs84Glsl + R"(
void main() {
  vec3 normal = a_normal;
  vec3 p = vec3(a_position.xy, a_position.z * u_vertical_exaggeration);
  p = globe_redrawn(p, normal, u_globe_ratio);
  gl_Position = u_view_projection * vec4(p, 1.0);
  // Normals as covectors: the inverse transpose of the z scale.
  v_normal = vec3(normal.xy, normal.z / u_vertical_exaggeration);
  v_value = a_value;
  v_slot = int(a_slot + 0.5);
}
)";
}

const char* const kFragmentSource = R"(#version 450 core
in vec3 v_normal;
in float v_value;
flat in int v_slot;
uniform sampler2D u_colormaps;  // one row per colour map
uniform float u_map_rows;
uniform vec2 u_range[16];
uniform int u_map[16];
uniform vec3 u_sun;
out vec4 o_color;
void main() {
  int slot = clamp(v_slot, 0, 15);
  vec3 color;
  if (isnan(v_value) || isinf(v_value)) {
    color = vec3(0.5);
  } else {
    vec2 r = u_range[slot];
    float t = clamp((v_value - r.x) / (r.y - r.x), 0.0, 1.0);
    float u = (t * 255.0 + 0.5) / 256.0;
    color = texture(u_colormaps, vec2(u, (float(u_map[slot]) + 0.5) / u_map_rows)).rgb;
  }
  // Two-sided, lit lightly: the colour map stays readable from every side.
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float light = 0.8 + 0.2 * abs(dot(n, u_sun));
  o_color = vec4(color * light, 1.0);
}
)";

}  // namespace

std::array<float, 3> colormap_color(std::string_view name, double t) {
  if (std::isnan(t)) return kMissingSliceColor;
  const auto& points = map_named(name).points;
  const double x = std::clamp(t, 0.0, 1.0) * static_cast<double>(points.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), points.size() - 2);
  const double f = x - static_cast<double>(i);
  std::array<float, 3> c{};
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<float>(points[i][k] + f * (points[i + 1][k] - points[i][k]));
  }
  return c;
}

SliceDrawing::SliceDrawing() {
  program_ = compile_builtin_program(vertex_source(), kFragmentSource, "slice");
  const auto rows = static_cast<GLsizei>(maps().size());
  std::vector<std::uint8_t> texels;
  texels.reserve(static_cast<std::size_t>(kTextureWidth * rows * 4));
  for (const Map& m : maps()) {
    for (int i = 0; i < kTextureWidth; ++i) {
      const auto c = colormap_color(m.name, i / double(kTextureWidth - 1));
      for (float v : c) texels.push_back(static_cast<std::uint8_t>(std::lround(v * 255.0f)));
      texels.push_back(255);
    }
  }
  colormaps_ = make_texture(GL_TEXTURE_2D);
  const GLuint id = colormaps_.get();
  glTextureStorage2D(id, 1, GL_RGBA8, kTextureWidth, rows);
  glTextureSubImage2D(id, 0, 0, 0, kTextureWidth, rows, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void SliceDrawing::draw(const GpuMeshes& meshes, const lod::Mat4& view_projection,
                        double vertical_exaggeration, double globe_ratio,
                        const std::vector<SliceStyle>& styles, const Vec3& sun) {
  bool any = false;
  for (const auto& [node, mesh] : meshes.meshes()) any = any || mesh.slice_index_count > 0;
  if (!any) return;
  const GLuint p = program_.get();
  glUseProgram(p);
  glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_view_projection"), 1, GL_FALSE,
                            view_projection.data());
  glProgramUniform1f(p, glGetUniformLocation(p, "u_vertical_exaggeration"),
                     static_cast<float>(vertical_exaggeration));
  glProgramUniform1f(p, glGetUniformLocation(p, "u_globe_ratio"), static_cast<float>(globe_ratio));
  std::array<float, 2 * view::kMaxViewSlices> ranges{};
  std::array<GLint, view::kMaxViewSlices> map{};
  for (std::size_t s = 0; s < view::kMaxViewSlices; ++s) {
    const bool styled = s < styles.size() && styles[s].lo < styles[s].hi;
    ranges[2 * s] = styled ? styles[s].lo : 0.0f;
    ranges[2 * s + 1] = styled ? styles[s].hi : 1.0f;
    map[s] = s < styles.size() ? map_index(styles[s].colormap) : 0;
  }
  glProgramUniform2fv(p, glGetUniformLocation(p, "u_range"), view::kMaxViewSlices, ranges.data());
  glProgramUniform1iv(p, glGetUniformLocation(p, "u_map"), view::kMaxViewSlices, map.data());
  glProgramUniform1f(p, glGetUniformLocation(p, "u_map_rows"), static_cast<float>(maps().size()));
  const double length = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
  const std::array<float, 3> s = length > 0 ? std::array<float, 3>{float(sun[0] / length),
                                                                   float(sun[1] / length),
                                                                   float(sun[2] / length)}
                                            : std::array<float, 3>{0, 0, 1};
  glProgramUniform3f(p, glGetUniformLocation(p, "u_sun"), s[0], s[1], s[2]);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_colormaps"), static_cast<GLint>(kTextureUnit));
  glBindTextureUnit(kTextureUnit, colormaps_.get());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (const auto& [node, mesh] : meshes.meshes()) {
    if (mesh.slice_index_count == 0) continue;
    glBindVertexArray(mesh.slice_vertex_array.get());
    glDrawElements(GL_TRIANGLES, mesh.slice_index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glDepthMask(GL_FALSE);
}

std::vector<SliceStyle> slice_styles(const Scene& scene,
                                     const std::vector<std::optional<view::SliceRange>>& shown) {
  std::vector<SliceStyle> styles;
  for (std::size_t i = 0; i < scene.slices.size(); ++i) {
    const Slice& slice = scene.slices[i];
    SliceStyle style;
    style.colormap = slice.colormap;
    if (slice.range) {
      style.lo = static_cast<float>(slice.range->lo);
      style.hi = static_cast<float>(slice.range->hi);
    } else if (i < shown.size() && shown[i]) {
      style.lo = (*shown[i])[0];
      style.hi = (*shown[i])[1];
    }
    if (!(style.lo < style.hi)) {
      const float pad = std::max(1e-6f, std::abs(style.lo) * 1e-6f);
      style.hi = style.lo + pad;
      style.lo -= pad;
    }
    styles.push_back(style);
  }
  return styles;
}

}  // namespace strielad::render
