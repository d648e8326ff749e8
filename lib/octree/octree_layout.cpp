// SPDX-License-Identifier: Apache-2.0
#include "octree/octree_layout.h"

#include <algorithm>
#include <limits>

#include "core/error.h"

namespace strielad {
namespace {

std::size_t nodes_along(std::size_t samples, std::uint32_t brick) {
  const std::size_t cells = samples - 1;
  return cells == 0 ? 1 : (cells + brick - 1) / brick;
}

}  // namespace

OctreeLayout::OctreeLayout(Dims3 grid, std::uint32_t brick) : grid_(grid), brick_(brick) {
  if (grid.x == 0 || grid.y == 0 || grid.z == 0) {
    throw make_error(ErrorCode::kInvalidArgument, "grid dimensions {}x{}x{} must all be positive",
                     grid.x, grid.y, grid.z);
  }
  if (brick < 2 || brick > 1024) {
    throw make_error(ErrorCode::kInvalidArgument, "brick size {} must be between 2 and 1024", brick);
  }
  constexpr std::size_t kMaxAxis = std::size_t{1} << 31;
  if (grid.x > kMaxAxis || grid.y > kMaxAxis || grid.z > kMaxAxis) {
    throw make_error(ErrorCode::kInvalidArgument, "grid dimension larger than 2^31 samples");
  }
  LevelShape shape;
  shape.samples = {grid.x, grid.y, grid.z};
  shape.stride = {1, 1, 1};
  for (;;) {
    for (int a = 0; a < 3; ++a) shape.nodes[a] = nodes_along(shape.samples[a], brick);
    shape.first_node = static_cast<NodeId>(node_count_);
    const std::size_t count = shape.node_count();
    if (count > std::numeric_limits<NodeId>::max() - node_count_) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "grid {}x{}x{} with brick {} needs more than 2^32 octree nodes; use a "
                       "larger brick",
                       grid.x, grid.y, grid.z, brick);
    }
    node_count_ += count;
    levels_.push_back(shape);
    if (count == 1) break;
    LevelShape next = shape;
    for (int a = 0; a < 3; ++a) {
      if (shape.nodes[a] > 1) {
        next.samples[a] = shape.samples[a] / 2 + 1;  // ceil((n - 1) / 2) + 1
        next.stride[a] = shape.stride[a] * 2;
      }
    }
    shape = next;
  }
}

NodeId OctreeLayout::id(const NodeKey& key) const {
  const LevelShape& s = level(key.level);
  for (int a = 0; a < 3; ++a) {
    if (key.index[a] >= s.nodes[a]) {
      throw make_error(ErrorCode::kNotFound, "node index {} on axis {} outside level {} ({} nodes)",
                       key.index[a], a, key.level, s.nodes[a]);
    }
  }
  return static_cast<NodeId>(s.first_node +
                             (key.index[2] * s.nodes[1] + key.index[1]) * s.nodes[0] +
                             key.index[0]);
}

NodeKey OctreeLayout::key(NodeId id) const {
  if (!contains(id)) {
    throw make_error(ErrorCode::kNotFound, "node {} does not exist (the octree has {} nodes)", id,
                     node_count_);
  }
  std::uint32_t l = 0;
  while (l + 1 < levels_.size() && id >= levels_[l + 1].first_node) ++l;
  const LevelShape& s = levels_[l];
  std::size_t local = id - s.first_node;
  NodeKey key;
  key.level = l;
  key.index[0] = static_cast<std::uint32_t>(local % s.nodes[0]);
  local /= s.nodes[0];
  key.index[1] = static_cast<std::uint32_t>(local % s.nodes[1]);
  key.index[2] = static_cast<std::uint32_t>(local / s.nodes[1]);
  return key;
}

IndexBox OctreeLayout::level_box(const NodeKey& key) const {
  const LevelShape& s = level(key.level);
  IndexBox box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::size_t{key.index[a]} * brick_;
    box.hi[a] = std::min(box.lo[a] + brick_, s.samples[a] - 1);
  }
  return box;
}

std::size_t OctreeLayout::fine_index(std::size_t l, int axis, std::size_t c) const {
  const std::size_t n = (axis == 0 ? grid_.x : axis == 1 ? grid_.y : grid_.z);
  return std::min(c * level(l).stride[axis], n - 1);
}

IndexBox OctreeLayout::fine_box(const NodeKey& key) const {
  IndexBox box = level_box(key);
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = fine_index(key.level, a, box.lo[a]);
    box.hi[a] = fine_index(key.level, a, box.hi[a]);
  }
  return box;
}

IndexBox OctreeLayout::owned_fine_box(const NodeKey& key) const {
  const LevelShape& s = level(key.level);
  IndexBox box;
  for (int a = 0; a < 3; ++a) {
    const std::size_t n = (a == 0 ? grid_.x : a == 1 ? grid_.y : grid_.z);
    box.lo[a] = fine_index(key.level, a, std::size_t{key.index[a]} * brick_);
    const bool last = key.index[a] + 1 == s.nodes[a];
    box.hi[a] = last ? n - 1
                     : fine_index(key.level, a, (std::size_t{key.index[a]} + 1) * brick_) - 1;
  }
  return box;
}

std::vector<NodeId> OctreeLayout::children(NodeId id) const {
  const NodeKey k = key(id);
  if (k.level == 0) return {};
  const LevelShape& parent = levels_[k.level];
  const LevelShape& child = levels_[k.level - 1];
  std::array<std::uint32_t, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    const bool halved = child.stride[a] != parent.stride[a];
    lo[a] = halved ? k.index[a] * 2 : k.index[a];
    hi[a] = halved ? std::min<std::uint32_t>(lo[a] + 1, static_cast<std::uint32_t>(child.nodes[a] - 1))
                   : lo[a];
  }
  std::vector<NodeId> out;
  for (std::uint32_t z = lo[2]; z <= hi[2]; ++z)
    for (std::uint32_t y = lo[1]; y <= hi[1]; ++y)
      for (std::uint32_t x = lo[0]; x <= hi[0]; ++x)
        out.push_back(this->id(NodeKey{k.level - 1, {x, y, z}}));
  return out;
}

std::optional<NodeId> OctreeLayout::parent(NodeId id) const {
  const NodeKey k = key(id);
  if (k.level + 1 >= levels_.size()) return std::nullopt;
  const LevelShape& child = levels_[k.level];
  const LevelShape& parent = levels_[k.level + 1];
  NodeKey p{k.level + 1, {}};
  for (int a = 0; a < 3; ++a) {
    const bool halved = child.stride[a] != parent.stride[a];
    p.index[a] = halved ? k.index[a] / 2 : k.index[a];
  }
  return this->id(p);
}

double OctreeLayout::overhead_fraction() const {
  auto stored = [&](std::size_t l) {
    double total = 0;
    const LevelShape& s = levels_[l];
    for (NodeId n = s.first_node; n < s.first_node + s.node_count(); ++n) {
      total += static_cast<double>(level_box(key(n)).count());
    }
    return total;
  };
  const double base = stored(0);
  double inner = 0;
  for (std::size_t l = 1; l < levels_.size(); ++l) inner += stored(l);
  return inner / base;
}

}  // namespace strielad
