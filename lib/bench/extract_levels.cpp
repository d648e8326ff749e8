// SPDX-License-Identifier: Apache-2.0
#include "bench/extract_levels.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "bench/extract_surface_distance.h"
#include "bench/latency_stats.h"
#include "bench/stopwatch.h"
#include "extract/conditions.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "store/store.h"

namespace strielad::bench {

double LevelRow::median_all() const { return median(seconds_all); }
double LevelRow::median_one() const { return median(seconds_one); }

namespace {

// Distance queries beyond this many are thinned evenly (deterministic).
constexpr std::size_t kMaxQueries = 200'000;

ResolvedScene scene_of(const Store& store, const ExtractCase& c) {
  ResolvedScene scene;
  ResolvedSubVolume sv;
  sv.id = 1;
  sv.name = c.name;
  for (int a = 0; a < 3; ++a) sv.box[a] = {-INFINITY, INFINITY};
  for (const CaseLimit& l : c.limits) {
    const auto v = static_cast<std::uint32_t>(store.manifest().variable_index(l.var));
    sv.limits.push_back({v, l.min, l.max});
    scene.needed_variables.push_back(v);
  }
  std::sort(scene.needed_variables.begin(), scene.needed_variables.end());
  scene.needed_variables.erase(
      std::unique(scene.needed_variables.begin(), scene.needed_variables.end()),
      scene.needed_variables.end());
  scene.subvolumes.push_back(std::move(sv));
  return scene;
}

std::vector<Point3> thinned(std::vector<Point3> points) {
  if (points.size() <= kMaxQueries) return points;
  std::vector<Point3> out;
  out.reserve(kMaxQueries);
  const double step = static_cast<double>(points.size()) / static_cast<double>(kMaxQueries);
  for (std::size_t i = 0; i < kMaxQueries; ++i) {
    out.push_back(points[static_cast<std::size_t>(static_cast<double>(i) * step)]);
  }
  return out;
}

struct LevelSurface {
  std::vector<Point3> points;        // vertices of limit-surface triangles, level-0 index space
  std::vector<Triangle3> triangles;  // limit-surface triangles into `points`
  std::vector<Point3> distinct;      // the distinct points (distance queries)
};

// Measures of one extraction; its limit surface in level-0 index space.
LevelSurface measure(const Store& store, const LevelExtraction& x, LevelRow& row) {
  const format::Manifest& m = store.manifest();
  const std::array<const std::vector<double>*, 3> axes{&m.x.values, &m.y.values, &m.z.values};
  LevelSurface s;
  row.triangles = x.totals.triangles;
  row.cut_cells = x.totals.cut_cells;
  row.chunks_read = x.totals.chunks_read;
  row.extracted = x.totals.outcomes[0] + x.totals.outcomes[1];
  row.skipped = x.totals.outcomes[2] + x.totals.outcomes[3] + x.totals.outcomes[4];
  row.volume = 0;
  row.seamless_triangles = 0;
  std::vector<std::uint32_t> index_of;  // mesh vertex -> points index + 1
  for (const NodeExtraction& n : x.nodes) {
    for (const SubVolumeResult& r : n.results) {
      const Mesh& mesh = r.mesh;
      if (mesh.empty()) continue;
      row.volume += enclosed_volume(mesh);
      index_of.assign(mesh.vertex_count(), 0);
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const FaceKind k = mesh.face_kinds[t];
        if (k != FaceKind::kNodeBoundary) ++row.seamless_triangles;
        if (k != FaceKind::kLimit) continue;
        Triangle3 tri{};
        for (int i = 0; i < 3; ++i) {
          const std::uint32_t v = mesh.triangles[t][i];
          if (index_of[v] == 0) {
            const auto& p = mesh.positions[v];
            s.points.push_back({fractional_index(*axes[0], p[0]), fractional_index(*axes[1], p[1]),
                                fractional_index(*axes[2], p[2])});
            index_of[v] = static_cast<std::uint32_t>(s.points.size());
          }
          tri[i] = index_of[v] - 1;
        }
        s.triangles.push_back(tri);
      }
    }
  }
  // Vertices on faces shared by two nodes appear in both meshes: query them once.
  s.distinct = s.points;
  std::sort(s.distinct.begin(), s.distinct.end());
  s.distinct.erase(std::unique(s.distinct.begin(), s.distinct.end()), s.distinct.end());
  row.limit_vertices = s.distinct.size();
  return s;
}

}  // namespace

