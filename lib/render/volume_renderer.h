// SPDX-License-Identifier: Apache-2.0
// The pseudo-volumetric renderer of strielad-view (the paper's A-buffer):
// 1. opaque pass: the background, terrain and flight tracks into a colour and a depth
//    texture;
// 2. geometry pass: every node's closed meshes, nearest node first, depth-tested
//    against the opaque depth but not writing it; each fragment runs the user's
//    color() and is appended to its pixel's list (an r32ui head image, a fragment pool
//    SSBO and an atomic counter): eye depth, colour, sub-volume slot, and whether the
//    ray enters (front face) or leaves;
// 3. sort pass: per pixel the K = 32 nearest fragments are kept and the list relinked
//    in depth order;
// 4. resolve pass: one walk along each pixel's sorted list; entry
//    and exit are paired per sub-volume (a nesting count; a leave and an enter of the
//    same sub-volume at one node face, within a relative 1e-4 of the depth, join into
//    one segment); each segment gets the colour of its entry and the opacity
//    alpha(id, true km travelled inside) times the colour's opacity scale; segments are
//    composited front to back by where they start, over the opaque pass.
// Fragment memory is bounded: the pool starts at 4 fragments per pixel; a frame that
// needs more grows it, up to max_fragment_bytes, and runs the geometry pass again. At
// the bound, the pass runs again with a depth limit taken from a 256-bin histogram of
// the fragments' depths (log-spaced from near to far), so that exactly the farthest
// bins are dropped and sub-volumes open at the limit end there. Pixels with more than
// K fragments keep the K nearest, and sub-volumes still open behind them end at the K-th.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lod/camera.h"
#include "lod/geometry.h"
#include "render/gl_handles.h"
#include "render/gpu_meshes.h"
#include "render/mesh_motion.h"
#include "render/slice_drawing.h"
#include "render/terrain_drawing.h"
#include "render/track_drawing.h"
#include "render/shader_program.h"

namespace strielad::render {

inline constexpr std::size_t kDefaultMaxFragmentBytes = 256ull << 20;  // 16 M fragments
inline constexpr std::size_t kFragmentBytes = 16;
inline constexpr int kDepthBins = 256;

struct RenderSettings {
  std::size_t max_fragment_bytes = kDefaultMaxFragmentBytes;
  std::array<float, 3> background_top{0.16f, 0.22f, 0.34f};
  std::array<float, 3> background_bottom{0.55f, 0.62f, 0.70f};
  float seam_relative = 1e-4f;
};

struct FrameInputs {
  lod::Camera camera;                  // world frame at the current exaggeration
  double vertical_exaggeration = 10.0;
  // > 0 on the globe (lod::WorldFrame::globe()): the exaggeration heights are drawn at,
  // which the shaders' height_m() and the distances alpha() takes remove
  // (vertical_exaggeration is then 1); 0 on the plane.
  double globe_exaggeration = 0;
  // On the globe: the exaggeration the meshes' and slices' vertex arrays were placed at
  // (view::GeometryPlacer::placed_exaggeration()); the vertex shaders move them to
  // globe_exaggeration (render/wgs84_glsl.h globe_redrawn). 0: globe_exaggeration.
  double globe_placed_exaggeration = 0;
  Vec3 sun_direction{0.3, -0.5, 0.8};  // towards the sun, world frame
  double time_seconds = 0;             // passed to color()
  bool mirrored = false;               // view::GeometryPlacer::mirrored()
  // Node boxes to outline (world frame), with an RGBA colour each; empty: none.
  std::vector<lod::WorldBox> outline_boxes;
  std::vector<std::array<float, 4>> outline_colors;
  // Meshes of a motion's step move with its displacement map (wind advection); meshes
  // of other steps are drawn where they are.
  std::vector<MeshMotion> motions;
  // Flight tracks (view/track_window.h): opaque lines and points, drawn in the opaque
  // pass so that sub-volumes in front of them cover them and those behind do not.
  std::shared_ptr<const view::TrackLines> tracks;
  std::array<float, 4> track_color{1.0f, 0.55f, 0.1f, 1.0f};
  // Terrain tiles (view/terrain_tiles.h) to draw in the opaque pass; null: none.
  std::shared_ptr<const view::TerrainFrame> terrain;
  bool terrain_drape = true;  // false: the tiles' drape images are not drawn
  // The scene's slices (drawn from meshes(), opaque): colour map and range per slice slot
  // (render/slice_drawing.h, slice_styles); empty: no slices drawn.
  std::vector<SliceStyle> slice_styles;
};

struct FrameStats {
  std::uint64_t fragments = 0;          // fragments generated (the atomic counter)
  std::uint64_t fragment_capacity = 0;  // of the pool this frame
  std::uint64_t dropped_fragments = 0;  // beyond the pool
  std::uint64_t covered_pixels = 0;     // with at least one fragment
  std::uint64_t truncated_pixels = 0;   // with more than K fragments
  std::uint32_t max_fragments_per_pixel = 0;
  std::size_t nodes_drawn = 0;
  std::size_t nodes_moved = 0;  // drawn with a displacement map
  std::size_t triangles_drawn = 0;
  std::size_t terrain_tiles = 0;      // terrain tiles drawn
  std::size_t terrain_triangles = 0;  // their triangles, skirts included
  double opaque_ms = 0, geometry_ms = 0, resolve_ms = 0;  // GPU time (timer queries)
  int geometry_passes = 1;    // 2 when the pool overflowed (grown, or a depth limit set)
  float depth_limit_km = 0;   // fragments beyond this eye depth were dropped (max: none)
  double fragments_per_covered_pixel() const {
    return covered_pixels ? static_cast<double>(fragments - dropped_fragments) / covered_pixels : 0;
  }
};

struct ShaderUpdate {
  bool ok = false;
  std::string error;  // the first error, "FILE:LINE:COL: error: ..." (empty when ok)
  int error_line = 0; // line of the user's code, 0 when unknown
  std::vector<ShaderDiagnostic> diagnostics;
};

class VolumeRenderer {
 public:
  // Needs a current OpenGL 4.3+ context. Compiles the built-in programs with the
  // default user shader. \error kUnsupported when the context lacks what the A-buffer
  // needs; kInternal when a built-in program does not compile (a bug).
  explicit VolumeRenderer(RenderSettings settings = {});

