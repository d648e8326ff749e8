// SPDX-License-Identifier: Apache-2.0
#include "render/gpu_meshes.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <vector>

namespace strielad::render {
namespace {

std::size_t geometry_bytes(const view::NodeGeometry& g) {
  return (g.vertices.size() + g.slice_vertices.size()) * sizeof(float) +
         (g.indices.size() + g.slice_indices.size()) * sizeof(std::uint32_t);
}

// glNamedBufferStorage refuses size 0: a node with only slices gets 4-byte buffers.
void storage(const GlBuffer& buffer, std::size_t bytes, const void* data) {
  glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 4)),
                       bytes == 0 ? nullptr : data, 0);
}

std::size_t gpu_bytes(const GpuMesh& m) { return m.source ? geometry_bytes(*m.source) : 0; }

// Vertex attribute `location` of `vao`: `size` floats at float `offset` of binding 0.
void float_attribute(GLuint vao, GLuint location, GLint size, std::size_t offset) {
  glEnableVertexArrayAttrib(vao, location);
  glVertexArrayAttribFormat(vao, location, size, GL_FLOAT, GL_FALSE,
                            static_cast<GLuint>(offset * sizeof(float)));
  glVertexArrayAttribBinding(vao, location, 0);
}

}  // namespace

std::size_t GpuMeshes::sync(const view::ProgressiveMeshes& meshes, std::size_t max_upload_bytes) {
  if (meshes.version() == synced_version_ && deferred_ == 0) return 0;
  // Free what is no longer shown.
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    const auto entry = meshes.entries().find(it->first);
    if (entry == meshes.entries().end() || !entry->second.mesh) {
      const auto next = std::next(it);
      drop(it);
      it = next;
    } else {
      ++it;
    }
  }
  std::size_t uploaded = 0;
  deferred_ = 0;
  for (const auto& [node, entry] : meshes.entries()) {
    if (!entry.mesh) continue;
    const auto it = meshes_.find(node);
    if (it != meshes_.end() && it->second.source == entry.mesh) continue;
    if (uploaded > 0 && uploaded + geometry_bytes(*entry.mesh) > max_upload_bytes) {
      ++deferred_;
      continue;
    }
    uploaded += geometry_bytes(*entry.mesh);
    upload(node, entry.mesh);
  }
  synced_version_ = meshes.version();
  return uploaded;
}

