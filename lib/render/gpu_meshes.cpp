// SPDX-License-Identifier: Apache-2.0
#include "render/gpu_meshes.h"

#include <algorithm>
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
      bytes_ -= gpu_bytes(it->second);
      triangles_ -= static_cast<std::size_t>(it->second.index_count) / 3;
      slice_triangles_ -= static_cast<std::size_t>(it->second.slice_index_count) / 3;
      it = meshes_.erase(it);
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
  auto& slot = meshes_[node];
  bytes_ -= gpu_bytes(slot);
  triangles_ -= static_cast<std::size_t>(slot.index_count) / 3;
  slice_triangles_ -= static_cast<std::size_t>(slot.slice_index_count) / 3;
  bytes_ += gpu_bytes(mesh);
  triangles_ += static_cast<std::size_t>(mesh.index_count) / 3;
  slice_triangles_ += static_cast<std::size_t>(mesh.slice_index_count) / 3;
  slot = std::move(mesh);
}

}  // namespace strielad::render
