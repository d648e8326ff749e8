// SPDX-License-Identifier: Apache-2.0
// Tables, targets and JSON of the extract suite (declared in extract_suite.h).
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bench/extract_suite.h"
#include "bench/latency_stats.h"

namespace strielad::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
double ratio(double a, double b) { return b > 0 ? a / b : kNaN; }

// What one contender did over a group's bricks.
struct ContenderSummary {
  std::size_t bricks = 0;
  double p50_ms = kNaN, p90_ms = kNaN;  // over bricks, of each brick's median
  double total_s = 0;                   // sum of the per-brick medians
  double spread = kNaN;                 // median over bricks of (max - min) / median
  double mcells_per_s = kNaN;           // cells per brick / p50
  double triangles = kNaN;              // mean per brick
  double limit_triangles = kNaN;        // mean per brick, on the limit surface
  double ns_per_triangle = kNaN;        // total seconds / total triangles
  double no_surface_p50_ms = kNaN;      // over bricks, with nothing to extract (kernel, FE)
  // (total seconds - total seconds with nothing to extract) / total triangles: what each
  // triangle costs beyond the contender's fixed cost.
  double marginal_ns_per_triangle = kNaN;
  double volume = kNaN;                 // sum over bricks (NaN if any is NaN)
  double volume_vs_paper = kNaN;        // (volume - paper's) / paper's
  double volume_vs_reference = kNaN;    // (volume - trilinear region's) / trilinear region's
  double max_brick_dv = kNaN;           // max |V - V_paper| / node volume over bricks
  double clean = kNaN;                  // fraction of clean meshes (kernel)
  double cut_cells = kNaN;              // fraction of cells cut (kernel)
};

ContenderSummary summarize_contender(const BrickGroup& g, std::size_t i) {
  ContenderSummary s;
  s.bricks = g.runs.size();
  if (g.runs.empty()) return s;
  const std::size_t ip = g.index_of(kPaper);
  std::vector<double> ms, spreads, no_surface_ms;
  double no_surface_total_s = 0;
  double tris = 0, limit_tris = 0, volume = 0, paper_volume = 0, reference = 0, max_dv = 0,
         cells = 0, cut = 0;
  std::size_t clean = 0;
  for (const BrickRun& r : g.runs) {
    ms.push_back(r.seconds[i] * 1e3);
    s.total_s += r.seconds[i];
    no_surface_ms.push_back(r.no_surface_seconds[i] * 1e3);
    no_surface_total_s += r.no_surface_seconds[i];
    const Summary rounds = summarize(r.rounds[i]);
    spreads.push_back(rounds.p50 > 0 ? (rounds.max - rounds.min) / rounds.p50 : 0);
    tris += static_cast<double>(r.triangles[i]);
    limit_tris += static_cast<double>(r.limit_triangles[i]);
    volume += r.volume[i];
    paper_volume += r.volume[ip];
    reference += r.reference_volume;
    max_dv = std::max(max_dv, std::fabs(r.volume[i] - r.volume[ip]) / r.node_volume);
    clean += r.kernel_clean ? 1 : 0;
    cells += static_cast<double>(r.cells);
    cut += static_cast<double>(r.kernel_stats.cut_cells);
  }
  const Summary q = summarize(ms);
  s.p50_ms = q.p50;
  s.p90_ms = q.p90;
  s.spread = median(spreads);
  s.mcells_per_s = ratio(cells / static_cast<double>(s.bricks), q.p50 * 1e-3) / 1e6;
  s.triangles = tris / static_cast<double>(s.bricks);
  s.limit_triangles = limit_tris / static_cast<double>(s.bricks);
  s.ns_per_triangle = ratio(s.total_s * 1e9, tris);
  if (std::isfinite(no_surface_total_s)) {
    s.no_surface_p50_ms = summarize(no_surface_ms).p50;
    s.marginal_ns_per_triangle = ratio((s.total_s - no_surface_total_s) * 1e9, tris);
  }
  s.volume = volume;
  s.volume_vs_paper = std::isnan(volume) ? kNaN : (volume - paper_volume) / paper_volume;
  s.volume_vs_reference = std::isnan(volume) ? kNaN : (volume - reference) / reference;
  s.max_brick_dv = std::isnan(volume) ? kNaN : max_dv;
  if (g.contenders[i] == kKernel) {
    s.clean = static_cast<double>(clean) / static_cast<double>(s.bricks);
    s.cut_cells = cut / cells;
  }
  return s;
}

