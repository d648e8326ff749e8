// SPDX-License-Identifier: Apache-2.0
#include "render/volume_shaders.h"

#include <fmt/format.h>

#include <cctype>

#include "render/default_user_shader.h"  // generated from examples/shaders/clouds.glsl
#include "render/wgs84_glsl.h"
#include "view/node_geometry.h"

namespace strielad::render {
namespace {

constexpr const char* kVersion = "#version 450 core\n";

// The fragment record of the per-pixel lists: 16 bytes.
constexpr const char* kFragmentRecord = R"(
struct Fragment {
  float depth;  // eye-space depth, km
  uint color;   // packUnorm4x8(rgb, opacity scale / MAX_OPACITY_SCALE)
  uint meta;    // bits 0-4: sub-volume slot; bit 5: entering (front face)
  uint next;    // next fragment of the pixel, 0xFFFFFFFF ends the list
};
)";

std::string glsl_identifier(const std::string& name) {
  std::string out;
  for (const char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

}  // namespace

std::string user_prelude(const std::vector<std::string>& attribute_names) {
  std::string s = fmt::format("#define MAX_ATTRIBUTES {}\n#define MAX_OPACITY_SCALE {:.1f}\n",
                              view::kViewAttributeSlots, kMaxOpacityScale);
  for (std::size_t i = 0; i < attribute_names.size() && i < view::kViewAttributeSlots; ++i) {
    s += fmt::format("#define ATTR_{} {}\n", glsl_identifier(attribute_names[i]), i);
  }
  s += R"(
uniform float u_vertical_exaggeration;
// > 0 on the globe: world positions are WGS84 ECEF km whose heights are drawn at this
// exaggeration (u_vertical_exaggeration is then 1).
uniform float u_globe_exaggeration;
)" + std::string(kWgs84Glsl) + R"(
// Height in metres of a world position, without the vertical exaggeration: above the
// vertical axis' zero on the plane (standard-atmosphere height on pressure axes), above
// the WGS84 ellipsoid on the globe.
float height_m(vec3 position) {
  if (u_globe_exaggeration > 0.0) return globe_height_km(position) / u_globe_exaggeration * 1000.0;
  return position.z / u_vertical_exaggeration * 1000.0;
}
// Attribute values are NaN where the data has no value.
bool missing(float value) { return isnan(value) || isinf(value); }
// The palette colour of sub-volume `id` (view/subvolume_palette.h): the n-th sub-volume
// of the scene gets the palette's n-th colour; grey for an id the scene does not have.
uniform vec3 u_subvolume_colors[32];
vec3 subvolume_color(int id) {
  vec3 c = vec3(0.5);
  for (int s = 0; s < 32; ++s) {  // a fixed trip count (see the resolve pass)
    if (u_slot_ids[s] == id) c = u_subvolume_colors[s];
  }
  return c;
}
vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time);
float alpha(int id, float distance);
)";
  return s;
}

