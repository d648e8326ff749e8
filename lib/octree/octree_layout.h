// SPDX-License-Identifier: Apache-2.0
// Geometry of the brick octree over a rectilinear grid (formats/store.md, "Octree").
//
// Level 0 holds leaf bricks of B cells per axis at full resolution. Each coarser level
// halves every axis that still has more than one node, sub-sampling the level below
// with stride 2 along that axis; the last sample of an axis is always kept, so every
// level covers the whole domain (its last cell may be shorter). A node's brick holds
// the B+1 samples of its B cells per axis: neighbours share their boundary samples,
// which is what a cell-based extraction needs to meet without cracks.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "grid/axis.h"

namespace strielad {

using NodeId = std::uint32_t;

// Inclusive index box.
struct IndexBox {
  std::array<std::size_t, 3> lo{}, hi{};
  std::size_t extent(int axis) const { return hi[axis] - lo[axis] + 1; }
  std::size_t count() const { return extent(0) * extent(1) * extent(2); }
  friend bool operator==(const IndexBox&, const IndexBox&) = default;
};

struct NodeKey {
  std::uint32_t level = 0;
  std::array<std::uint32_t, 3> index{};  // node index along x, y, z within the level
  friend bool operator==(const NodeKey&, const NodeKey&) = default;
};

struct LevelShape {
  std::array<std::size_t, 3> samples{};  // samples of this level's grid per axis
  std::array<std::size_t, 3> stride{};   // level-0 samples per step of this level
  std::array<std::size_t, 3> nodes{};    // nodes per axis
  NodeId first_node = 0;
  std::size_t node_count() const { return nodes[0] * nodes[1] * nodes[2]; }
};

class OctreeLayout {
 public:
  // Throws kInvalidArgument when a dimension is zero, brick < 2, or the node count
  // does not fit a 32-bit node id.
  OctreeLayout(Dims3 grid, std::uint32_t brick);

  Dims3 grid() const { return grid_; }
  std::uint32_t brick() const { return brick_; }
  std::size_t level_count() const { return levels_.size(); }
  const LevelShape& level(std::size_t l) const { return levels_.at(l); }
  std::size_t node_count() const { return node_count_; }
  NodeId root() const { return static_cast<NodeId>(node_count_ - 1); }

  NodeId id(const NodeKey& key) const;
  NodeKey key(NodeId id) const;  // throws kNotFound for an id outside the octree
  bool contains(NodeId id) const { return id < node_count_; }

  // Samples of the node's brick, as an inclusive box in its level's grid.
  IndexBox level_box(const NodeKey& key) const;
  // The same samples as level-0 indices (inclusive; used for exact value ranges).
  IndexBox fine_box(const NodeKey& key) const;
  // Level-0 samples the node owns: the boxes of one level partition the grid, so per-node
  // counts add up exactly. Half-open, returned as inclusive box of owned samples.
  IndexBox owned_fine_box(const NodeKey& key) const;
  // Level-0 index of sample c of level l along axis a.
  std::size_t fine_index(std::size_t l, int axis, std::size_t c) const;

  std::vector<NodeId> children(NodeId id) const;  // empty for level-0 nodes
  std::optional<NodeId> parent(NodeId id) const;  // empty for the root

  // Stored samples of all levels above 0 relative to level 0 (the octree overhead).
  double overhead_fraction() const;

 private:
  Dims3 grid_;
  std::uint32_t brick_;
  std::vector<LevelShape> levels_;
  std::size_t node_count_ = 0;
};

}  // namespace strielad