std::string group_key(const BrickGroup& g) {
  return fmt::format("{} B={}", g.extract_case.name, g.brick);
}

Table brick_table(const ExtractSuiteReport& r, const ExtractCase& c) {
  Table t{"bricks_" + c.name,
          fmt::format("Per-brick extraction, {}: one thread, same bricks for every contender, "
                      "median of {} round(s) per brick",
                      c.label, r.options.repeat),
          {"B / contender", "bricks", "ms p50", "ms p90", "spread %", "Mcells/s", "tris/brick",
           "limit tris", "ns/tri", "ms no surface", "ns/tri beyond", "volume", "dV vs paper %",
           "max dV/node %", "dV vs trilinear %", "clean %", "cut cells %", "x paper",
           "x FlyingEdges"},
          {},
          {}};
  for (const BrickGroup& g : r.groups) {
    if (g.extract_case.name != c.name) continue;
    if (g.runs.empty()) {
      t.add({fmt::format("B={} (no brick cut by {})", g.brick, c.label), Cell::integer(0), kNaN,
             kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN,
             kNaN, kNaN});
      continue;
    }
    const ContenderSummary paper = summarize_contender(g, g.index_of(kPaper));
    const std::size_t ife = g.index_of(kFlyingEdges);
    const ContenderSummary fe =
        ife != std::string::npos ? summarize_contender(g, ife) : ContenderSummary{};
    for (std::size_t i = 0; i < g.contenders.size(); ++i) {
      const ContenderSummary s = summarize_contender(g, i);
      const bool is_paper = g.contenders[i] == kPaper;
      t.add({fmt::format("B={} {}", g.brick, g.contenders[i]),
             Cell::integer(static_cast<double>(s.bricks)), Cell(s.p50_ms, 3), Cell(s.p90_ms, 3),
             Cell(s.spread * 100, 0), Cell(s.mcells_per_s, 2), Cell(s.triangles, 0),
             Cell(s.limit_triangles, 0), Cell(s.ns_per_triangle, 0), Cell(s.no_surface_p50_ms, 3),
             Cell(s.marginal_ns_per_triangle, 0), Cell(s.volume, 3),
             Cell(is_paper ? kNaN : s.volume_vs_paper * 100, 4),
             Cell(is_paper ? kNaN : s.max_brick_dv * 100, 4), Cell(s.volume_vs_reference * 100, 3),
             Cell(s.clean * 100, 1), Cell(s.cut_cells * 100, 1),
             Cell(ratio(paper.p50_ms, s.p50_ms), 1), Cell(ratio(fe.p50_ms, s.p50_ms), 2)});
    }
  }
  for (const BrickGroup& g : r.groups) {
    if (g.extract_case.name != c.name) continue;
    std::uint64_t table = 0, cut = 0, simple = 0, clipped = 0;
    for (const BrickRun& run : g.runs) {
      table += run.kernel_stats.table_cells;
      cut += run.kernel_stats.cut_cells;
      simple += run.kernel_stats.simple_tets;
      clipped += run.kernel_stats.clipped_tets;
    }
    const double tetrahedra_share =
        cut == 0 ? 0.0 : 100.0 * static_cast<double>(cut - table) / static_cast<double>(cut);
    const double clipper_share =
        simple + clipped == 0 ? 0.0 : 100.0 * static_cast<double>(clipped) / static_cast<double>(simple + clipped);
    t.notes.push_back(fmt::format(
        "B={}: {} bricks picked (seed {}) of {} full {}^3-sample level-0 nodes whose exact [min, "
        "max] straddles {} = {}; kernel: {:.1f}% of cut cells crossed by several conditions (cut "
        "into tetrahedra), {:.1f}% of their cut tetrahedra took the general clipper; group took "
        "{:.0f} s",
        g.brick, g.runs.size(), r.options.pick_seed, g.candidates, g.brick + 1,
        c.limits[c.select].var, c.threshold(), tetrahedra_share, clipper_share, g.seconds));
  }
  t.notes.push_back(
      "timed: strielad kernel = the whole extract_node_mesh call (conditions, cell loops and "
      "tetrahedra, welding, axis mapping, gradient normals); paper VTK pipeline = vtkRectilinearGrid build + "
      "vtkTableBasedClipDataSet per limit + vtkDataSetSurfaceFilter + vtkTriangleFilter + "
      "vtkPolyDataNormals; vtkFlyingEdges3D = vtkImageData build + contour with normals; OpenVDB = "
      "FloatGrid + copyFromDense + volumeToMesh (not the padded copy before it); the peers' "
      "conversion to the common Mesh is not timed. VTK and OpenVDB run in a one-thread TBB arena");
  t.notes.push_back(
      "ms p50/p90 = over bricks, of each brick's median over rounds; contenders take turns within "
      "each round; spread = median over bricks of (max - min) / median of its rounds; Mcells/s = "
      "(B)^3 cells / ms p50 (one core); x paper, x FlyingEdges = their ms p50 / this row's ms p50; "
      "tris/brick = mean triangles per brick, limit tris = those on the limit surface (the kernel "
      "and the paper pipeline also close the mesh on the node's faces); ns/tri = all bricks' "
      "median seconds / all their triangles; ms no surface = the same contender on the same brick "
      "with the case's field set to one value outside the region (nothing to extract; kernel and "
      "vtkFlyingEdges3D, taking the same turns): its cost before the first triangle; ns/tri beyond "
      "= (all bricks' median seconds - the same with no surface) / all their triangles");
  t.notes.push_back(
      "volume = sum over bricks of the enclosed volume (deg x deg x m); kernel and paper meshes "
      "are "
      "closed; vtkFlyingEdges3D's open iso-surface is closed with the paper pipeline's node-face "
      "triangles (same lattice-edge crossings), so its dV is that of the limit surface alone; "
      "OpenVDB's surface stops half a cell short of the node's faces and encloses nothing "
      "(see the whole-level table); max dV/node = max over bricks of |V - V_paper| / node box "
      "volume; dV vs trilinear = against the volume of the exact region (every limit on the "
      "trilinearly interpolated field), by the midpoint rule on 8^3 points "
      "per cell the boundary may cross; clean = check_mesh: closed, consistently oriented, no "
      "zero-area triangle, unit "
      "normals");
  return t;
}