std::string geometry_vertex_source() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_slot;
layout(location = 3) in vec4 a_attributes0;
layout(location = 4) in vec4 a_attributes1;
uniform mat4 u_view_projection;
uniform mat4 u_view;
uniform float u_vertical_exaggeration;
// Wind advection (render/mesh_motion.h): displacement keyframes around the mesh's time.
uniform bool u_moving;
uniform float u_motion_weight;
uniform vec3 u_motion_lo;
uniform vec3 u_motion_size;
uniform vec3 u_motion_lattice;
// The globe (u_globe_exaggeration > 0): positions are placed with their heights at
// u_globe_placed_exaggeration and drawn at u_globe_exaggeration (globe_redrawn). The
// map is in (longitude deg, latitude deg, height km) and holds (dlon cos(lat0), dlat, dh)
// (view/displacement_map.h).
uniform float u_globe_exaggeration;
uniform float u_globe_placed_exaggeration;
uniform bool u_motion_periodic;
layout(binding = 2) uniform sampler3D u_motion_from;
layout(binding = 3) uniform sampler3D u_motion_to;
out vec3 v_world;
out vec3 v_normal;
out float v_eye_depth;
flat out int v_slot;
out vec4 v_attributes0;
out vec4 v_attributes1;
)" + std::string(kWgs84Glsl) + R"(
// The displacement recorded at lattice-space position q (trilinear in space, linear
// between the two keyframes); texel centres sit at lattice points: (u (n - 1) + 0.5) / n.
vec3 motion_at(vec3 q) {
  vec3 u = clamp((q - u_motion_lo) / u_motion_size, 0.0, 1.0);
  if (u_motion_periodic) u.x = fract((q.x - u_motion_lo.x) / 360.0);
  vec3 tc = (u * (u_motion_lattice - 1.0) + 0.5) / u_motion_lattice;
  return mix(texture(u_motion_from, tc).xyz, texture(u_motion_to, tc).xyz, u_motion_weight);
}
const float DEGREES = 57.29577951308232;
void main() {
  vec3 position = a_position;
  vec3 normal = a_normal;
  if (u_moving && u_globe_exaggeration > 0.0) {
    // Moved in longitude, latitude and height, placed back on the globe at the
    // exaggerated height; the normal keeps its east/north/up parts.
    float lon = atan(a_position.y, a_position.x), lat = globe_latitude(a_position);
    float h = globe_height_at(a_position, lat);
    float lon_deg = lon * DEGREES;
    if (!u_motion_periodic) {
      float centre = u_motion_lo.x + 0.5 * u_motion_size.x;
      lon_deg = centre + (lon_deg - centre) - 360.0 * floor((lon_deg - centre) / 360.0 + 0.5);
    }
    vec3 d = motion_at(vec3(lon_deg, lat * DEGREES, h / u_globe_placed_exaggeration));
    float lon1 = lon + d.x / max(cos(lat), 1e-6) / DEGREES;
    float lat1 = lat + d.y / DEGREES;
    float h1 = h + d.z * u_globe_placed_exaggeration;
    position = a_position + (globe_place(lon1, lat1, h1) - globe_place(lon, lat, h));
    vec3 e0 = vec3(-sin(lon), cos(lon), 0.0);
    vec3 up0 = vec3(cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat));
    vec3 n0 = cross(up0, e0);
    vec3 e1 = vec3(-sin(lon1), cos(lon1), 0.0);
    vec3 up1 = vec3(cos(lat1) * cos(lon1), cos(lat1) * sin(lon1), sin(lat1));
    vec3 n1 = cross(up1, e1);
    normal = dot(a_normal, e0) * e1 + dot(a_normal, n0) * n1 + dot(a_normal, up0) * up1;
  } else if (u_moving) {
    position += motion_at(a_position);
  }
  if (u_globe_exaggeration > 0.0) {
    position = globe_redrawn(position, normal, u_globe_exaggeration / u_globe_placed_exaggeration);
  }
  vec3 world = vec3(position.xy, position.z * u_vertical_exaggeration);
  v_world = world;
  v_normal = vec3(normal.xy, normal.z / u_vertical_exaggeration);
  v_eye_depth = -(u_view * vec4(world, 1.0)).z;
  v_slot = int(a_slot + 0.5);
  v_attributes0 = a_attributes0;
  v_attributes1 = a_attributes1;
  gl_Position = u_view_projection * vec4(world, 1.0);
}
)";
}

std::string geometry_fragment_source(const std::string& prelude) {
  return std::string(kVersion) + "layout(early_fragment_tests) in;\n" + kFragmentRecord +
         R"(
layout(binding = 0, r32ui) uniform coherent uimage2D u_heads;
layout(binding = 0, offset = 0) uniform atomic_uint u_fragment_counter;
layout(std430, binding = 1) buffer FragmentPool { Fragment fragments[]; };
layout(std430, binding = 3) buffer DepthHistogram { uint depth_bins[256]; };
uniform uint u_capacity;
uniform float u_near;
uniform float u_far;
uniform float u_depth_limit;
uniform vec3 u_eye;
uniform vec3 u_sun;
uniform float u_time;
uniform bool u_mirrored;
uniform int u_slot_ids[32];
in vec3 v_world;
in vec3 v_normal;
in float v_eye_depth;
flat in int v_slot;
in vec4 v_attributes0;
in vec4 v_attributes1;
)" + prelude + R"(
void main() {
  float attributes[MAX_ATTRIBUTES] = float[](v_attributes0.x, v_attributes0.y, v_attributes0.z,
      v_attributes0.w, v_attributes1.x, v_attributes1.y, v_attributes1.z, v_attributes1.w);
  vec3 n = normalize(v_normal);
  // The outward normal: on a back face (the ray leaves) it points away from the eye.
  vec4 c = color(u_slot_ids[v_slot], attributes, n, u_sun, v_world,
                 normalize(u_eye - v_world), u_time);
  if (any(isnan(c)) || any(isinf(c))) c = vec4(1.0, 0.0, 1.0, 1.0);  // shows a broken colour
  c = vec4(clamp(c.rgb, 0.0, 1.0), clamp(c.a, 0.0, MAX_OPACITY_SCALE) / MAX_OPACITY_SCALE);
  if (v_eye_depth >= u_depth_limit) return;  // beyond what the pool can hold
  // Log-spaced depth bins from near to far (VolumeRenderer's depth limit).
  float t = log(max(v_eye_depth, u_near) / u_near) / log(u_far / u_near);
  atomicAdd(depth_bins[clamp(int(t * 256.0), 0, 255)], 1u);
  uint index = atomicCounterIncrement(u_fragment_counter);
  if (index >= u_capacity) return;  // the pool is full: counted, not stored
  bool entering = gl_FrontFacing != u_mirrored;
  fragments[index].depth = v_eye_depth;
  fragments[index].color = packUnorm4x8(c);
  fragments[index].meta = uint(v_slot) | (entering ? 32u : 0u);
  fragments[index].next = imageAtomicExchange(u_heads, ivec2(gl_FragCoord.xy), index);
}
)";
}

