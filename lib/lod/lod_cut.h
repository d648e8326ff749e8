// SPDX-License-Identifier: Apache-2.0
// The view-dependent level-of-detail cut through the brick octree: the set of nodes a
// client shows for a camera, and the per-frame differences it sends the server.
//
// The cut is computed top-down from the root:
// - a node whose world box lies wholly outside the view frustum is dropped, with all
//   its descendants (lod/frustum.h; the test is conservative, so a node that may be
//   visible is kept);
// - a visible node above level 0 whose bounding sphere covers more than
//   split_solid_angle_sr seen from the eye (lod/geometry.h, sphere_solid_angle; 4 pi
//   when the eye is inside the sphere) is split: it leaves the cut and its visible
//   children enter it;
// - with hysteresis h, a node that was split in the previous update stays split while
//   it covers more than split_solid_angle_sr * (1 - h), so a camera hovering at the
//   threshold does not make nodes flicker between one parent and eight children;
// - splits are done in order of priority, the distance from the eye to the node's box
//   centre (smaller = sooner): when a split would take the cut beyond max_nodes it is
//   refused, so the nodes nearest the eye get their detail first. (A later, farther
//   split that still fits, e.g. of a node with fewer visible children, is done.)
// A node not split stays in the cut. The cut never holds a node together with one of
// its ancestors, and the visible level-0 nodes under its nodes are each under exactly
// one of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lod/camera.h"
#include "lod/frustum.h"
#include "lod/geometry.h"
#include "octree/octree_layout.h"

namespace strielad::lod {

// A node is split while its bounding sphere covers more than 0.01 sr, a cone 6.5 degrees
// across: 155 pixels of a 1080-pixel-high 45 degree view. A brick of B = 20..24 cells
// has a bounding sphere about sqrt(3) B = 35..42 cells across, so a node is split while
// its cells are wider than about 4 pixels, and its children show cells about 2 pixels
// wide: the cut keeps cells between about 2 and 4 pixels, where finer detail is not
// visible and coarser shows facets. On the paper's grid (1429 x 1556 x 150, brick 20)
// the whole-domain view at the start of the default fly-in is a cut of about 1,300
// nodes; closer views reach max_nodes.
inline constexpr double kDefaultSplitSolidAngleSr = 0.01;
// A hard cap on the cut: 4096 nodes of 21^3..25^3 samples are about 40 to 64 million
// samples, an eighth to a fifth of the paper's grid at full resolution: the order of
// what a client keeps as meshes in GPU memory and a server extracts for one view.
inline constexpr std::size_t kDefaultMaxNodes = 4096;
// A node's priority is re-sent when its distance changed by more than 10%: the server
// orders work by priority, and a 10% change barely moves a node among its neighbours.
inline constexpr double kDefaultReprioritizeRelative = 0.1;
// Collapse at 75% of the split threshold: a node stays split until its solid angle has
// dropped by a quarter (the camera backed off by about 15% of its distance).
inline constexpr double kDefaultHysteresis = 0.25;

struct LodOptions {
  double split_solid_angle_sr = kDefaultSplitSolidAngleSr;  // finite, >= 0
  std::size_t max_nodes = kDefaultMaxNodes;                 // >= 1
  double reprioritize_relative = kDefaultReprioritizeRelative;  // finite, >= 0
  double hysteresis = kDefaultHysteresis;                   // in [0, 1); 0 = none
};

// \error kInvalidArgument naming the option that is out of range.
void validate_lod_options(const LodOptions& options);

struct PrioritizedNode {
  NodeId node = 0;
  float priority = 0;  // distance from the eye to the node's box centre, km
  friend bool operator==(const PrioritizedNode&, const PrioritizedNode&) = default;
};

// What changed since the previous update (what the client sends the server).
struct CutDiff {
  std::vector<PrioritizedNode> added;          // entered the cut; nearest first
  std::vector<NodeId> removed;                 // left the cut; ascending id
  std::vector<PrioritizedNode> reprioritized;  // stayed, priority re-sent; nearest first
  bool empty() const { return added.empty() && removed.empty() && reprioritized.empty(); }
};

// Counters of the last update (for the benchmark and the viewer's overlay).
struct LodStats {
  std::size_t visited = 0;  // visible nodes whose distance and solid angle were evaluated
  std::size_t culled = 0;   // children dropped by the frustum test (and the root)
  std::size_t split = 0;    // nodes split
  bool capped = false;      // a split was refused by max_nodes
};

class LodCut {
 public:
  // `boxes` holds the world box of every node of `layout`, indexed by NodeId
  // (node_world_boxes). The layout is not referenced after construction.
  // \error kInvalidArgument when boxes.size() != layout.node_count() or the options
  // are invalid (validate_lod_options).
  LodCut(const OctreeLayout& layout, std::vector<WorldBox> boxes, LodOptions options = {});

  // Computes the cut for `camera` and returns its difference to the previous one:
  // added nodes with their priority, removed nodes, and nodes that stayed whose priority
  // moved by more than reprioritize_relative of the priority last sent for them (the
  // sent priority is then updated). A node is never in more than one list.
  // \error kInvalidArgument for an invalid camera (validate_camera); the cut is unchanged.
  CutDiff update(const Camera& camera);

  // The current cut with the priorities of the last update, in the order the update
  // reached its nodes (deterministic but not sorted, to keep an update cheap; the lists
  // of a CutDiff are sorted).
  const std::vector<PrioritizedNode>& nodes() const { return cut_; }

  // Every node of the current cut as added, with its current priority, which becomes
  // the priority sent (for a server that forgot the client's cut: a new generation).
  CutDiff full();

  // Forgets the cut (and the hysteresis state): nodes() is empty and the next update
  // lists every node of its cut as added.
  void reset();

  const LodOptions& options() const { return options_; }
  const LodStats& stats() const { return stats_; }
  // The world box of a node. \error kNotFound for a node outside the octree.
  const WorldBox& box(NodeId node) const;

 private:
  void compute_cut(const Camera& camera);

  LodOptions options_;
  std::vector<WorldBox> boxes_;
  std::vector<Vec3> centers_;               // per node: box centre
  std::vector<double> radii_;               // per node: bounding sphere radius
  std::vector<std::uint32_t> child_begin_;  // children of n: child_ids_[begin[n]..begin[n+1])
  std::vector<NodeId> child_ids_;
  NodeId root_ = 0;

  std::vector<PrioritizedNode> cut_;      // current cut
  std::vector<PrioritizedNode> next_;     // scratch: the cut being computed
  std::vector<std::uint8_t> in_cut_;      // per node: in cut_
  std::vector<float> sent_;               // per node in cut_: the priority last sent
  std::vector<std::uint32_t> mark_;       // per node: == epoch_ when in next_
  std::uint32_t epoch_ = 0;
  std::vector<std::uint8_t> was_split_;   // per node: split in the last update
  std::vector<NodeId> split_nodes_;       // the nodes flagged in was_split_
  std::vector<NodeId> next_split_;        // scratch
  std::vector<std::uint64_t> heap_;       // scratch: nodes to split, packed (priority, id)
  LodStats stats_;
};

}  // namespace strielad::lod