Table level_table(const LevelGroup& g) {
  Table t{"levels_" + g.extract_case.name,
          fmt::format("Error against run time over the octree levels, {} (brick {}, {} round(s), "
                      "extract_level with {} threads and 1)",
                      g.extract_case.label, g.brick,
                      g.rows.empty() ? 0 : g.rows[0].seconds_one.size(), g.threads_all),
          {"level", "stride", "nodes", "extracted", "bricks read", "s all cores", "s 1 thread",
           "x faster (1 thr)", "triangles", "seamless tris", "volume", "volume error %",
           "dist L->0", "dist 0->L", "mean dist", "p90 L->0"},
          {},
          {}};
  const double t0 = g.rows.empty() ? kNaN : g.rows.front().median_one();
  for (const LevelRow& row : g.rows) {
    t.add({fmt::format("L{}", row.level),
           fmt::format("{}x{}x{}", row.stride[0], row.stride[1], row.stride[2]),
           Cell::integer(static_cast<double>(row.nodes)),
           Cell::integer(static_cast<double>(row.extracted)),
           Cell::integer(static_cast<double>(row.chunks_read)), Cell(row.median_all(), 3),
           Cell(row.median_one(), 3), Cell(ratio(t0, row.median_one()), 1),
           Cell::integer(static_cast<double>(row.triangles)),
           Cell::integer(static_cast<double>(row.seamless_triangles)), Cell(row.volume, 1),
           Cell(row.volume_error * 100, 3), Cell(row.distance_to_fine, 3),
           Cell(row.distance_from_fine, 3), Cell(row.distance(), 3),
           Cell(row.distance_to_fine_p90, 3)});
  }
  t.notes.push_back(
      "seconds = extract_level's wall time for the whole level (index checks, brick reads and "
      "decompression through a fresh 256 MiB cache from the page cache, kernel on every node not "
      "skipped), median of the rounds; extracted = nodes meshed, the rest were skipped from the "
      "index alone");
  t.notes.push_back(
      "volume = sum of the closed per-node meshes' volumes (= the seamless union's), deg x deg x "
      "m; volume error = relative to level 0");
  t.notes.push_back(
      "distances in level-0 cells (index space: each axis in its own cells, so the stretched "
      "height axis counts model levels), exact point-to-triangle distances between the limit "
      "surfaces (triangles on a limit; node and grid faces left out): L->0 = mean over the level's "
      "distinct surface vertices of the distance to level 0's surface, 0->L = mean over level 0's "
      "vertices of the distance to this level's surface (large where detail, e.g. small clouds, "
      "is lost), mean dist = their average; vertex sets thinned evenly to at most 200,000 "
      "queries");
  return t;
}

