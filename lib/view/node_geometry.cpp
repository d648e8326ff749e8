// SPDX-License-Identifier: Apache-2.0
#include "view/node_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include "core/error.h"

namespace strielad::view {
GeometryPlacer::GeometryPlacer(
    const format::Manifest& manifest, HeightPlacement heights,
    std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates,
    PlacerShape shape)
    : frame_(manifest,
             lod::WorldFrameOptions{.vertical_exaggeration = 1.0, .shape = shape.shape},
             heights.level_heights_m, std::move(horizontal_coordinates)),
      mirrored_(frame_.mirrored()),
      heights_(std::move(heights)) {
  if (frame_.globe()) frame_ = frame_.with_exaggeration(shape.globe_exaggeration);
}

namespace {

// Places vertex v of `mesh` in the world frame: its position into position[0..2] and
// its normal (the inverse transpose of the axis-to-world Jacobian, renormalized;
// straight up if it vanishes: lod::WorldFrame::normal_to_world) into normal[0..2].
// \error kInvalidInput naming the node and `what` for a vertex without a world position.
void place_vertex(const lod::WorldFrame& frame, const Mesh& mesh, std::size_t v, NodeId node,
                  std::string_view what, float* position, float* normal_out) {
  const auto& p = mesh.positions[v];
  const Vec3 world = frame.to_world(p);
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(world[axis])) {
      throw make_error(ErrorCode::kInvalidInput, "node {}: {} {}: vertex {} has no world position",
                       node, what, mesh.subvolume_id, v);
    }
    position[axis] = static_cast<float>(world[axis]);
  }
  const auto& n = mesh.normals[v];
  const Vec3 normal = frame.normal_to_world(p, {n[0], n[1], n[2]});
  for (int axis = 0; axis < 3; ++axis) normal_out[axis] = static_cast<float>(normal[axis]);
}

// Appends the mesh's triangles, their indices offset by `first`.
// \error kInvalidInput naming the node and `what` for an index out of range.
void append_triangles(const Mesh& mesh, std::size_t first, NodeId node, std::string_view what,
                      std::vector<std::uint32_t>& indices) {
  const std::size_t n = mesh.vertex_count();
  indices.reserve(indices.size() + mesh.triangle_count() * 3);
  for (const auto& t : mesh.triangles) {
    for (const auto index : t) {
      if (index >= n) {
        throw make_error(ErrorCode::kInvalidInput, "node {}: {} {}: index {} >= vertex count {}",
                         node, what, mesh.subvolume_id, index, n);
      }
      indices.push_back(static_cast<std::uint32_t>(first + index));
    }
  }
}

}  // namespace

void GeometryPlacer::append_slice(const Mesh& mesh, std::uint32_t slot, NodeGeometry& out) const {
  const std::size_t first = out.slice_vertex_count();
  const std::size_t n = mesh.vertex_count();
  if (first + n > std::numeric_limits<std::uint32_t>::max()) {
    throw make_error(ErrorCode::kInvalidInput, "node {}: more than 2^32 slice vertices", out.node);
  }
  if (mesh.attributes.size() != 1 || mesh.attributes[0].size() != n || mesh.normals.size() != n) {
    throw make_error(ErrorCode::kInvalidInput,
                     "node {}: slice {}: {} attributes and {} normals for {} vertices (one "
                     "colouring value and one normal per vertex expected)",
                     out.node, mesh.subvolume_id, mesh.attributes.size(), mesh.normals.size(), n);
  }
  out.slice_vertices.resize((first + n) * kSliceVertexFloats);
  for (std::size_t v = 0; v < n; ++v) {
    float* dst = out.slice_vertices.data() + (first + v) * kSliceVertexFloats;
    place_vertex(frame_, mesh, v, out.node, "slice", dst + kSliceVertexPosition,
                 dst + kSliceVertexNormal);
    const float value = mesh.attributes[0][v];
    dst[kSliceVertexValue] = value;
    dst[kSliceVertexSlot] = static_cast<float>(slot);
    if (std::isfinite(value) && slot < kMaxViewSlices) {
      auto& r = out.slice_value_ranges[slot];
      r = {std::min(r[0], value), std::max(r[1], value)};
    }
  }
  append_triangles(mesh, first, out.node, "slice", out.slice_indices);
}

