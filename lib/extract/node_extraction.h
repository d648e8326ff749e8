// SPDX-License-Identifier: Apache-2.0
// Extraction of a resolved scene's sub-volumes in one octree node of a store, leaving
// out what the scene does not need: a sub-volume whose value range or domain box
// excludes the node is skipped from the index alone (no brick read, no decompression),
// a node wholly inside every limit needs no limit bricks, and only the scene's
// variables are ever read (formats/scene.md, "Leaving out").
#pragma once

#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

#include "extract/extract_request.h"
#include "extract/mesh.h"
#include "extract/thread_scratch.h"
#include "format/step_file_format.h"
#include "octree/octree_layout.h"
#include "scene/scene.h"

namespace strielad {

class Store;
class BrickCache;

enum class NodeOutcome : std::uint8_t {
  kMesh = 0,              // extracted, the mesh has triangles
  kEmpty = 1,             // extracted (bricks read), nothing inside
  kSkippedValueRange = 2, // a limit's range misses the node's exact value range
  kSkippedDomain = 3,     // the domain box misses the node
  kSkippedNoData = 4,     // a limit variable has no valid sample in the node
};

std::string_view node_outcome_name(NodeOutcome outcome);

// One sub-volume's outcome in a node. Also the protocol's form of it (protocol/messages.h,
// NodeResult), which carries every field but `stats`.
struct SubVolumeResult {
  std::uint32_t subvolume_id = 0;
  NodeOutcome outcome = NodeOutcome::kEmpty;
  std::string reason;  // for skips: which variable or axis, and the ranges
  Mesh mesh;
  ExtractStats stats;
  friend bool operator==(const SubVolumeResult&, const SubVolumeResult&) = default;
};

// One slice's outcome in a node (formats/scene.md, "Slices"): kMesh with a mesh of face
// kind kSlice and one attribute (the colouring variable), kEmpty, or a skip decided
// from the node's box and index alone: kSkippedDomain (the plane misses the node, or
// lies on its upper face that the neighbouring node draws), kSkippedValueRange (the
// level's value is outside the node's range of its variable), kSkippedNoData. Also the
// protocol's form of it (protocol/messages.h, NodeResult, version 2).
struct SliceResult {
  std::uint32_t slice_id = 0;
  NodeOutcome outcome = NodeOutcome::kEmpty;
  std::string reason;
  Mesh mesh;
  friend bool operator==(const SliceResult&, const SliceResult&) = default;
};

// How sub-volume meshes are built, for output frames (ExtractRequest's fields).
struct NodeMeshOptions {
  bool merge_face_squares = true;  // false for frames that are not affine on the grid
  bool axis_normals = true;        // false where the frame replaces every normal
};

struct NodeExtraction {
  NodeId node = 0;
  std::vector<SubVolumeResult> results;  // one per scene sub-volume, in scene order
  std::vector<SliceResult> slices;       // one per scene slice, in scene order
  std::uint32_t bricks_used = 0;         // bricks fetched (cache or disk) for this node
};

// Fields are evaluated in float32 (the kernel's precision): float64 variables are rounded
// to float, and values beyond +-3.4e38 are clamped to the float range, so they stay valid
// and finite (a limit bound beyond that range selects none of them).
// Throws strielad::Error (naming the file, variable and node) when a needed brick is
// damaged; other nodes are unaffected. `stop` is polled before every brick read and
// every sub-volume and slice: once stop is requested the call throws kCancelled. Slices
// (lib/extract/slice_extraction.h) share the node's bricks with the sub-volumes: each
// needed brick is fetched once.
// `mesh_options`: as the ExtractRequest fields of the same names. Works in `scratch` (one
// extraction at a time).
NodeExtraction extract_node(const Store& store, BrickCache* cache, const ResolvedScene& scene,
                            std::uint32_t step, NodeId node, ExtractScratch& scratch,
                            std::stop_token stop = {}, NodeMeshOptions mesh_options = {});

// The same in this thread's scratch (this_thread_scratch()).
NodeExtraction extract_node(const Store& store, BrickCache* cache, const ResolvedScene& scene,
                            std::uint32_t step, NodeId node, std::stop_token stop = {},
                            NodeMeshOptions mesh_options = {});

// The variables whose bricks extract_node would read for this node, decided from the
// index alone (sorted, distinct; empty when every sub-volume is skipped). Prefetching
// warms exactly these.
std::vector<std::uint32_t> node_brick_variables(const Store& store, const ResolvedScene& scene,
                                                std::uint32_t step, NodeId node);

// Whether the node's index entry alone proves that `limit` holds nowhere in the node:
// no valid sample, or the exact value range misses [min, max]. The one rule every
// consumer of a scene skips by (extraction, .vdb export).
bool limit_excludes_node(const format::IndexEntry& entry, const ResolvedLimit& limit);

// The node's sample coordinates on the manifest's axes (no brick is read).
struct NodeGeometry {
  std::array<std::vector<double>, 3> coords;
  std::array<std::vector<std::size_t>, 3> fine;  // the samples' level-0 indices
  std::array<bool, 6> grid_edge{};  // as NodeSamples::grid_edge
};
NodeGeometry node_geometry(const Store& store, NodeId node);

}  // namespace strielad