Table whole_level_table(const ExtractSuiteReport& r) {
  Table t{"whole_level",
          "The whole level-0 grid in one call: OpenVDB volumeToMesh against the kernel's level "
          "extraction, one thread",
          {"what", "seconds", "triangles", "volume", "dV vs kernel %"},
          {},
          {}};
  for (const WholeLevelVdb& w : r.whole_level) {
    std::uint64_t kernel_tris = 0;
    for (const LevelGroup& g : r.level_groups) {
      if (g.extract_case.name == w.case_name && !g.rows.empty())
        kernel_tris = g.rows[0].seamless_triangles;
    }
    t.add({fmt::format("{}: strielad extract_level L0, 1 thread", w.case_name),
           Cell(w.kernel_seconds_one, 3), Cell::integer(static_cast<double>(kernel_tris)),
           Cell(w.kernel_volume, 1), kNaN});
    t.add({fmt::format("{}: OpenVDB volumeToMesh, level-0 grid", w.case_name),
           Cell(median(w.mesh_seconds), 3), Cell::integer(static_cast<double>(w.triangles)),
           Cell(w.volume, 1), Cell((w.volume - w.kernel_volume) / w.kernel_volume * 100, 3)});
    t.add({fmt::format("{}: OpenVDB grid built from the store", w.case_name),
           Cell(w.build_seconds, 3), kNaN, kNaN, kNaN});
    t.notes.push_back(fmt::format(
        "{}: FloatGrid of {} active voxels (background 0, inactive where 0) built serially by "
        "vdb::build_level_grid (brick reads included); volumeToMesh at the threshold without "
        "adaptivity in a one-thread arena, median of {} round(s); its points mapped to the real "
        "axes; "
        "kernel triangles = the seamless union's; the kernel time includes brick reads and "
        "decompression, OpenVDB's does not (it starts from the built grid)",
        w.case_name, w.active_voxels, w.mesh_seconds.size()));
  }
  t.notes.push_back(
      "OpenVDB's surface closes half a voxel beyond the grid's edge where a cloud touches it (the "
      "grid's background 0 lies outside the data), the kernel's at the edge itself, so volumes "
      "differ by that rim as well as by dual vs primal vertices");
  return t;
}

Table targets_table(const ExtractSuiteReport& r) {
  Table t{"targets", "Targets: equal volumes", {"target", "measured", "met"}, {}, {}};
  for (const auto& g : r.targets) {
    t.add({g.name, g.measured, g.evaluated ? (g.met ? "yes" : "NO") : "not measured"});
  }
  t.notes.push_back(
      "volumes equal = the kernel's total enclosed volume over the bricks within 1% of the "
      "paper pipeline's");
  return t;
}