void GeometryPlacer::append_mesh(const Mesh& mesh, std::uint32_t slot, int height_attribute,
                                 NodeGeometry& out) const {
  const std::size_t first = out.vertex_count();
  const std::size_t n = mesh.vertex_count();
  if (first + n > std::numeric_limits<std::uint32_t>::max()) {
    throw make_error(ErrorCode::kInvalidInput, "node {}: more than 2^32 vertices", out.node);
  }
  const std::size_t attributes = std::min(mesh.attributes.size(), kViewAttributeSlots);
  out.vertices.resize((first + n) * kVertexFloats);
  for (std::size_t v = 0; v < n; ++v) {
    float* dst = out.vertices.data() + (first + v) * kVertexFloats;
    place_vertex(frame_, mesh, v, out.node, "sub-volume", dst + kVertexPosition,
                 dst + kVertexNormal);
    dst[kVertexSlot] = static_cast<float>(slot);
    for (std::size_t a = 0; a < kViewAttributeSlots; ++a) {
      dst[kVertexAttributes + a] = a < attributes ? mesh.attributes[a][v]
                                                  : std::numeric_limits<float>::quiet_NaN();
    }
  }
  const std::size_t first_triangle_index = out.indices.size();
  append_triangles(mesh, first, out.node, "sub-volume", out.indices);
  if (heights_.kind == HeightPlacement::Kind::kVariable && height_attribute >= 0) {
    const auto a = static_cast<std::size_t>(height_attribute);
    if (a >= mesh.attributes.size() || mesh.attributes[a].size() != n) {
      throw make_error(ErrorCode::kInvalidInput,
                       "node {}: sub-volume {}: {} attributes; the heights '{}' were asked "
                       "for as attribute {}",
                       out.node, mesh.subvolume_id, mesh.attributes.size(), heights_.variable, a);
    }
    place_heights(mesh.attributes[a], first, first_triangle_index, out);
  }
}

void GeometryPlacer::place_heights(const std::vector<float>& values, std::size_t first,
                                   std::size_t first_triangle_index, NodeGeometry& out) const {
  // z from the variable where it has a value (the frame's height where it is missing).
  const std::size_t n = values.size();
  for (std::size_t v = 0; v < n; ++v) {
    const float value = values[v];
    if (!std::isfinite(value)) continue;
    float* position = &out.vertices[(first + v) * kVertexFloats + kVertexPosition];
    const double km = heights_.metres(value) * 1e-3;
    if (!frame_.globe()) {
      position[2] = static_cast<float>(km);
      continue;
    }
    // On the globe: the same longitude and latitude, at the value's height.
    const Vec3 g = frame_.geographic_of({position[0], position[1], position[2]});
    const Vec3 placed = frame_.place_geographic(g[0], g[1], km * frame_.vertical_exaggeration());
    for (int c = 0; c < 3; ++c) position[c] = static_cast<float>(placed[c]);
  }
  // Normals of the placed surface: area-weighted face normals, outward (flipped where
  // the map reverses orientation, as the renderer's front-face rule is).
  std::vector<Vec3> sum(n, Vec3{0, 0, 0});
  const auto position = [&](std::uint32_t i) {
    const float* p = &out.vertices[std::size_t(i) * kVertexFloats + kVertexPosition];
    return Vec3{p[0], p[1], p[2]};
  };
  const double sign = mirrored_ ? -1.0 : 1.0;
  const auto first_index = static_cast<std::uint32_t>(first);
  for (std::size_t k = first_triangle_index; k + 2 < out.indices.size(); k += 3) {
    const std::uint32_t i0 = out.indices[k], i1 = out.indices[k + 1], i2 = out.indices[k + 2];
    const Vec3 p0 = position(i0);
    const Vec3 f =
        scale(cross(sub(position(i1), p0), sub(position(i2), p0)), sign);
    for (const std::uint32_t i : {i0, i1, i2}) {
      for (int c = 0; c < 3; ++c) sum[i - first_index][c] += f[c];
    }
  }
  for (std::size_t v = 0; v < n; ++v) {
    const double len = length(sum[v]);
    if (!(len > 0) || !std::isfinite(len)) continue;  // keeps the frame's normal
    float* normal = &out.vertices[(first + v) * kVertexFloats + kVertexNormal];
    for (int c = 0; c < 3; ++c) normal[c] = static_cast<float>(sum[v][c] / len);
  }
}

}  // namespace strielad::view
