// SPDX-License-Identifier: Apache-2.0
#include "view/node_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include "core/error.h"

namespace strielad::view {
namespace {

// d world / d axis along one axis at `value`, by a central difference scaled to the
// value (the maps are smooth and monotonic; linear ones give their exact slope).
double axis_slope(const lod::WorldFrame& frame, int axis, double value) {
  const double h = std::max(std::abs(value), 1.0) * 1e-6;
  return (frame.axis_to_world(axis, value + h) - frame.axis_to_world(axis, value - h)) /
         (2 * h);
}

}  // namespace

GeometryPlacer::GeometryPlacer(const format::Manifest& manifest)
    : frame_(manifest, lod::WorldFrameOptions{.vertical_exaggeration = 1.0}) {
  int negative = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& domain = frame_.domain();
    const double mid = frame_.world_to_axis(axis, 0.5 * (domain.lo[axis] + domain.hi[axis]));
    if (axis_slope(frame_, axis, mid) < 0) ++negative;
  }
  mirrored_ = (negative % 2) == 1;
}

namespace {

// Places vertex v of `mesh` in the world frame: its position into position[0..2] and
// its normal (the inverse transpose of the diagonal axis-to-world Jacobian: divided by
// the slopes, renormalized; straight up if it vanishes) into normal[0..2].
// \error kInvalidInput naming the node and `what` for a vertex without a world position.
void place_vertex(const lod::WorldFrame& frame, const Mesh& mesh, std::size_t v, NodeId node,
                  std::string_view what, float* position, float* normal_out) {
  const auto& p = mesh.positions[v];
  lod::Vec3 normal{0, 0, 0};
  for (int axis = 0; axis < 3; ++axis) {
    const double world = frame.axis_to_world(axis, p[axis]);
    if (!std::isfinite(world)) {
      throw make_error(ErrorCode::kInvalidInput, "node {}: {} {}: vertex {} has no world position",
                       node, what, mesh.subvolume_id, v);
    }
    position[axis] = static_cast<float>(world);
    normal[axis] = mesh.normals[v][axis] / axis_slope(frame, axis, p[axis]);
  }
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] +
                                  normal[2] * normal[2]);
  for (int axis = 0; axis < 3; ++axis) {
    normal_out[axis] = length > 0 ? static_cast<float>(normal[axis] / length)
                                  : (axis == 2 ? 1.0f : 0.0f);
  }
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

void GeometryPlacer::append_mesh(const Mesh& mesh, std::uint32_t slot, NodeGeometry& out) const {
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
  append_triangles(mesh, first, out.node, "sub-volume", out.indices);
}

}  // namespace strielad::view