std::string resolve_vertex_source() {
  return std::string(kVersion) + R"(
void main() {
  // One triangle covering the viewport.
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
}

std::string sort_fragment_source() {
  return std::string(kVersion) + fmt::format("#define K {}\n", kMaxLayersPerPixel) +
         kFragmentRecord + R"(
layout(binding = 0, r32ui) uniform coherent uimage2D u_heads;
layout(binding = 1, r32ui) uniform writeonly uimage2D u_listed;
layout(std430, binding = 1) buffer FragmentPool { Fragment fragments[]; };
layout(std430, binding = 2) buffer ResolveStats {
  uint covered_pixels;    // pixels with at least one fragment
  uint truncated_pixels;  // pixels with more than K fragments (the farthest dropped)
  uint max_list;          // the longest list
  uint listed_total;      // fragments in all lists
};
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  uint head = imageLoad(u_heads, px).r;
  if (head == 0xFFFFFFFFu) return;
  // The K nearest fragments by depth (insertion sort; farther ones are dropped), then
  // the list is relinked in that order so the resolve walks it front to back.
  float depth[K];
  uint index[K];
  int n = 0;
  uint listed = 0u;
  for (uint i = head; i != 0xFFFFFFFFu; i = fragments[i].next) {
    ++listed;
    float d = fragments[i].depth;
    if (n == K && d >= depth[K - 1]) continue;
    int j = n < K ? n++ : K - 1;
    while (j > 0 && depth[j - 1] > d) {
      depth[j] = depth[j - 1];
      index[j] = index[j - 1];
      --j;
    }
    depth[j] = d;
    index[j] = i;
  }
  for (int f = 0; f < n; ++f) {
    fragments[index[f]].next = f + 1 < n ? index[f + 1] : 0xFFFFFFFFu;
  }
  imageStore(u_heads, px, uvec4(index[0]));
  imageStore(u_listed, px, uvec4(listed));
  atomicAdd(covered_pixels, 1u);
  atomicAdd(listed_total, listed);
  atomicMax(max_list, listed);
  if (listed > uint(K)) atomicAdd(truncated_pixels, 1u);
}
)";
}

namespace {

// The resolve pass's inputs: the sorted lists, the opaque scene and the frame's uniforms.
constexpr const char* kResolveBindings = R"(
layout(binding = 0, r32ui) uniform readonly uimage2D u_heads;
layout(binding = 1, r32ui) uniform readonly uimage2D u_listed;
layout(std430, binding = 1) readonly buffer FragmentPool { Fragment fragments[]; };
layout(binding = 0) uniform sampler2D u_opaque_color;
layout(binding = 1) uniform sampler2D u_opaque_depth;
uniform mat4 u_inverse_projection;
uniform mat4 u_inverse_view;
uniform float u_near;
uniform float u_far;
uniform int u_slot_ids[32];
uniform float u_seam_relative;
uniform float u_depth_limit;
uniform float u_time;
out vec4 o_color;
)";

