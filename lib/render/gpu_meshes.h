// SPDX-License-Identifier: Apache-2.0
// The GPU copies of the meshes a view shows: one vertex array, vertex buffer and index
// buffer per node (and a second set for the node's slices, when it has any), kept in step with view::ProgressiveMeshes (uploaded when a node's
// mesh changed, freed when the node left the cut or shows nothing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "render/gl_handles.h"
#include "view/progressive_meshes.h"

namespace strielad::render {

struct GpuMesh {
  std::shared_ptr<const view::NodeGeometry> source;  // what was uploaded
  GlVertexArray vertex_array;
  GlBuffer vertices;
  GlBuffer indices;
  GLsizei index_count = 0;
  std::array<float, 3> center{};  // of the vertices' bounding box (world km, exaggeration 1)
  // Slices (view::kSliceVertexFloats per vertex; attribute locations 0 position,
  // 1 normal, 2 value, 3 slot); slice_index_count 0 and no objects when none.
  GlVertexArray slice_vertex_array;
  GlBuffer slice_vertices;
  GlBuffer slice_indices;
  GLsizei slice_index_count = 0;
};

class GpuMeshes {
 public:
  // Uploads changed meshes and frees those no longer shown. At most `max_upload_bytes`
  // are uploaded per call (at least one mesh), so a burst of results spreads over
  // frames; until a node's new mesh is uploaded its previous one stays drawn.
  // Returns the bytes uploaded.
  std::size_t sync(const view::ProgressiveMeshes& meshes, std::size_t max_upload_bytes);
  void clear();

  const std::unordered_map<NodeId, GpuMesh>& meshes() const { return meshes_; }
  std::size_t bytes() const { return bytes_; }
  std::size_t triangles() const { return triangles_; }
  std::size_t slice_triangles() const { return slice_triangles_; }
  // Meshes whose upload was deferred by the byte budget in the last sync.
  std::size_t deferred() const { return deferred_; }
  // Increases whenever a mesh is uploaded or freed (what is drawn changed).
  std::uint64_t shown_version() const { return shown_version_; }

  // The level-of-detail cross-fade (render/lod_fade.h) keeps the set shown before a
  // change alive next to the new one, sharing the nodes that did not change. While
  // retaining, a mesh that sync frees or replaces is set aside (the first one of each
  // node: the mesh shown when retaining began) instead of being destroyed, and nodes
  // uploaded since are remembered; exchange_retained() swaps between the two sets
  // (twice: back), moving handles only, no GPU work.
  void begin_retaining();
  // Frees the meshes set aside; meshes() stays what it is.
  void end_retaining();
  bool retaining() const { return retaining_; }
  // True when the retained set differs from meshes().
  bool retained_differs() const { return !retired_.empty() || !fresh_.empty(); }
  void exchange_retained();

 private:
  void upload(NodeId node, std::shared_ptr<const view::NodeGeometry> geometry);
  // Frees (or sets aside, while retaining) the mesh of `node`.
  void drop(std::unordered_map<NodeId, GpuMesh>::iterator it);
  void count(const GpuMesh& mesh, int sign);

  std::unordered_map<NodeId, GpuMesh> meshes_;
  std::uint64_t synced_version_ = ~0ull;
  std::size_t bytes_ = 0;
  std::size_t triangles_ = 0;
  std::size_t slice_triangles_ = 0;
  std::size_t deferred_ = 0;
  std::uint64_t shown_version_ = 0;
  bool retaining_ = false;
  std::unordered_map<NodeId, GpuMesh> retired_;  // shown when retaining began, since replaced
  std::unordered_set<NodeId> fresh_;             // uploaded since retaining began
};

}  // namespace strielad::render