void GpuMeshes::upload(NodeId node, std::shared_ptr<const view::NodeGeometry> geometry) {
  GpuMesh mesh;
  mesh.vertex_array = make_vertex_array();
  mesh.vertices = make_buffer();
  mesh.indices = make_buffer();
  const auto& g = *geometry;
  storage(mesh.vertices, g.vertices.size() * sizeof(float), g.vertices.data());
  storage(mesh.indices, g.indices.size() * sizeof(std::uint32_t), g.indices.data());
  const GLuint vao = mesh.vertex_array.get();
  glVertexArrayVertexBuffer(vao, 0, mesh.vertices.get(), 0,
                            static_cast<GLsizei>(view::kVertexFloats * sizeof(float)));
  glVertexArrayElementBuffer(vao, mesh.indices.get());
  float_attribute(vao, 0, 3, view::kVertexPosition);
  float_attribute(vao, 1, 3, view::kVertexNormal);
  float_attribute(vao, 2, 1, view::kVertexSlot);
  float_attribute(vao, 3, 4, view::kVertexAttributes);
  float_attribute(vao, 4, 4, view::kVertexAttributes + 4);
  mesh.index_count = static_cast<GLsizei>(g.indices.size());
  std::array<float, 3> lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                          std::numeric_limits<float>::max()};
  std::array<float, 3> hi{-lo[0], -lo[1], -lo[2]};
  for (std::size_t v = 0; v < g.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], g.vertices[v * view::kVertexFloats + a]);
      hi[a] = std::max(hi[a], g.vertices[v * view::kVertexFloats + a]);
    }
  }
  for (std::size_t v = 0; v < g.slice_vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], g.slice_vertices[v * view::kSliceVertexFloats + a]);
      hi[a] = std::max(hi[a], g.slice_vertices[v * view::kSliceVertexFloats + a]);
    }
  }
  for (int a = 0; a < 3; ++a) mesh.center[a] = 0.5f * (lo[a] + hi[a]);
  if (!g.slice_indices.empty()) {
    mesh.slice_vertex_array = make_vertex_array();
    mesh.slice_vertices = make_buffer();
    mesh.slice_indices = make_buffer();
    storage(mesh.slice_vertices, g.slice_vertices.size() * sizeof(float), g.slice_vertices.data());
    storage(mesh.slice_indices, g.slice_indices.size() * sizeof(std::uint32_t),
            g.slice_indices.data());
    const GLuint svao = mesh.slice_vertex_array.get();
    glVertexArrayVertexBuffer(svao, 0, mesh.slice_vertices.get(), 0,
                              static_cast<GLsizei>(view::kSliceVertexFloats * sizeof(float)));
    glVertexArrayElementBuffer(svao, mesh.slice_indices.get());
    float_attribute(svao, 0, 3, view::kSliceVertexPosition);
    float_attribute(svao, 1, 3, view::kSliceVertexNormal);
    float_attribute(svao, 2, 1, view::kSliceVertexValue);
    float_attribute(svao, 3, 1, view::kSliceVertexSlot);
    mesh.slice_index_count = static_cast<GLsizei>(g.slice_indices.size());
  }
  mesh.source = std::move(geometry);
  if (const auto it = meshes_.find(node); it != meshes_.end()) drop(it);
  count(mesh, +1);
  meshes_.emplace(node, std::move(mesh));
  if (retaining_) fresh_.insert(node);
  ++shown_version_;
}

void GpuMeshes::clear() {
  end_retaining();
  meshes_.clear();
  bytes_ = triangles_ = slice_triangles_ = deferred_ = 0;
  synced_version_ = ~0ull;
  ++shown_version_;
}

void GpuMeshes::count(const GpuMesh& mesh, int sign) {
  const auto apply = [sign](std::size_t& total, std::size_t n) {
    total = sign > 0 ? total + n : total - n;
  };
  apply(bytes_, gpu_bytes(mesh));
  apply(triangles_, static_cast<std::size_t>(mesh.index_count) / 3);
  apply(slice_triangles_, static_cast<std::size_t>(mesh.slice_index_count) / 3);
}

void GpuMeshes::drop(std::unordered_map<NodeId, GpuMesh>::iterator it) {
  count(it->second, -1);
  ++shown_version_;
  const NodeId node = it->first;
  if (retaining_ && !fresh_.contains(node) && !retired_.contains(node)) {
    retired_.insert(meshes_.extract(it));
    return;
  }
  fresh_.erase(node);
  meshes_.erase(it);
}

void GpuMeshes::begin_retaining() {
  end_retaining();
  retaining_ = true;
}

void GpuMeshes::end_retaining() {
  retired_.clear();
  fresh_.clear();
  retaining_ = false;
}

void GpuMeshes::exchange_retained() {
  // meshes() - fresh + retired <-> meshes(); the fresh meshes become the ones set aside,
  // and the retired nodes the ones that are new relative to them.
  std::unordered_map<NodeId, GpuMesh> aside;
  for (const NodeId node : fresh_) {
    auto handle = meshes_.extract(node);
    count(handle.mapped(), -1);
    aside.insert(std::move(handle));
  }
  std::unordered_set<NodeId> fresh;
  while (!retired_.empty()) {
    auto handle = retired_.extract(retired_.begin());
    fresh.insert(handle.key());
    count(handle.mapped(), +1);
    meshes_.insert(std::move(handle));
  }
  retired_ = std::move(aside);
  fresh_ = std::move(fresh);
  ++shown_version_;
}

}  // namespace strielad::render