// The resolve shader's main() begins: the background where the pixel has no list, else
// the pixel's ray, from which true_km() measures true distances along it.
constexpr const char* kResolveRayScale = R"(
float linear_depth(float d) {
  float z = d * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - z * (u_far - u_near));
}

// The pixel's ray (set at the start of main()): its unit direction in the world, world km
// per unit of eye depth, the eye, and on the plane true km per unit of eye depth.
vec3 ray_world_;
float km_per_depth_;
vec3 eye_world_;
float to_true_km_;

// True (unexaggerated) kilometres of the ray between eye depths d0 and d1. On the plane
// the vertical part of the ray is divided by the exaggeration. On the globe, at the
// middle of each quarter of the segment: the part along the ellipsoid normal divided by
// the exaggeration, the part across it scaled from the exaggerated height's sphere to
// the true height's ((R + h) / (R + h E)).
float true_km(float d0, float d1) {
  float depth = max(d1 - d0, 0.0);
  if (u_globe_exaggeration <= 0.0) return depth * to_true_km_;
  float km = 0.0;
  for (int q = 0; q < 4; ++q) {
    vec3 p = eye_world_ + ray_world_ * ((d0 + (float(q) + 0.5) * 0.25 * depth) * km_per_depth_);
    vec3 up = normalize(vec3(p.xy, p.z / (1.0 - WGS84_E2)));
    float h = globe_height_km(p);
    float ground = max(length(p) - h, 1.0);
    float radial = dot(ray_world_, up);
    vec3 across = (ray_world_ - radial * up) * ((ground + h / u_globe_exaggeration) / max(ground + h, 1.0));
    km += length(across + up * (radial / u_globe_exaggeration));
  }
  return km * 0.25 * depth * km_per_depth_;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 background = texelFetch(u_opaque_color, px, 0);
  uint head = imageLoad(u_heads, px).r;
  if (head == 0xFFFFFFFFu) {
    o_color = vec4(background.rgb, 1.0);
    return;
  }
  uint listed = imageLoad(u_listed, px).r;

  // Eye depth to true distance along this pixel's ray (without vertical exaggeration).
  vec2 ndc = (vec2(px) + 0.5) / vec2(textureSize(u_opaque_color, 0)) * 2.0 - 1.0;
  vec4 eye = u_inverse_projection * vec4(ndc, 1.0, 1.0);
  vec3 ray_eye = normalize(eye.xyz / eye.w);
  vec3 ray_world = mat3(u_inverse_view) * ray_eye;
  ray_world_ = ray_world;
  km_per_depth_ = 1.0 / max(-ray_eye.z, 1e-6);
  eye_world_ = (u_inverse_view * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
  to_true_km_ = length(vec3(ray_world.xy, ray_world.z / u_vertical_exaggeration)) * km_per_depth_;
)";

// main() goes on: the walk along the sorted list that turns fragments into segments.
constexpr const char* kResolveSegmentWalk = R"(
  // One walk front to back (the sort pass relinked the list in depth order). A
  // segment of a sub-volume slot opens at an entry and gets the next place in the
  // segment list, so the list is in order of where segments begin; it closes at the
  // exit that brings the slot's nesting count to 0, unless the slot enters again within
  // u_seam_relative of that depth (it leaves one node and enters the next: the same
  // segment goes on). A slot left without having entered began at the near plane (the
  // eye is inside): such segments come before all others.
  // Every loop has a fixed trip count: Mesa's llvmpipe 22.3 ends loops whose lanes
  // leave at different iterations too early in some 4x4 pixel blocks
  // (tests/render/abuffer_pixels_test.cpp and abuffer_limits_test.cpp catch it).
  int inside[32];
  int open_segment[32];   // the slot's current segment, -1 when none
  float exit_depth[32];   // where the slot last left (its segment may go on)
  uint pending = 0u;      // slots that left and may go on through a node face
  for (int s = 0; s < 32; ++s) {
    inside[s] = 0;
    open_segment[s] = -1;
    exit_depth[s] = 0.0;
  }
  float seg_start[K];
  float seg_end[K];
  uint seg_color[K];
  int seg_slot[K];
  int segments = 0;
  // Segments from the near plane, one per slot at most.
  float near_end[32];
  uint near_color[32];
  uint near_slots = 0u;
  float last = 0.0;
  uint i = head;
  for (int k = 0; k < K; ++k) {
    if (i == 0xFFFFFFFFu) continue;
    float d = fragments[i].depth;
    uint meta = fragments[i].meta;
    uint color = fragments[i].color;
    i = fragments[i].next;
    last = d;
    int s = int(meta & 31u);
    uint bit = 1u << uint(s);
    bool entering = (meta & 32u) != 0u;
    bool at_seam = (pending & bit) != 0u && d - exit_depth[s] <= u_seam_relative * d;
    if (!at_seam) pending &= ~bit;  // its segment ended at exit_depth (already recorded)
    if (entering) {
      if (inside[s] == 0 && !at_seam && segments < K) {
        seg_start[segments] = d;
        seg_end[segments] = d;
        seg_color[segments] = color;
        seg_slot[segments] = s;
        open_segment[s] = segments++;
      }
      pending &= ~bit;
      ++inside[s];
    } else if (inside[s] > 0) {
      if (--inside[s] == 0) {
        if (open_segment[s] >= 0) seg_end[open_segment[s]] = d;
        exit_depth[s] = d;
        pending |= bit;
      }
    } else if (!at_seam) {
      if ((near_slots & bit) == 0u) {
        near_slots |= bit;
        near_color[s] = color;
        near_end[s] = d;
      } else if (open_segment[s] < 0) {
        near_end[s] = d;  // the near-plane segment went on through a node face
      }
      exit_depth[s] = d;
      pending |= bit;
    } else if ((near_slots & bit) != 0u && open_segment[s] < 0) {
      near_end[s] = d;
    }  // else: a second exit at a node face
  }
)";

