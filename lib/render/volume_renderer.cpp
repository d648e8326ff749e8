// SPDX-License-Identifier: Apache-2.0
#include "render/volume_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/error.h"
#include "render/colored_vertices.h"
#include "render/volume_shaders.h"
#include "view/subvolume_palette.h"

namespace strielad::render {
namespace {

constexpr std::uint32_t kEndOfList = 0xFFFFFFFFu;
constexpr std::size_t kInitialFragmentsPerPixel = 4;

GLint location(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

void set_mat4(GLuint program, const char* name, const lod::Mat4& m) {
  glProgramUniformMatrix4fv(program, location(program, name), 1, GL_FALSE, m.data());
}
void set_vec3(GLuint program, const char* name, const Vec3& v) {
  glProgramUniform3f(program, location(program, name), static_cast<float>(v[0]),
                     static_cast<float>(v[1]), static_cast<float>(v[2]));
}
void set_float(GLuint program, const char* name, double v) {
  glProgramUniform1f(program, location(program, name), static_cast<float>(v));
}

// The exaggeration the meshes' and slices' vertex arrays carry on the globe (0 given:
// the one drawn).
double globe_placed_exaggeration(const FrameInputs& inputs) {
  return inputs.globe_placed_exaggeration > 0 ? inputs.globe_placed_exaggeration
                                              : inputs.globe_exaggeration;
}
// Heights drawn over heights placed on the globe; 1 on the plane.
double globe_ratio(const FrameInputs& inputs) {
  return inputs.globe_exaggeration > 0 ? inputs.globe_exaggeration / globe_placed_exaggeration(inputs)
                                       : 1.0;
}

// Inverse of a general 4x4 matrix (column-major), by cofactors in double.
lod::Mat4 inverse(const lod::Mat4& m) {
  std::array<double, 16> a{}, inv{};
  for (int i = 0; i < 16; ++i) a[i] = m[i];
  inv[0] = a[5] * a[10] * a[15] - a[5] * a[11] * a[14] - a[9] * a[6] * a[15] +
           a[9] * a[7] * a[14] + a[13] * a[6] * a[11] - a[13] * a[7] * a[10];
  inv[4] = -a[4] * a[10] * a[15] + a[4] * a[11] * a[14] + a[8] * a[6] * a[15] -
           a[8] * a[7] * a[14] - a[12] * a[6] * a[11] + a[12] * a[7] * a[10];
  inv[8] = a[4] * a[9] * a[15] - a[4] * a[11] * a[13] - a[8] * a[5] * a[15] +
           a[8] * a[7] * a[13] + a[12] * a[5] * a[11] - a[12] * a[7] * a[9];
  inv[12] = -a[4] * a[9] * a[14] + a[4] * a[10] * a[13] + a[8] * a[5] * a[14] -
            a[8] * a[6] * a[13] - a[12] * a[5] * a[10] + a[12] * a[6] * a[9];
  inv[1] = -a[1] * a[10] * a[15] + a[1] * a[11] * a[14] + a[9] * a[2] * a[15] -
           a[9] * a[3] * a[14] - a[13] * a[2] * a[11] + a[13] * a[3] * a[10];
  inv[5] = a[0] * a[10] * a[15] - a[0] * a[11] * a[14] - a[8] * a[2] * a[15] +
           a[8] * a[3] * a[14] + a[12] * a[2] * a[11] - a[12] * a[3] * a[10];
  inv[9] = -a[0] * a[9] * a[15] + a[0] * a[11] * a[13] + a[8] * a[1] * a[15] -
           a[8] * a[3] * a[13] - a[12] * a[1] * a[11] + a[12] * a[3] * a[9];
  inv[13] = a[0] * a[9] * a[14] - a[0] * a[10] * a[13] - a[8] * a[1] * a[14] +
            a[8] * a[2] * a[13] + a[12] * a[1] * a[10] - a[12] * a[2] * a[9];
  inv[2] = a[1] * a[6] * a[15] - a[1] * a[7] * a[14] - a[5] * a[2] * a[15] +
           a[5] * a[3] * a[14] + a[13] * a[2] * a[7] - a[13] * a[3] * a[6];
  inv[6] = -a[0] * a[6] * a[15] + a[0] * a[7] * a[14] + a[4] * a[2] * a[15] -
           a[4] * a[3] * a[14] - a[12] * a[2] * a[7] + a[12] * a[3] * a[6];
  inv[10] = a[0] * a[5] * a[15] - a[0] * a[7] * a[13] - a[4] * a[1] * a[15] +
            a[4] * a[3] * a[13] + a[12] * a[1] * a[7] - a[12] * a[3] * a[5];
  inv[14] = -a[0] * a[5] * a[14] + a[0] * a[6] * a[13] + a[4] * a[1] * a[14] -
            a[4] * a[2] * a[13] - a[12] * a[1] * a[6] + a[12] * a[2] * a[5];
  inv[3] = -a[1] * a[6] * a[11] + a[1] * a[7] * a[10] + a[5] * a[2] * a[11] -
           a[5] * a[3] * a[10] - a[9] * a[2] * a[7] + a[9] * a[3] * a[6];
  inv[7] = a[0] * a[6] * a[11] - a[0] * a[7] * a[10] - a[4] * a[2] * a[11] +
           a[4] * a[3] * a[10] + a[8] * a[2] * a[7] - a[8] * a[3] * a[6];
  inv[11] = -a[0] * a[5] * a[11] + a[0] * a[7] * a[9] + a[4] * a[1] * a[11] -
            a[4] * a[3] * a[9] - a[8] * a[1] * a[7] + a[8] * a[3] * a[5];
  inv[15] = a[0] * a[5] * a[10] - a[0] * a[6] * a[9] - a[4] * a[1] * a[10] +
            a[4] * a[2] * a[9] + a[8] * a[1] * a[6] - a[8] * a[2] * a[5];
  const double det = a[0] * inv[0] + a[1] * inv[4] + a[2] * inv[8] + a[3] * inv[12];
  lod::Mat4 out{};
  for (int i = 0; i < 16; ++i) out[i] = static_cast<float>(inv[i] / det);
  return out;
}

// The near edge of depth bin `bin` (log-spaced from near to far, as depth_bin() in the
// geometry shader); kDepthBins gives the far plane.
double depth_bin_edge(const lod::Camera& camera, int bin) {
  return camera.near_km * std::pow(camera.far_km / camera.near_km, double(bin) / kDepthBins);
}

double elapsed_ms(const GlQuery& query) {
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query.get(), GL_QUERY_RESULT, &ns);
  return static_cast<double>(ns) * 1e-6;
}

}  // namespace

VolumeRenderer::VolumeRenderer(RenderSettings settings) : settings_(settings) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major < 4 || (major == 4 && minor < 5)) {
    throw make_error(ErrorCode::kUnsupported,
                     "the A-buffer renderer needs OpenGL 4.5 (SSBOs, image atomics, direct "
                     "state access); this context is {}.{}",
                     major, minor);
  }
  background_program_ =
      compile_builtin_program(resolve_vertex_source(), background_fragment_source(), "background");
  line_program_ = compile_builtin_program(line_vertex_source(), line_fragment_source(), "outline");
  sort_program_ = compile_builtin_program(resolve_vertex_source(), sort_fragment_source(), "sort");
  empty_vertex_array_ = make_vertex_array();
  line_vertex_array_ = make_vertex_array();
  line_buffer_ = make_buffer();
  counter_ = make_buffer();
  glNamedBufferStorage(counter_.get(), sizeof(GLuint), nullptr,
                       GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  resolve_stats_ = make_buffer();
  glNamedBufferStorage(resolve_stats_.get(), 4 * sizeof(GLuint), nullptr,
                       GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  histogram_ = make_buffer();
  glNamedBufferStorage(histogram_.get(), kDepthBins * sizeof(GLuint), nullptr,
                       GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  for (auto& t : timers_) t = make_query(GL_TIME_ELAPSED);
  const auto update = compile_user_programs(default_user_shader(), user_name_);
  if (!update.ok) {
    throw make_error(ErrorCode::kInternal, "the built-in user shader: {}", update.error);
  }
  user_source_ = default_user_shader();
}

ShaderUpdate VolumeRenderer::compile_user_programs(const std::string& source,
                                                   const std::string& name) {
  const std::string prelude = user_prelude(attribute_names_);
  ShaderUpdate update;
  auto geometry = compile_program(
      {{GL_VERTEX_SHADER, geometry_vertex_source(), std::nullopt},
       {GL_FRAGMENT_SHADER, geometry_fragment_source(prelude), source}},
      name);
  auto resolve = geometry.ok()
                     ? compile_program({{GL_VERTEX_SHADER, resolve_vertex_source(), std::nullopt},
                                        {GL_FRAGMENT_SHADER, resolve_fragment_source(prelude),
                                         source}},
                                       name)
                     : CompileResult{};
  const CompileResult& failed = !geometry.ok() ? geometry : resolve;
  if (!geometry.ok() || !resolve.ok()) {
    update.diagnostics = failed.diagnostics;
    update.error = failed.first_error();
    if (update.error.empty()) update.error = name + ": the shader does not compile";
    for (const auto& d : failed.diagnostics) {
      if (d.user_line > 0) {
        update.error_line = d.user_line;
        break;
      }
    }
    return update;
  }
  geometry_program_ = std::move(geometry.program);
  resolve_program_ = std::move(resolve.program);
  update.ok = true;
  update.diagnostics = geometry.diagnostics;
  return update;
}

ShaderUpdate VolumeRenderer::set_user_shader(const std::string& source, const std::string& name) {
  auto update = compile_user_programs(source, name);
  if (update.ok) {
    user_source_ = source;
    user_name_ = name;
  }
  return update;
}

ShaderUpdate VolumeRenderer::set_scene_layout(const std::vector<std::uint32_t>& slot_ids,
                                              const std::vector<std::string>& attribute_names) {
  slot_ids_ = slot_ids;
  if (slot_ids_.size() > 32) slot_ids_.resize(32);
  if (attribute_names == attribute_names_) {
    ShaderUpdate unchanged;
    unchanged.ok = true;
    return unchanged;
  }
  const auto previous = attribute_names_;
  attribute_names_ = attribute_names;
  auto update = compile_user_programs(user_source_, user_name_);
  if (!update.ok) {
    // The user's shader relies on the old names (ATTR_x): fall back to the default.
    auto fallback = compile_user_programs(default_user_shader(), "built-in clouds.glsl");
    if (fallback.ok) {
      user_source_ = default_user_shader();
      user_name_ = "built-in clouds.glsl";
    } else {
      attribute_names_ = previous;
    }
  }
  return update;
}

void VolumeRenderer::set_max_fragment_bytes(std::size_t bytes) {
  settings_.max_fragment_bytes = std::max<std::size_t>(bytes, kFragmentBytes * 1024);
  if (capacity_ * kFragmentBytes > settings_.max_fragment_bytes) {
    capacity_ = 0;  // re-made at the next frame within the new bound
  }
}

void VolumeRenderer::ensure_targets(int width, int height) {
  if (width == width_ && height == height_ && opaque_framebuffer_) return;
  width_ = width;
  height_ = height;
  opaque_color_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(opaque_color_.get(), 1, GL_RGBA8, width, height);
  opaque_depth_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(opaque_depth_.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  for (GLuint t : {opaque_color_.get(), opaque_depth_.get()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  opaque_framebuffer_ = make_framebuffer();
  glNamedFramebufferTexture(opaque_framebuffer_.get(), GL_COLOR_ATTACHMENT0, opaque_color_.get(), 0);
  glNamedFramebufferTexture(opaque_framebuffer_.get(), GL_DEPTH_ATTACHMENT, opaque_depth_.get(), 0);
  heads_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(heads_.get(), 1, GL_R32UI, width, height);
  listed_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(listed_.get(), 1, GL_R32UI, width, height);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (capacity_ < pixels * kInitialFragmentsPerPixel) ensure_pool(pixels * kInitialFragmentsPerPixel);
}

void VolumeRenderer::ensure_pool(std::size_t fragments) {
  const std::size_t limit = std::max<std::size_t>(settings_.max_fragment_bytes / kFragmentBytes, 1024);
  const std::size_t wanted = std::min(fragments, limit);
  if (wanted <= capacity_ && pool_) return;
  pool_ = make_buffer();
  glNamedBufferStorage(pool_.get(), static_cast<GLsizeiptr>(wanted * kFragmentBytes), nullptr, 0);
  capacity_ = wanted;
}

struct VolumeRenderer::FrameSetup {
  lod::Mat4 view_matrix{}, projection{}, view_projection{};
  // The sub-volume id of each slot; unused slots hold -1, an id no sub-volume has (ids
  // are 1..65535).
  std::array<GLint, 32> slot_ids{};
  std::array<float, 3 * view::kSubVolumePaletteSize> palette{};
  // The meshes nearest first, with their distance from the eye.
  std::vector<std::pair<double, const GpuMesh*>> order;
  // The displacement of each step that moves (a handful of steps at most).
  std::unordered_map<std::uint32_t, MotionBinding> motions;
};

namespace {

std::array<GLint, 32> slot_id_uniform(const std::vector<std::uint32_t>& slot_ids) {
  std::array<GLint, 32> ids;
  ids.fill(-1);
  for (std::size_t i = 0; i < slot_ids.size(); ++i) ids[i] = static_cast<GLint>(slot_ids[i]);
  return ids;
}

std::array<float, 3 * view::kSubVolumePaletteSize> subvolume_palette_uniform() {
  std::array<float, 3 * view::kSubVolumePaletteSize> palette{};
  for (std::size_t i = 0; i < view::kSubVolumePaletteSize; ++i) {
    const auto c = view::subvolume_palette_color(i);
    for (int k = 0; k < 3; ++k) palette[3 * i + k] = c[k];
  }
  return palette;
}

// The meshes ordered by the distance of their centres (at the frame's exaggeration) from
// the eye, nearest first.
std::vector<std::pair<double, const GpuMesh*>> meshes_nearest_first(const GpuMeshes& meshes,
                                                                    const FrameInputs& inputs) {
  std::vector<std::pair<double, const GpuMesh*>> order;
  order.reserve(meshes.meshes().size());
  for (const auto& [node, mesh] : meshes.meshes()) {
    const Vec3 c{mesh.center[0], mesh.center[1], mesh.center[2] * inputs.vertical_exaggeration};
    order.emplace_back(length(sub(c, inputs.camera.eye)), &mesh);
  }
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return order;
}

// The geometry program's motion uniforms and textures: `motion`'s displacement map, or
// none (null).
void bind_motion(GLuint g, const MotionBinding* motion) {
  glProgramUniform1i(g, location(g, "u_moving"), motion ? 1 : 0);
  if (!motion) return;
  const auto& map = *motion->map;
  set_float(g, "u_motion_weight", motion->weight);
  set_vec3(g, "u_motion_lo", map.box.lo);
  Vec3 size{};
  for (int a = 0; a < 3; ++a) size[a] = std::max(map.box.hi[a] - map.box.lo[a], 1e-9);
  set_vec3(g, "u_motion_size", size);
  set_vec3(g, "u_motion_lattice",
           Vec3{double(map.lattice[0]), double(map.lattice[1]), double(map.lattice[2])});
  glProgramUniform1i(g, location(g, "u_motion_periodic"), map.periodic ? 1 : 0);
  glBindTextureUnit(2, motion->from);
  glBindTextureUnit(3, motion->to);
}

}  // namespace

FrameStats VolumeRenderer::render(const FrameInputs& inputs, GLuint framebuffer, int width,
                                  int height) {
  FrameStats stats;
  if (width <= 0 || height <= 0) return stats;
  ensure_targets(width, height);
  if (!pool_ || capacity_ == 0) {
    ensure_pool(static_cast<std::size_t>(width) * height * kInitialFragmentsPerPixel);
  }
  FrameSetup frame;
  frame.view_matrix = lod::view_matrix(inputs.camera);
  frame.projection = lod::projection_matrix(inputs.camera);
  frame.view_projection = lod::multiply(frame.projection, frame.view_matrix);
  glViewport(0, 0, width, height);

  // 1. Opaque pass: the background, the terrain, the slices, the flight tracks.
  draw_opaque_pass(inputs, frame, height, stats);

  // 2. Geometry pass(es) into the per-pixel lists.
  frame.slot_ids = slot_id_uniform(slot_ids_);
  frame.palette = subvolume_palette_uniform();
  frame.order = meshes_nearest_first(meshes_, inputs);
  motion_textures_.sync(inputs.motions);
  for (const auto& m : inputs.motions) {
    if (m.map) frame.motions[m.map->step] = motion_textures_.binding(m.map->step);
  }
  const float depth_limit = fill_fragment_lists(inputs, frame, stats);

  // 3. Sort each pixel's list (no colour output), 4. resolve into the target.
  glBeginQuery(GL_TIME_ELAPSED, timers_[2].get());
  sort_fragment_lists();
  resolve_fragment_lists(inputs, frame, framebuffer, depth_limit);
  glEndQuery(GL_TIME_ELAPSED);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);

  if (!inputs.outline_boxes.empty()) draw_outlines(inputs, frame.view_projection);

  GLuint resolved[4] = {0, 0, 0, 0};
  glGetNamedBufferSubData(resolve_stats_.get(), 0, sizeof(resolved), resolved);
  stats.fragment_capacity = capacity_;
  stats.covered_pixels = resolved[0];
  stats.truncated_pixels = resolved[1];
  stats.max_fragments_per_pixel = resolved[2];
  stats.opaque_ms = elapsed_ms(timers_[0]);
  stats.geometry_ms = elapsed_ms(timers_[1]);
  stats.resolve_ms = elapsed_ms(timers_[2]);
  glBindVertexArray(0);
  glUseProgram(0);
  return stats;
}

void VolumeRenderer::draw_opaque_pass(const FrameInputs& inputs, const FrameSetup& frame,
                                      int height, FrameStats& stats) {
  glBeginQuery(GL_TIME_ELAPSED, timers_[0].get());
  glBindFramebuffer(GL_FRAMEBUFFER, opaque_framebuffer_.get());
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_FALSE);
  glUseProgram(background_program_.get());
  glProgramUniform3fv(background_program_.get(), location(background_program_.get(), "u_top"), 1,
                      settings_.background_top.data());
  glProgramUniform3fv(background_program_.get(), location(background_program_.get(), "u_bottom"), 1,
                      settings_.background_bottom.data());
  set_float(background_program_.get(), "u_height", height);
  glBindVertexArray(empty_vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (inputs.terrain) {
    const auto drawn = terrain_drawing_.draw(*inputs.terrain, frame.view_projection,
                                             inputs.vertical_exaggeration, inputs.sun_direction,
                                             inputs.terrain_drape);
    stats.terrain_tiles = drawn.tiles;
    stats.terrain_triangles = drawn.triangles;
  }
  if (!inputs.slice_styles.empty()) {
    slice_drawing_.draw(meshes_, frame.view_projection, inputs.vertical_exaggeration,
                        globe_ratio(inputs), inputs.slice_styles, inputs.sun_direction);
  }
  if (inputs.tracks) {
    track_drawing_.draw(*inputs.tracks, frame.view_projection, inputs.vertical_exaggeration,
                        inputs.track_color);
  }
  glEndQuery(GL_TIME_ELAPSED);
}

// Nearest node first; every fragment is also counted in a depth histogram. When the pool
// overflows, it grows (up to the bound) and the pass runs again; at the bound, the pass
// runs again with a depth limit below which everything fits, so the fragments dropped
// are exactly the farthest (to the histogram's resolution).
float VolumeRenderer::fill_fragment_lists(const FrameInputs& inputs, const FrameSetup& frame,
                                          FrameStats& stats) {
  glBeginQuery(GL_TIME_ELAPSED, timers_[1].get());
  float depth_limit = std::numeric_limits<float>::max();
  std::uint64_t generated = draw_geometry_pass(inputs, frame, depth_limit, stats);
  stats.fragments = generated;
  if (generated > capacity_) {
    ensure_pool(static_cast<std::size_t>(generated) + generated / 8);
    if (generated > capacity_) {
      // At the bound: the nearest depth bins that fit.
      std::array<GLuint, kDepthBins> bins{};
      glGetNamedBufferSubData(histogram_.get(), 0, sizeof(bins), bins.data());
      std::uint64_t kept = 0;
      int bin = 0;
      while (bin < kDepthBins && kept + bins[bin] <= capacity_) kept += bins[bin++];
      depth_limit = static_cast<float>(depth_bin_edge(inputs.camera, bin));
    }
    ++stats.geometry_passes;
    generated = draw_geometry_pass(inputs, frame, depth_limit, stats);
  }
  glEndQuery(GL_TIME_ELAPSED);
  stats.depth_limit_km = depth_limit;
  stats.dropped_fragments = stats.fragments - std::min<std::uint64_t>(generated, capacity_);
  return depth_limit;
}

std::uint64_t VolumeRenderer::draw_geometry_pass(const FrameInputs& inputs,
                                                 const FrameSetup& frame, float depth_limit,
                                                 FrameStats& stats) {
  const GLuint end_of_list = kEndOfList;
  glClearTexImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &end_of_list);
  const GLuint zero = 0;
  glNamedBufferSubData(counter_.get(), 0, sizeof(GLuint), &zero);
  glClearNamedBufferData(histogram_.get(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, opaque_framebuffer_.get());
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_LESS);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const GLuint g = geometry_program_.get();
  glUseProgram(g);
  set_mat4(g, "u_view_projection", frame.view_projection);
  set_mat4(g, "u_view", frame.view_matrix);
  set_float(g, "u_vertical_exaggeration", inputs.vertical_exaggeration);
  set_float(g, "u_globe_exaggeration", inputs.globe_exaggeration);
  set_float(g, "u_globe_placed_exaggeration", globe_placed_exaggeration(inputs));
  set_vec3(g, "u_eye", inputs.camera.eye);
  set_vec3(g, "u_sun", normalize(inputs.sun_direction));
  set_float(g, "u_time", inputs.time_seconds);
  set_float(g, "u_near", inputs.camera.near_km);
  set_float(g, "u_far", inputs.camera.far_km);
  set_float(g, "u_depth_limit", depth_limit);
  glProgramUniform1i(g, location(g, "u_mirrored"), inputs.mirrored ? 1 : 0);
  glProgramUniform1ui(g, location(g, "u_capacity"), static_cast<GLuint>(capacity_));
  glProgramUniform1iv(g, location(g, "u_slot_ids"), 32, frame.slot_ids.data());
  glProgramUniform3fv(g, location(g, "u_subvolume_colors"), 32, frame.palette.data());
  glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, counter_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, pool_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, histogram_.get());
  stats.nodes_drawn = 0;
  stats.nodes_moved = 0;
  stats.triangles_drawn = 0;
  const MotionBinding* bound = nullptr;
  for (const auto& [distance, mesh] : frame.order) {
    const MotionBinding* motion = nullptr;
    if (!inputs.motions.empty()) {
      const auto it = frame.motions.find(mesh->source->step);
      if (it != frame.motions.end() && it->second.map != nullptr) motion = &it->second;
    }
    if (motion != bound || (!motion && stats.nodes_drawn == 0)) {
      bind_motion(g, motion);
      bound = motion;
    }
    if (motion) ++stats.nodes_moved;
    glBindVertexArray(mesh->vertex_array.get());
    glDrawElements(GL_TRIANGLES, mesh->index_count, GL_UNSIGNED_INT, nullptr);
    ++stats.nodes_drawn;
    stats.triangles_drawn += static_cast<std::size_t>(mesh->index_count) / 3;
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint generated = 0;
  glGetNamedBufferSubData(counter_.get(), 0, sizeof(GLuint), &generated);
  return static_cast<std::uint64_t>(generated);
}

void VolumeRenderer::sort_fragment_lists() {
  const GLuint zeros[4] = {0, 0, 0, 0};
  glNamedBufferSubData(resolve_stats_.get(), 0, sizeof(zeros), zeros);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, opaque_framebuffer_.get());
  glDisable(GL_DEPTH_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glUseProgram(sort_program_.get());
  glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(1, listed_.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, pool_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, resolve_stats_.get());
  glBindVertexArray(empty_vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void VolumeRenderer::resolve_fragment_lists(const FrameInputs& inputs, const FrameSetup& frame,
                                            GLuint framebuffer, float depth_limit) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  const GLuint r = resolve_program_.get();
  glUseProgram(r);
  set_mat4(r, "u_inverse_projection", inverse(frame.projection));
  set_mat4(r, "u_inverse_view", inverse(frame.view_matrix));
  set_float(r, "u_near", inputs.camera.near_km);
  set_float(r, "u_far", inputs.camera.far_km);
  set_float(r, "u_vertical_exaggeration", inputs.vertical_exaggeration);
  set_float(r, "u_globe_exaggeration", inputs.globe_exaggeration);
  set_float(r, "u_seam_relative", settings_.seam_relative);
  set_float(r, "u_depth_limit", depth_limit);
  set_float(r, "u_time", inputs.time_seconds);
  glProgramUniform1iv(r, location(r, "u_slot_ids"), 32, frame.slot_ids.data());
  glProgramUniform3fv(r, location(r, "u_subvolume_colors"), 32, frame.palette.data());
  glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(1, listed_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindTextureUnit(0, opaque_color_.get());
  glBindTextureUnit(1, opaque_depth_.get());
  glBindVertexArray(empty_vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void VolumeRenderer::draw_outlines(const FrameInputs& inputs, const lod::Mat4& view_projection) {
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::vector<float> data;
  data.reserve(inputs.outline_boxes.size() * 24 * 7);
  for (std::size_t b = 0; b < inputs.outline_boxes.size(); ++b) {
    const auto& box = inputs.outline_boxes[b];
    const auto color = b < inputs.outline_colors.size() ? inputs.outline_colors[b]
                                                        : std::array<float, 4>{1, 1, 0, 0.6f};
    for (const auto& edge : kEdges) {
      for (const int corner : edge) {
        data.push_back(static_cast<float>((corner & 1) ? box.hi[0] : box.lo[0]));
        data.push_back(static_cast<float>((corner & 2) ? box.hi[1] : box.lo[1]));
        data.push_back(static_cast<float>((corner & 4) ? box.hi[2] : box.lo[2]));
        data.insert(data.end(), color.begin(), color.end());
      }
    }
  }
  const GLuint vao = line_vertex_array_.get();
  upload_colored_vertices(vao, line_buffer_, data);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(line_program_.get());
  set_mat4(line_program_.get(), "u_view_projection", view_projection);
  glBindVertexArray(vao);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(data.size() / 7));
  glDisable(GL_BLEND);
}

std::vector<std::uint8_t> VolumeRenderer::read_pixels(GLuint framebuffer, int width, int height) {
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  // GL's first row is the bottom one.
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(rows.begin() + y * stride, rows.begin() + (y + 1) * stride,
                     rows.begin() + (height - 1 - y) * stride);
  }
  return rows;
}

}  // namespace strielad::render
