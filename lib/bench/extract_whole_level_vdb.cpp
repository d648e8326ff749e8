// SPDX-License-Identifier: Apache-2.0
// run_whole_level_vdb (extract_levels.h): the only bench translation unit with OpenVDB
// (its volumeToMesh templates cost most of a minute to compile).
#include <openvdb/tools/VolumeToMesh.h>
#include <spdlog/spdlog.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "bench/extract_levels.h"
#include "bench/latency_stats.h"
#include "bench/stopwatch.h"
#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "store/store.h"
#include "vdb/level_grid_openvdb.h"

namespace strielad::bench {

std::optional<WholeLevelVdb> run_whole_level_vdb(const Store& store, const ExtractCase& c,
                                                 std::uint32_t level, int repeat) {
  if (!c.one_limit() || !(c.limits[0].min > 0) || std::isfinite(c.limits[0].max))
    return std::nullopt;
  const auto variable =
      static_cast<std::uint32_t>(store.manifest().variable_index(c.limits[0].var));
  const double iso = c.limits[0].min;
  WholeLevelVdb out;
  out.case_name = c.name;
  out.level = level;
  const Stopwatch build_clock;
  vdb::LevelGridSummary summary;
  const openvdb::FloatGrid::Ptr grid =
      vdb::build_level_grid(store, 0, variable, level, {}, &summary);
  out.build_seconds = build_clock.seconds();
  out.active_voxels = summary.active_voxels;

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  tbb::task_arena one(1, 1);
  for (int r = 0; r < std::max(1, repeat); ++r) {
    points.clear();
    triangles.clear();
    quads.clear();
    one.execute([&] {
      const Stopwatch w;
      openvdb::tools::volumeToMesh(*grid, points, triangles, quads, iso, 0.0);
      out.mesh_seconds.push_back(w.seconds());
    });
  }
  out.triangles = triangles.size() + 2 * quads.size();

  // World -> level index -> the level's samples on the real axes.
  const OctreeLayout& octree = store.octree();
  const format::Manifest& m = store.manifest();
  const std::array<const Axis*, 3> axes{&m.x, &m.y, &m.z};
  NodeSamples level_axes;
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < octree.level(level).samples[a]; ++i) {
      level_axes.coords[a].push_back(axes[a]->values[octree.fine_index(level, a, i)]);
    }
  }
  Mesh mesh;
  mesh.positions.reserve(points.size());
  for (const auto& p : points) {
    const openvdb::Vec3d index = grid->transform().worldToIndex(openvdb::Vec3d(p));
    std::array<double, 3> q{};
    for (int a = 0; a < 3; ++a) q[a] = peers::index_to_axis(level_axes, a, index[a]);
    mesh.positions.push_back(q);
  }
  for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  out.volume = std::fabs(enclosed_volume(mesh));
  spdlog::info(
      "bench: OpenVDB volumeToMesh on the whole level-{} {} grid: build {:.2f} s, mesh "
      "{:.2f} s (one thread), {} triangles",
      level, c.limits[0].var, out.build_seconds, median(out.mesh_seconds), out.triangles);
  return out;
}

}  // namespace strielad::bench
