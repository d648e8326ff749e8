// SPDX-License-Identifier: Apache-2.0
// The meshes of one octree node as the viewer draws them: every sub-volume's mesh of a
// NodeResult placed in the world frame (lod/world_frame.h, kilometres) and packed into
// one interleaved vertex array and one index array, ready to upload as they are; the
// node's slice meshes (protocol version 2) likewise into their own two arrays, drawn
// opaque by render/slice_drawing.h.
//
// Positions are world kilometres at vertical exaggeration 1 (z is the true height in
// km); the renderer applies the exaggeration as a scale of z, so changing it needs no
// new geometry. Normals are transformed with the inverse transpose of the axis-to-world
// Jacobian, so they stay outward and perpendicular to the surface in the world frame.
// With heights from a variable (view/height_placement.h) a sub-volume vertex's z is the
// variable's value (carried as a mesh attribute), and its normal the placed surface's
// own (area-weighted face normals): the map's vertical derivatives are not known per
// vertex. Vertices where the value is missing, and slices, keep the frame's height.
//
// On the globe (lod::FrameShape; WGS84 ECEF km) "up" is not z, so the exaggeration cannot
// be a scale of z: positions are placed at the globe's exaggeration (PlacerShape;
// placed_exaggeration() is what they carry), and the renderer's vertex shaders move each
// along its ellipsoid normal to the exaggeration drawn (render/wgs84_glsl.h
// globe_redrawn), so changing it needs no new geometry either.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "lod/world_frame.h"
#include "octree/octree_layout.h"
#include "protocol/messages.h"
#include "view/height_placement.h"

namespace strielad::view {

// Per-vertex attribute values a colour function sees (the scene's first eight
// attributes; formats/scene.md allows more, which the viewer does not pass on).
inline constexpr std::size_t kViewAttributeSlots = 8;
// Sub-volumes the viewer tells apart (the A-buffer keeps a 5-bit slot per fragment).
inline constexpr std::size_t kMaxViewSubVolumes = 32;

// Interleaved float layout of one vertex.
inline constexpr std::size_t kVertexPosition = 0;   // 3 floats, world km (exaggeration 1)
inline constexpr std::size_t kVertexNormal = 3;     // 3 floats, unit, world frame
inline constexpr std::size_t kVertexSlot = 6;       // 1 float: the sub-volume's slot
inline constexpr std::size_t kVertexAttributes = 7; // kViewAttributeSlots floats, NaN = missing
inline constexpr std::size_t kVertexFloats = kVertexAttributes + kViewAttributeSlots;

// Slices the viewer tells apart (formats/scene.md allows 16 per scene).
inline constexpr std::size_t kMaxViewSlices = 16;
// Interleaved float layout of one slice vertex.
inline constexpr std::size_t kSliceVertexPosition = 0;  // 3 floats, world km (exaggeration 1)
inline constexpr std::size_t kSliceVertexNormal = 3;    // 3 floats, unit, world frame
inline constexpr std::size_t kSliceVertexValue = 6;     // 1 float: colouring variable, NaN = missing
inline constexpr std::size_t kSliceVertexSlot = 7;      // 1 float: the slice's position in the scene
inline constexpr std::size_t kSliceVertexFloats = 8;

// Smallest and largest finite colouring value per slice slot; lo > hi when there is none.
using SliceValueRanges = std::array<std::array<float, 2>, kMaxViewSlices>;
inline constexpr SliceValueRanges kNoSliceValues = [] {
  SliceValueRanges r{};
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (auto& lo_hi : r) lo_hi = {kInf, -kInf};
  return r;
}();

struct NodeGeometry {
  NodeId node = 0;
  std::uint32_t step = 0;               // the time step the meshes show
  std::vector<float> vertices;          // kVertexFloats per vertex
  std::vector<std::uint32_t> indices;   // triangles, counter-clockwise seen from outside
                                        // in axis coordinates (see mirrored)
  std::vector<float> slice_vertices;          // kSliceVertexFloats per vertex
  std::vector<std::uint32_t> slice_indices;   // slice triangles (drawn two-sided)
  // The range of each slice's values in slice_vertices, kept as they are appended, so
  // that the range of everything shown (view/slice_ranges.h) costs no pass over the
  // vertices on every frame.
  SliceValueRanges slice_value_ranges = kNoSliceValues;
  std::size_t vertex_count() const { return vertices.size() / kVertexFloats; }
  std::size_t triangle_count() const { return indices.size() / 3; }
  std::size_t slice_vertex_count() const { return slice_vertices.size() / kSliceVertexFloats; }
  std::size_t slice_triangle_count() const { return slice_indices.size() / 3; }
  // Nothing to draw: no sub-volume and no slice triangle.
  bool empty() const { return indices.empty() && slice_indices.empty(); }
};

// The world's shape for a placer: the plane, the globe, or the globe for wide domains
// (lod::kGlobeMinExtentDeg), and the vertical exaggeration placed into a globe's positions.
struct PlacerShape {
  lod::FrameShape shape = lod::FrameShape::kPlane;
  double globe_exaggeration = lod::kDefaultVerticalExaggeration;  // finite, > 0
};

// Maps axis coordinates of a store to the viewer's world frame at exaggeration 1 (on the
// globe, at PlacerShape::globe_exaggeration).
class GeometryPlacer {
 public:
  // \error as lod::WorldFrame for axes without a world position.
  // `horizontal_coordinates`: a curvilinear store's GEOMETRY coordinates
  // (Store::horizontal_coordinates), which its frame needs (lod::WorldFrameOptions).
  explicit GeometryPlacer(
      const format::Manifest& manifest, HeightPlacement heights = {},
      std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates = nullptr,
      PlacerShape shape = {});