  // Compiles `source` (the user's color() and alpha()) into both programs that use it.
  // On failure nothing changes: the last good shader keeps running.
  ShaderUpdate set_user_shader(const std::string& source, const std::string& name);
  const std::string& user_shader_source() const { return user_source_; }
  const std::string& user_shader_name() const { return user_name_; }

  // The scene's sub-volume ids by slot and its attribute names (ATTR_<name> defines);
  // recompiles the current user shader when the names change.
  ShaderUpdate set_scene_layout(const std::vector<std::uint32_t>& slot_ids,
                                const std::vector<std::string>& attribute_names);

  GpuMeshes& meshes() { return meshes_; }

  // Renders into `framebuffer` (0 = the default one) of `width` x `height` pixels.
  FrameStats render(const FrameInputs& inputs, GLuint framebuffer, int width, int height);

  // RGBA8 rows, top row first, of the framebuffer last rendered into.
  static std::vector<std::uint8_t> read_pixels(GLuint framebuffer, int width, int height);

  std::size_t fragment_capacity() const { return capacity_; }
  const RenderSettings& settings() const { return settings_; }
  void set_max_fragment_bytes(std::size_t bytes);

 private:
  ShaderUpdate compile_user_programs(const std::string& source, const std::string& name);
  void ensure_targets(int width, int height);
  void ensure_pool(std::size_t fragments);
  void draw_outlines(const FrameInputs& inputs, const lod::Mat4& view_projection);

  // The passes of render(), in order (this file's header comment); FrameSetup holds
  // what they share for one frame (matrices, slot ids, palette, meshes in draw order).
  struct FrameSetup;
  void draw_opaque_pass(const FrameInputs& inputs, const FrameSetup& frame, int height,
                        FrameStats& stats);
  // Every geometry pass the frame needs (a second one when the fragment pool overflowed);
  // returns the depth limit beyond which fragments were dropped (max: none).
  float fill_fragment_lists(const FrameInputs& inputs, const FrameSetup& frame,
                            FrameStats& stats);
  // One geometry pass; returns the number of fragments it generated.
  std::uint64_t draw_geometry_pass(const FrameInputs& inputs, const FrameSetup& frame,
                                   float depth_limit, FrameStats& stats);
  void sort_fragment_lists();
  void resolve_fragment_lists(const FrameInputs& inputs, const FrameSetup& frame,
                              GLuint framebuffer, float depth_limit);

  RenderSettings settings_;
  std::string user_source_;
  std::string user_name_ = "built-in clouds.glsl";
  std::vector<std::uint32_t> slot_ids_;
  std::vector<std::string> attribute_names_;

  GlProgram geometry_program_, resolve_program_;  // with the user's code
  GlProgram sort_program_, background_program_, line_program_;
  GlVertexArray empty_vertex_array_;
  GlVertexArray line_vertex_array_;
  GlBuffer line_buffer_;

  int width_ = 0, height_ = 0;
  GlFramebuffer opaque_framebuffer_;
  GlTexture opaque_color_, opaque_depth_;
  GlTexture heads_, listed_;
  GlBuffer pool_, counter_, resolve_stats_, histogram_;
  std::size_t capacity_ = 0;
  std::array<GlQuery, 3> timers_;

  GpuMeshes meshes_;
  MotionTextures motion_textures_;
  TrackDrawing track_drawing_;
  TerrainDrawing terrain_drawing_;
  SliceDrawing slice_drawing_;
};

}  // namespace strielad::render