// How fast the kernel is against the peers on the same bricks: reported as it is (the
// earlier per-brick speed targets, 50x the paper's pipeline and 2x vtkFlyingEdges3D, are
// withdrawn; speed goals are end to end).
Table standing_table(const ExtractSuiteReport& r) {
  Table t{"standing", "Standing: the kernel against the peers, per brick",
          {"case", "against", "measured"}, {}, {}};
  for (const BrickGroup& g : r.groups) {
    if (g.runs.empty()) continue;
    const ContenderSummary k = summarize_contender(g, g.index_of(kKernel));
    const ContenderSummary p = summarize_contender(g, g.index_of(kPaper));
    t.add({group_key(g), "paper VTK pipeline",
           fmt::format("{:.1f}x ({:.3f} vs {:.3f} ms/brick; total time {:.1f}x)",
                       ratio(p.p50_ms, k.p50_ms), k.p50_ms, p.p50_ms,
                       ratio(p.total_s, k.total_s))});
    if (const std::size_t ife = g.index_of(kFlyingEdges); ife != std::string::npos) {
      const ContenderSummary fe = summarize_contender(g, ife);
      t.add({group_key(g), "vtkFlyingEdges3D",
             fmt::format("{:.2f}x ({:.3f} vs {:.3f} ms/brick; total time {:.2f}x)",
                         ratio(fe.p50_ms, k.p50_ms), k.p50_ms, fe.p50_ms,
                         ratio(fe.total_s, k.total_s))});
    }
  }
  t.notes.push_back(
      "peer's median ms per brick / the kernel's (one thread, same bricks); the kernel's meshes "
      "are closed and multi-condition, vtkFlyingEdges3D's an open single iso-surface");
  return t;
}

}  // namespace

std::vector<Target> evaluate_extract_targets(const ExtractSuiteReport& r) {
  std::vector<Target> out;
  for (const BrickGroup& g : r.groups) {
    const std::string key = group_key(g);
    if (g.runs.empty()) {
      out.push_back(
          {fmt::format("{}: kernel volume = paper volume within 1%", key), "no bricks", false,
           false});
      continue;
    }
    const ContenderSummary k = summarize_contender(g, g.index_of(kKernel));
    const ContenderSummary p = summarize_contender(g, g.index_of(kPaper));
    out.push_back(
        {fmt::format("{}: kernel volume = paper volume within 1%", key),
         fmt::format("{:+.3f}% (max per brick {:.3f}% of the node; vs the exact trilinear "
                     "region: kernel {:+.3f}%, paper {:+.3f}%; {:.1f}% of kernel meshes clean)",
                     k.volume_vs_paper * 100, k.max_brick_dv * 100, k.volume_vs_reference * 100,
                     p.volume_vs_reference * 100, k.clean * 100),
         std::fabs(k.volume_vs_paper) <= 0.01, true});
  }
  return out;
}

std::vector<Table> extract_report_tables(const ExtractSuiteReport& r) {
  std::vector<Table> tables;
  for (const ExtractCase& c : r.options.cases) tables.push_back(brick_table(r, c));
  for (const LevelGroup& g : r.level_groups) tables.push_back(level_table(g));
  if (!r.whole_level.empty()) tables.push_back(whole_level_table(r));
  tables.push_back(standing_table(r));
  tables.push_back(targets_table(r));
  return tables;
}