// main() ends: the open segments closed, every segment's opacity from the user's
// alpha(), composited front to back over the background.
constexpr const char* kResolveCompositing = R"(  // What is still open ends behind the last kept fragment (list truncated) or at the
  // opaque scene (its exit is hidden behind it, or beyond the far plane).
  float end = listed > uint(K) ? last : linear_depth(texelFetch(u_opaque_depth, px, 0).r);
  end = min(end, u_depth_limit);
  for (int s = 0; s < 32; ++s) {
    if (inside[s] > 0 && open_segment[s] >= 0) seg_end[open_segment[s]] = max(end, seg_start[open_segment[s]]);
  }
  vec3 rgb = vec3(0.0);
  float a = 0.0;
  for (int s = 0; s < 32 && near_slots != 0u; ++s) {  // (uniform unless the eye is inside)
    if ((near_slots & (1u << uint(s))) == 0u) continue;
    vec4 c = unpackUnorm4x8(near_color[s]);
    float o = alpha(u_slot_ids[s], true_km(u_near, near_end[s]));
    o = isnan(o) ? 1.0 : clamp(o * c.a * MAX_OPACITY_SCALE, 0.0, 1.0);
    float w = (1.0 - a) * o;
    rgb += w * c.rgb;
    a += w;
  }
  for (int k = 0; k < K; ++k) {
    if (k >= segments) continue;
    vec4 c = unpackUnorm4x8(seg_color[k]);
    float o = alpha(u_slot_ids[seg_slot[k]], true_km(seg_start[k], seg_end[k]));
    o = isnan(o) ? 1.0 : clamp(o * c.a * MAX_OPACITY_SCALE, 0.0, 1.0);
    float w = (1.0 - a) * o;
    rgb += w * c.rgb;
    a += w;
  }
  o_color = vec4(rgb + (1.0 - a) * background.rgb, 1.0);
}
)";

}  // namespace

std::string resolve_fragment_source(const std::string& prelude) {
  return std::string(kVersion) + fmt::format("#define K {}\n", kMaxLayersPerPixel) +
         kFragmentRecord + kResolveBindings + prelude + kResolveRayScale + kResolveSegmentWalk +
         kResolveCompositing;
}

std::string background_fragment_source() {
  return std::string(kVersion) + R"(
uniform vec3 u_top;
uniform vec3 u_bottom;
uniform float u_height;
out vec4 o_color;
void main() {
  o_color = vec4(mix(u_bottom, u_top, gl_FragCoord.y / u_height), 1.0);
}
)";
}

std::string line_vertex_source() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_projection;
out vec4 v_color;
void main() {
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";
}

std::string line_fragment_source() {
  return std::string(kVersion) + R"(
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";
}

const std::string& default_user_shader() {
  static const std::string source(kDefaultUserShader);
  return source;
}

}  // namespace strielad::render