LevelGroup run_level_group(const Store& store, const ExtractCase& c,
                           const LevelGroupOptions& options) {
  LevelGroup g;
  g.extract_case = c;
  g.brick = store.octree().brick();
  g.threads_all =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  const ResolvedScene scene = scene_of(store, c);
  const OctreeLayout& octree = store.octree();
  const int repeat = std::max(1, options.repeat);
  std::optional<SurfaceDistance> fine;  // level 0's limit surface
  std::vector<Point3> fine_queries;
  for (std::uint32_t level = 0; level < octree.level_count(); ++level) {
    LevelRow row;
    row.level = level;
    const LevelShape& shape = octree.level(level);
    row.samples = shape.samples;
    row.stride = shape.stride;
    row.nodes = shape.node_count();
    LevelSurface surface;
    for (int r = 0; r < repeat; ++r) {
      for (int threads : {g.threads_all, 1}) {
        LevelExtractionOptions lo;
        lo.level = level;
        lo.threads = threads;
        const LevelExtraction x = extract_level(store, scene, lo);
        (threads == 1 ? row.seconds_one : row.seconds_all).push_back(x.totals.seconds);
        if (r == 0 && threads == g.threads_all) surface = measure(store, x, row);
      }
    }
    if (level == 0) {
      fine_queries = thinned(std::move(surface.distinct));
      fine.emplace(std::move(surface.points), std::move(surface.triangles));
      row.volume_error = 0;
      row.distance_to_fine = row.distance_from_fine = row.distance_to_fine_p90 = 0;
    } else {
      const double v0 = g.rows.front().volume;
      row.volume_error =
          v0 != 0 ? (row.volume - v0) / v0 : std::numeric_limits<double>::quiet_NaN();
      const DistanceSummary to = surface_distances(thinned(std::move(surface.distinct)), *fine);
      const SurfaceDistance coarse(std::move(surface.points), std::move(surface.triangles));
      const DistanceSummary from = surface_distances(fine_queries, coarse);
      row.distance_to_fine = to.mean;
      row.distance_to_fine_p90 = to.p90;
      row.distance_from_fine = from.mean;
    }
    spdlog::info(
        "bench: levels {} L{}: {:.3f} s all cores, {:.3f} s one thread, {} triangles, "
        "volume error {:.2e}, distance {:.2f} cells",
        c.name, level, row.median_all(), row.median_one(), row.triangles, row.volume_error,
        row.distance());
    g.rows.push_back(std::move(row));
  }
  return g;
}

SurfaceComparison compare_level0_surfaces(const Store& reference, const Store& other,
                                          const ExtractCase& c) {
  SurfaceComparison out;
  out.case_name = c.name;
  LevelExtractionOptions lo;
  lo.level = 0;
  LevelRow ref_row, row;
  LevelSurface ref = measure(reference, extract_level(reference, scene_of(reference, c), lo), ref_row);
  LevelSurface mine = measure(other, extract_level(other, scene_of(other, c), lo), row);
  out.reference_volume = ref_row.volume;
  out.volume = row.volume;
  out.volume_error = ref_row.volume != 0 ? (row.volume - ref_row.volume) / ref_row.volume
                                         : std::numeric_limits<double>::quiet_NaN();
  out.reference_triangles = ref_row.triangles;
  out.triangles = row.triangles;
  const std::vector<Point3> ref_queries = thinned(std::move(ref.distinct));
  const std::vector<Point3> my_queries = thinned(std::move(mine.distinct));
  const SurfaceDistance ref_surface(std::move(ref.points), std::move(ref.triangles));
  const SurfaceDistance my_surface(std::move(mine.points), std::move(mine.triangles));
  const DistanceSummary to = surface_distances(my_queries, ref_surface);
  const DistanceSummary from = surface_distances(ref_queries, my_surface);
  out.distance_mean = 0.5 * (to.mean + from.mean);
  out.distance_p90 = std::max(to.p90, from.p90);
  out.distance_max = std::max(to.max, from.max);
  return out;
}

}  // namespace strielad::bench