  // The exaggeration the placed positions carry: 1 on the plane (the renderer scales z),
  // the globe's on the globe (the renderer must not scale).
  double placed_exaggeration() const { return frame_.vertical_exaggeration(); }

  // The node's meshes of time step `step` packed. `slot_of_id(id)` gives the slot of a sub-volume id (the
  // position of the sub-volume in the scene); a mesh whose id has no slot is left out.
  // Slice meshes are packed with their position in result.slices (the scene's slice
  // order) as their slot; those beyond kMaxViewSlices are left out. `height_attribute`:
  // the position of heights().variable among the meshes' attributes (the scene's
  // attributes as sent); -1 places every vertex by the frame.
  // \error kInvalidInput naming the node when a mesh has a non-finite position or an
  // index out of range (the decoder checks both; this guards the upload).
  template <typename SlotOf>
  std::shared_ptr<const NodeGeometry> place(const protocol::NodeResult& result,
                                            std::uint32_t step, SlotOf slot_of_id,
                                            int height_attribute = -1) const;

  // True when the axis-to-world map reverses orientation (an odd number of decreasing
  // axis maps, e.g. a pressure axis): counter-clockwise triangles seen from outside in
  // axis coordinates are then clockwise in the world, and the renderer flips its
  // front-face rule.
  bool mirrored() const { return mirrored_; }
  const lod::WorldFrame& frame() const { return frame_; }
  const HeightPlacement& heights() const { return heights_; }

 private:
  void append_mesh(const Mesh& mesh, std::uint32_t slot, int height_attribute,
                   NodeGeometry& out) const;
  void append_slice(const Mesh& mesh, std::uint32_t slot, NodeGeometry& out) const;
  // Heights (and normals) of the vertices from `first` on from the variable's values;
  // their triangles start at out.indices[first_triangle_index].
  void place_heights(const std::vector<float>& values, std::size_t first,
                     std::size_t first_triangle_index, NodeGeometry& out) const;

  lod::WorldFrame frame_;
  bool mirrored_ = false;
  HeightPlacement heights_;
};

template <typename SlotOf>
std::shared_ptr<const NodeGeometry> GeometryPlacer::place(const protocol::NodeResult& result,
                                                          std::uint32_t step,
                                                          SlotOf slot_of_id,
                                                          int height_attribute) const {
  auto geometry = std::make_shared<NodeGeometry>();
  geometry->node = result.node;
  geometry->step = step;
  for (const auto& sub : result.subvolumes) {
    if (sub.outcome != NodeOutcome::kMesh || sub.mesh.empty()) continue;
    const int slot = slot_of_id(sub.subvolume_id);
    if (slot < 0) continue;
    append_mesh(sub.mesh, static_cast<std::uint32_t>(slot), height_attribute, *geometry);
  }
  for (std::size_t i = 0; i < result.slices.size() && i < kMaxViewSlices; ++i) {
    const auto& slice = result.slices[i];
    if (slice.outcome != NodeOutcome::kMesh || slice.mesh.empty()) continue;
    append_slice(slice.mesh, static_cast<std::uint32_t>(i), *geometry);
  }
  return geometry;
}

}  // namespace strielad::view
