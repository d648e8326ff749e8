// SPDX-License-Identifier: Apache-2.0
// The library's only translation unit instantiating tools::volumeToMesh.
#include "peers/openvdb_volume_to_mesh.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <mutex>

#include "core/error.h"
#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "peers/peer_input.h"

namespace strielad::peers {
namespace {

constexpr std::string_view kWho = "OpenVDB volumeToMesh peer";

// openvdb::initialize() registers grid types; like lib/vdb, once per process.
void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

PeerResult volume_to_mesh(const NodeSamples& samples, std::size_t field, double iso,
                          double adaptivity) {
  PeerResult result;
  const auto dims = samples.dims();
  result.cells = std::uint64_t(dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
  const auto& values = samples.fields[field];
  const float background = static_cast<float>(far_below(iso));
  // The samples plus one layer replicating the outermost samples on every side: the
  // cells beyond the node then hold no crossing on edges leaving the node, so nothing is
  // meshed across the node's boundary (the grid background never meets the samples).
  const std::array<std::size_t, 3> padded{dims[0] + 2, dims[1] + 2, dims[2] + 2};
  std::vector<float> dense_values(padded[0] * padded[1] * padded[2]);
  auto clamp_index = [](std::size_t i, std::size_t n) {
    return i == 0 ? std::size_t(0) : std::min(i - 1, n - 1);
  };
  for (std::size_t k = 0, out = 0; k < padded[2]; ++k) {
    const std::size_t sk = clamp_index(k, dims[2]);
    for (std::size_t j = 0; j < padded[1]; ++j) {
      const std::size_t row = (sk * dims[1] + clamp_index(j, dims[1])) * dims[0];
      for (std::size_t i = 0; i < padded[0]; ++i, ++out) {
        dense_values[out] = sanitize_sample(values[row + clamp_index(i, dims[0])], background);
      }
    }
  }

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  const auto start = std::chrono::steady_clock::now();
  auto grid = openvdb::FloatGrid::create(background);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);  // inside = below iso, normals outward
  // Voxel (i+1, j+1, k+1) = sample (i, j, k): the padding at index -1 would fall into
  // other root-level nodes (OpenVDB's top nodes span 4096 voxels from 0), and allocating
  // 8 of them instead of 1 costs more than the meshing.
  const openvdb::CoordBBox bbox(openvdb::Coord(0, 0, 0),
                                openvdb::Coord(int(dims[0]) + 1, int(dims[1]) + 1, int(dims[2]) + 1));
  // LayoutXYZ: x varies fastest, as in NodeSamples.
  openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(bbox, dense_values.data());
  openvdb::tools::copyFromDense(dense, *grid, 0.0f);
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, iso, adaptivity);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Keep polygons whose vertices all lie within the node's lattice (index space). Dual
  // vertices of the cells just outside it lie half a cell out.
  constexpr float kEps = 1e-3f;
  std::vector<std::uint32_t> remap(points.size(), UINT32_MAX);
  std::vector<bool> inside(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    bool in = true;
    for (int a = 0; a < 3; ++a) {
      points[p][a] -= 1.0f;  // back to sample indices
      in = in && points[p][a] >= -kEps && points[p][a] <= float(dims[a] - 1) + kEps;
    }
    inside[p] = in;
  }
  Mesh& mesh = result.mesh;
  auto vertex = [&](std::uint32_t p) {
    if (remap[p] == UINT32_MAX) {
      remap[p] = std::uint32_t(mesh.positions.size());
      // Clamped: a vertex on the lattice's face may be a rounding error outside it.
      std::array<double, 3> x{};
      for (int a = 0; a < 3; ++a) x[a] = std::clamp(double(points[p][a]), 0.0, double(dims[a] - 1));
      mesh.positions.push_back(x);
    }
    return remap[p];
  };
  // OpenVDB 10's polygons are clockwise seen from outside (larger values): reversed.
  auto add_triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (!inside[a] || !inside[b] || !inside[c]) return;
    mesh.triangles.push_back({vertex(a), vertex(c), vertex(b)});
  };
  for (const auto& q : quads) {
    if (!inside[q[0]] || !inside[q[1]] || !inside[q[2]] || !inside[q[3]]) continue;
    add_triangle(q[0], q[1], q[2]);
    add_triangle(q[0], q[2], q[3]);
  }
  for (const auto& t : triangles) add_triangle(t[0], t[1], t[2]);
  mesh.face_kinds.assign(mesh.triangles.size(), FaceKind::kLimit);
  map_index_mesh_to_axes(mesh, samples);
  compute_vertex_normals(mesh);
  result.divergence_volume = enclosed_volume(mesh);
  const EdgeCounts edges = count_open_edges(mesh);
  result.boundary_edges = edges.boundary;
  result.non_manifold_edges = edges.non_manifold;
  result.closed = !mesh.empty() && edges.closed();
  return result;
}

}  // namespace

PeerResult run_openvdb_volume_to_mesh(const NodeSamples& samples, std::size_t field, double iso,
                                      const VolumeToMeshOptions& options) {
  check_node_samples(samples, kWho);
  check_field_index(samples, field, kWho);
  if (!std::isfinite(iso)) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: iso value {} is not finite", kWho, iso);
  }
  if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0)) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: adaptivity {} is outside [0, 1]", kWho,
                     options.adaptivity);
  }
  initialize_openvdb();
  auto run = [&] { return volume_to_mesh(samples, field, iso, options.adaptivity); };
  if (options.threads == 0) return run();
  tbb::task_arena arena(static_cast<int>(options.threads), options.threads == 1 ? 1 : 0);
  return arena.execute(run);
}

}  // namespace strielad::peers