namespace {

nlohmann::json case_json(const ExtractCase& c) {
  nlohmann::json limits = nlohmann::json::array();
  for (const CaseLimit& l : c.limits) {
    nlohmann::json j = {{"var", l.var}};
    if (std::isfinite(l.min)) j["min"] = l.min;
    if (std::isfinite(l.max)) j["max"] = l.max;
    limits.push_back(j);
  }
  return nlohmann::json{
      {"name", c.name}, {"label", c.label}, {"limits", limits}, {"select", c.select}};
}

nlohmann::json options_json(const ExtractSuiteOptions& o) {
  nlohmann::json cases = nlohmann::json::array(), level_cases = nlohmann::json::array();
  for (const auto& c : o.cases) cases.push_back(case_json(c));
  for (const auto& c : o.level_cases) level_cases.push_back(case_json(c));
  return {{"dims", {o.dims.x, o.dims.y, o.dims.z}},
          {"variables", o.variables},
          {"bricks", o.bricks},
          {"bricks_per_case", o.bricks_per_case},
          {"repeat", o.repeat},
          {"pick_seed", o.pick_seed},
          {"seed", o.seed},
          {"threads", o.threads},
          {"cases", cases},
          {"levels", o.levels},
          {"level_brick", o.level_brick},
          {"level_cases", level_cases},
          {"level_repeat", o.level_repeat}};
}

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

// Per-brick medians and volumes as columns, for anyone recomputing the summaries.
nlohmann::json brick_group_json(const BrickGroup& g) {
  nlohmann::json nodes = nlohmann::json::array(), reference = nlohmann::json::array();
  nlohmann::json seconds = nlohmann::json::object(), volume = nlohmann::json::object();
  nlohmann::json no_surface = nlohmann::json::object();
  for (const auto& c : g.contenders) {
    seconds[c] = nlohmann::json::array();
    no_surface[c] = nlohmann::json::array();
    volume[c] = nlohmann::json::array();
  }
  for (const BrickRun& run : g.runs) {
    nodes.push_back(run.node);
    reference.push_back(run.reference_volume);
    for (std::size_t i = 0; i < g.contenders.size(); ++i) {
      seconds[g.contenders[i]].push_back(run.seconds[i]);
      no_surface[g.contenders[i]].push_back(finite_or_null(run.no_surface_seconds[i]));
      volume[g.contenders[i]].push_back(finite_or_null(run.volume[i]));
    }
  }
  return {{"case", g.extract_case.name},
          {"brick", g.brick},
          {"contenders", g.contenders},
          {"candidates", g.candidates},
          {"group_seconds", g.seconds},
          {"nodes", nodes},
          {"median_seconds", seconds},
          {"no_surface_median_seconds", no_surface},
          {"volume", volume},
          {"trilinear_volume", reference}};
}

nlohmann::json level_group_json(const LevelGroup& g) {
  nlohmann::json rows = nlohmann::json::array();
  for (const LevelRow& row : g.rows) {
    rows.push_back({{"level", row.level},
                    {"seconds_all", row.seconds_all},
                    {"seconds_one", row.seconds_one},
                    {"volume", row.volume},
                    {"volume_error", row.volume_error},
                    {"distance_to_fine", row.distance_to_fine},
                    {"distance_from_fine", row.distance_from_fine},
                    {"triangles", row.triangles}});
  }
  return {{"case", g.extract_case.name},
          {"brick", g.brick},
          {"threads_all", g.threads_all},
          {"rows", rows}};
}

}  // namespace

nlohmann::json extract_report_json(const ExtractSuiteReport& r, const std::vector<Table>& tables) {
  const auto& o = r.options;
  nlohmann::json targets = nlohmann::json::array();
  for (const auto& t : r.targets) {
    targets.push_back(
        {{"name", t.name}, {"measured", t.measured}, {"met", t.met}, {"evaluated", t.evaluated}});
  }
  nlohmann::json j = {
      {"suite", "extract"},
      {"command", o.command_line},
      {"options", options_json(o)},
      {"machine", r.machine},
      {"input",
       {{"bytes", r.input.bytes},
        {"reused", r.input.reused},
        {"generate_seconds", r.input.generate_seconds}}},
      {"convert_seconds", r.convert_seconds},
      {"suite_seconds", r.seconds},
      {"plot", r.plot_status},
      {"targets", targets},
      {"tables", nlohmann::json::array()},
  };
  for (const auto& t : tables) j["tables"].push_back(table_json(t));
  nlohmann::json groups = nlohmann::json::array();
  for (const BrickGroup& g : r.groups) groups.push_back(brick_group_json(g));
  j["bricks"] = groups;
  nlohmann::json levels = nlohmann::json::array();
  for (const LevelGroup& g : r.level_groups) levels.push_back(level_group_json(g));
  j["levels"] = levels;
  return j;
}

}  // namespace strielad::bench
