// SPDX-License-Identifier: Apache-2.0
#include "robust/extract_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "client/server_client.h"
#include "core/error.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "grid/longitude_turns.h"
#include "peers/vtk_paper_pipeline.h"
#include "robust/case_reference.h"
#include "serve/server.h"
#include "store/level_samples.h"

namespace strielad::robust {
namespace {

constexpr std::uint32_t kDomainSubVolume = 100;
constexpr std::uint32_t kFirstBoxSubVolume = 200;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kFloatMax = std::numeric_limits<float>::max();

// The value as extraction sees it: float32, clamped to the float range.
double as_extracted(double v) {
  if (std::isnan(v)) return v;
  return static_cast<double>(static_cast<float>(std::clamp(v, -kFloatMax, kFloatMax)));
}

bool within(double v, const ResolvedLimit& limit) {
  const double e = as_extracted(v);
  return !std::isnan(e) && e >= limit.min && e <= limit.max;
}

std::array<double, 2> extent(const std::vector<double>& coords) {
  const auto [lo, hi] = std::minmax_element(coords.begin(), coords.end());
  return {*lo, *hi};
}

double box_volume(const NodeGeometry& g) {
  double v = 1;
  for (int a = 0; a < 3; ++a) {
    const auto e = extent(g.coords[a]);
    v *= e[1] - e[0];
  }
  return v;
}

// Volume bounds of a limit's region inside one node from the level's samples.
struct VolumeBounds {
  double lower = 0, upper = 0;
};

VolumeBounds limit_volume_bounds(const LevelSamples<double>& level, const IndexBox& box,
                                 const NodeGeometry& g, const ResolvedLimit& limit) {
  VolumeBounds b;
  const auto& d = level.dims;
  const auto at = [&](std::size_t x, std::size_t y, std::size_t z) {
    return level.values[(z * d[1] + y) * d[0] + x];
  };
  for (std::size_t z = box.lo[2]; z < box.hi[2]; ++z)
    for (std::size_t y = box.lo[1]; y < box.hi[1]; ++y)
      for (std::size_t x = box.lo[0]; x < box.hi[0]; ++x) {
        int inside = 0;
        for (int k = 0; k < 8; ++k) {
          inside += within(at(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1)), limit) ? 1 : 0;
        }
        if (inside == 0) continue;
        const std::size_t i = x - box.lo[0], j = y - box.lo[1], l = z - box.lo[2];
        const double volume = std::fabs((g.coords[0][i + 1] - g.coords[0][i]) *
                                        (g.coords[1][j + 1] - g.coords[1][j]) *
                                        (g.coords[2][l + 1] - g.coords[2][l]));
        b.upper += volume;
        if (inside == 8) b.lower += volume;
      }
  return b;
}

bool any_missing(const LevelSamples<double>& level, const IndexBox& box) {
  const auto& d = level.dims;
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z)
    for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y)
      for (std::size_t x = box.lo[0]; x <= box.hi[0]; ++x) {
        if (std::isnan(level.values[(z * d[1] + y) * d[0] + x])) return true;
      }
  return false;
}

// Edges (between distinct positions) not used equally often in both directions: 0 for
// a closed, consistently oriented mesh, also where it touches itself along an edge
// (an edge of four triangles, two each way: samples exactly at a bound).
std::uint64_t unbalanced_edges(const Mesh& mesh) {
  std::map<std::array<double, 3>, std::uint32_t> ids;
  std::vector<std::uint32_t> id(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    id[v] = ids.try_emplace(mesh.positions[v], static_cast<std::uint32_t>(ids.size())).first->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::int64_t> balance;
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = id[t[i]], b = id[t[(i + 1) % 3]];
      if (a == b) continue;
      balance[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  }
  std::uint64_t unbalanced = 0;
  for (const auto& [edge, count] : balance) unbalanced += count != 0 ? 1 : 0;
  return unbalanced;
}

// Positions, attributes and (for meshes straight from the kernel) topology of one mesh.
// `longitude_x`: x is a longitude axis, whose meshes may come out whole turns away from
// the node's own longitudes (a range in another convention: grid/longitude_turns.h).
void check_mesh_content(const Mesh& mesh, const NodeGeometry& g, bool missing_in_node,
                        double position_slack, bool topology, bool longitude_x,
                        StageFindings& f, const std::string& where,
                        std::uint64_t* pinch_edges) {
  if (mesh.face_kinds.size() != mesh.triangles.size()) {
    f.problem("{}: {} face kinds for {} triangles", where, mesh.face_kinds.size(),
              mesh.triangles.size());
  }
  if (topology) {
    const MeshCheck m = check_mesh(mesh);
    const std::uint64_t unbalanced = unbalanced_edges(mesh);
    if (unbalanced != 0 || m.open_edges != 0 || m.degenerate_triangles != 0 || m.bad_normals != 0 ||
        m.bad_positions != 0) {
      f.problem("{}: mesh not closed and clean: {} edges not used equally often in both "
                "directions ({} open), {} zero-area triangles, {} bad normals, {} bad positions",
                where, unbalanced, m.open_edges, m.degenerate_triangles, m.bad_normals,
                m.bad_positions);
    }
    *pinch_edges += m.nonmanifold_edges;
  } else {
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
      const auto& n = mesh.normals[v];
      const double len = std::sqrt(double{n[0]} * n[0] + double{n[1]} * n[1] + double{n[2]} * n[2]);
      if (!std::isfinite(len) || std::fabs(len - 1.0) > 1e-3) {
        f.problem("{}: normal {} is not unit length ({})", where, v, len);
        break;
      }
    }
  }
  for (int a = 0; a < 3; ++a) {
    const auto e = extent(g.coords[a]);
    const double slack = position_slack * (e[1] - e[0]) + 1e-12 * std::fabs(e[1]);
    const double centre = 0.5 * (e[0] + e[1]);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      double p = mesh.positions[v][a];
      if (a == 0 && longitude_x) p -= kFullTurn * std::round((p - centre) / kFullTurn);
      if (!std::isfinite(p) || p < e[0] - slack || p > e[1] + slack) {
        f.problem("{}: vertex {} axis {} at {} outside the node's [{}, {}]", where, v, a, p, e[0],
                  e[1]);
        break;
      }
    }
  }
  if (mesh.attribute_names != std::vector<std::string>{"f"} || mesh.attributes.size() != 1) {
    f.problem("{}: attributes {} instead of [f]", where, fmt::join(mesh.attribute_names, ", "));
    return;
  }
  const auto& values = mesh.attributes[0];
  if (values.size() != mesh.positions.size()) {
    f.problem("{}: {} attribute values for {} vertices", where, values.size(), mesh.positions.size());
  }
  for (std::size_t v = 0; v < values.size(); ++v) {
    if (std::isinf(values[v]) || (std::isnan(values[v]) && !missing_in_node)) {
      f.problem("{}: attribute f at vertex {} is {} in a node without missing samples", where, v,
                values[v]);
      break;
    }
  }
}

// The level of extraction that the scene's check runs at: 0, 1 and the root's.
std::vector<std::size_t> levels_to_check(const OctreeLayout& layout) {
  std::set<std::size_t> levels{0, layout.level_count() - 1};
  if (layout.level_count() > 1) levels.insert(1);
  return {levels.begin(), levels.end()};
}

bool is_refusal(const Error& e) { return e.code() != ErrorCode::kInternal; }

// Whole turns at which a sub-volume's x range meets coordinates `x` (longitude_turns.h):
// {0} off a longitude axis or without a range.
std::vector<int> turns_of(const ResolvedSubVolume& sv, const format::Manifest& m,
                          const std::vector<double>& x) {
  const bool bounded = sv.box[0].lo != -kInfinity || sv.box[0].hi != kInfinity;
  if (m.x.kind != AxisKind::kLongitude || !bounded) return {0};
  return longitude_turns(sv.box[0].lo, sv.box[0].hi, x.front(), x.back());
}

double overlap(const std::array<double, 2>& e, double lo, double hi) {
  return std::max(0.0, std::min(e[1], hi) - std::max(e[0], lo));
}

// The volume of the node's box inside the sub-volume's domain (every axis; every turn of
// a longitude range).
double box_part(const NodeGeometry& g, const ResolvedSubVolume& sv, const format::Manifest& m) {
  double x = 0;
  const auto ex = extent(g.coords[0]);
  for (int turn : turns_of(sv, m, g.coords[0])) {
    x += overlap(ex, sv.box[0].lo - kFullTurn * turn, sv.box[0].hi - kFullTurn * turn);
  }
  return x * overlap(extent(g.coords[1]), sv.box[1].lo, sv.box[1].hi) *
         overlap(extent(g.coords[2]), sv.box[2].lo, sv.box[2].hi);
}

struct UnionTally {
  std::uint64_t count = 0;
  double worst = 0;  // largest relative volume difference to VTK
};

// Every sub-volume's seamless union at this level: closed and consistently oriented, and
// its volume the sum of VTK's table-clip pipeline over the same nodes (each node's samples
// and request, the longitude range per turn as extraction does it): exact for boxes at
// every level; within 1 % at level 0 where a limit cuts (VTK clips hexahedra linearly,
// the kernel interpolates trilinearly through Kuhn tetrahedra: the two surfaces part
// further on coarse levels, where a cell spans several samples of the field, so there
// only closedness is checked).
void check_unions(const Store& store, const ResolvedScene& scene, const LevelExtraction& result,
                  std::size_t level, StageFindings& f, UnionTally& tally) {
  const format::Manifest& m = store.manifest();
  for (const ResolvedSubVolume& sv : scene.subvolumes) {
    const std::string where = fmt::format("level {} sub-volume {} (seamless union)", level, sv.id);
    const Mesh joined = seamless_union(result, sv.id);
    const MeshCheck check = check_mesh(joined);
    if (!check.closed()) {
      f.problem("{}: {} open, {} non-manifold, {} misoriented edges", where, check.open_edges,
                check.nonmanifold_edges, check.misoriented_edges);
      continue;
    }
    ++tally.count;
    if (!sv.limits.empty() && level != 0) continue;
    double reference = 0;
    for (const NodeExtraction& node : result.nodes) {
      const auto it = std::find_if(node.results.begin(), node.results.end(),
                                   [&](const SubVolumeResult& r) { return r.subvolume_id == sv.id; });
      if (it == node.results.end() || it->outcome != NodeOutcome::kMesh) continue;
      const NodeGeometry g = node_geometry(store, node.node);
      NodeSamples samples;
      samples.coords = g.coords;
      samples.grid_edge = g.grid_edge;
      samples.fields.push_back(store.read_brick(scene.time, 0, node.node).to_vector<float>());
      for (int turn : turns_of(sv, m, g.coords[0])) {
        ExtractRequest request;
        request.subvolume_id = sv.id;
        for (const ResolvedLimit& l : sv.limits) request.limits.push_back({0, l.min, l.max});
        for (int a = 0; a < 3; ++a) request.box[a] = {sv.box[a].lo, sv.box[a].hi};
        request.box[0] = {sv.box[0].lo - kFullTurn * turn, sv.box[0].hi - kFullTurn * turn};
        peers::PaperPipelineOptions options;
        options.measure = false;
        const peers::PeerResult vtk = peers::run_paper_pipeline(samples, request, options);
        reference += enclosed_volume(vtk.mesh);
      }
    }
    const double volume = enclosed_volume(joined);
    const double difference = std::fabs(volume - reference) / std::max(std::fabs(reference), 1e-300);
    const double tolerance = sv.limits.empty() ? 1e-9 : 1e-2;
    if (reference != 0 && difference > tolerance) {
      f.problem("{}: encloses {} but VTK's table clip of the same nodes {} ({:.3g} apart)", where,
                volume, reference, difference);
    }
    if (reference != 0) tally.worst = std::max(tally.worst, difference);
  }
}

}  // namespace

Scene case_scene(const ExtremeCase& c, const format::Manifest& manifest) {
  Scene scene;
  scene.time = 0;
  std::uint32_t id = 1;
  for (const auto& limit : c.limits) {
    SubVolume sv;
    sv.id = id++;
    sv.name = fmt::format("f in [{}, {}]", limit.min ? fmt::format("{}", *limit.min) : "-inf",
                          limit.max ? fmt::format("{}", *limit.max) : "inf");
    sv.limits.push_back(Limit{"f", limit.min, limit.max});
    scene.subvolumes.push_back(std::move(sv));
  }
  if (c.lon_domain) {
    SubVolume sv;
    sv.id = kDomainSubVolume;
    sv.name = "longitude band";
    sv.domain[manifest.x.name] = AxisRange{(*c.lon_domain)[0], (*c.lon_domain)[1]};
    scene.subvolumes.push_back(std::move(sv));
  }
  const std::array<const Axis*, 3> axes{&manifest.x, &manifest.y, &manifest.z};
  for (std::size_t k = 0; k < c.domains.size(); ++k) {
    const ExtremeCase::DomainBox& box = c.domains[k];
    SubVolume sv;
    sv.id = kFirstBoxSubVolume + static_cast<std::uint32_t>(k);
    for (int a = 0; a < 3; ++a) {
      if (box.ranges[a]) sv.domain[axes[a]->name] = AxisRange{(*box.ranges[a])[0], (*box.ranges[a])[1]};
    }
    if (box.with_limit && !c.limits.empty()) {
      sv.limits.push_back(Limit{"f", c.limits.front().min, c.limits.front().max});
    }
    sv.name = fmt::format("box {}{}", k, box.with_limit ? " with a limit" : "");
    scene.subvolumes.push_back(std::move(sv));
  }
  scene.attributes = {"f"};
  return scene;
}

namespace {

// Every node's value range in the input, widened on the coarse levels to the samples
// those levels hold.
std::vector<NodeReference> reference_ranges(const ExtremeCase& c, const Store& store) {
  const OctreeLayout& layout = store.octree();
  const std::vector<std::vector<double>> level0 = reference_level0(c);
  std::vector<NodeReference> ranges = reference_node_stats(layout, level0.at(0));
  for (std::size_t level = 1; level < layout.level_count(); ++level) {
    widen_to_level_samples(ranges, layout, level, read_level_samples<double>(store, 0, 0, level).values);
  }
  return ranges;
}

struct ExtractionTally {
  std::uint64_t meshes = 0, empty = 0, skipped = 0, triangles = 0, pinches = 0;
};

// One level's extraction against the input: what every sub-volume result is checked with.
struct LevelCheck {
  const Store& store;
  const ResolvedScene& scene;
  const std::vector<NodeReference>& ranges;
  const LevelSamples<double>& samples;
  std::size_t level;
  bool longitude_x;
};

bool is_skip(NodeOutcome outcome) {
  return outcome == NodeOutcome::kSkippedValueRange || outcome == NodeOutcome::kSkippedNoData ||
         outcome == NodeOutcome::kSkippedDomain;
}

// A skip, an empty result or a mesh as the node's box and the input's value range call for.
void check_outcome(const std::string& where, const SubVolumeResult& sv,
                   const ResolvedSubVolume& rsv, const NodeReference& r, bool outside_box,
                   StageFindings& f) {
  const bool skip = is_skip(sv.outcome);
  if (sv.outcome == NodeOutcome::kSkippedDomain && !outside_box) {
    f.problem("{}: skipped by domain ({}) but the node meets the domain", where, sv.reason);
  } else if (!rsv.limits.empty() && !(outside_box && (skip || sv.outcome == NodeOutcome::kEmpty))) {
    const ResolvedLimit& limit = rsv.limits.front();
    const NodeOutcome want = std::isnan(r.min) ? NodeOutcome::kSkippedNoData
                             : (r.max < limit.min || r.min > limit.max)
                                 ? NodeOutcome::kSkippedValueRange
                                 : NodeOutcome::kMesh;
    if (want != NodeOutcome::kMesh && sv.outcome != want) {
      f.problem("{}: {} but the input's range [{}, {}] calls for {}", where,
                node_outcome_name(sv.outcome), r.min, r.max, node_outcome_name(want));
    } else if (want == NodeOutcome::kMesh && skip) {
      f.problem("{}: {} ({}) but the input's range [{}, {}] meets [{}, {}]", where,
                node_outcome_name(sv.outcome), sv.reason, r.min, r.max, limit.min, limit.max);
    }
  }
  if (sv.outcome != NodeOutcome::kMesh && !sv.mesh.empty()) {
    f.problem("{}: outcome {} with triangles", where, node_outcome_name(sv.outcome));
  }
}

// The region's volume inside the node: the domain's part of the box without limits,
// between the cells wholly inside and those touching a lone limit.
void check_node_volume(const LevelCheck& lc, const std::string& where, const Mesh& mesh,
                       const ResolvedSubVolume& rsv, const NodeGeometry& g, const IndexBox& box,
                       StageFindings& f) {
  const double volume = enclosed_volume(mesh);
  const double slack = 1e-9 * box_volume(g);
  if (rsv.limits.empty()) {
    const double want = box_part(g, rsv, lc.store.manifest());
    if (std::fabs(volume - want) > slack + 1e-9 * want) {
      f.problem("{}: encloses {} but the domain cuts {} out of the node", where, volume, want);
    }
  } else if (rsv.box != std::array<AxisRange, 3>{AxisRange{-kInfinity, kInfinity},
                                                 AxisRange{-kInfinity, kInfinity},
                                                 AxisRange{-kInfinity, kInfinity}}) {
    // A limit inside a box: checked on the level's union against VTK (check_unions).
  } else {
    const VolumeBounds b = limit_volume_bounds(lc.samples, box, g, rsv.limits.front());
    if (volume < b.lower * (1 - 1e-9) - slack || volume > b.upper * (1 + 1e-9) + slack) {
      f.problem("{}: encloses {}, outside [{}, {}] (cells wholly inside .. touching the limit)",
                where, volume, b.lower, b.upper);
    }
  }
}

// Every sub-volume result of one node.
void check_node(const LevelCheck& lc, const NodeExtraction& node, StageFindings& f,
                ExtractionTally& tally) {
  const OctreeLayout& layout = lc.store.octree();
  const IndexBox box = layout.level_box(layout.key(node.node));
  const NodeGeometry g = node_geometry(lc.store, node.node);
  const bool missing = any_missing(lc.samples, box);
  const NodeReference& r = lc.ranges[node.node];
  for (std::size_t s = 0; s < node.results.size(); ++s) {
    const SubVolumeResult& sv = node.results[s];
    const ResolvedSubVolume& rsv = lc.scene.subvolumes[s];
    const std::string where =
        fmt::format("level {} node {} sub-volume {}", lc.level, node.node, sv.subvolume_id);
    const bool skip = is_skip(sv.outcome);
    tally.skipped += skip ? 1 : 0;
    tally.empty += sv.outcome == NodeOutcome::kEmpty ? 1 : 0;
    const bool outside_box = box_part(g, rsv, lc.store.manifest()) == 0;
    check_outcome(where, sv, rsv, r, outside_box, f);
    if (skip) continue;
    if (sv.outcome == NodeOutcome::kMesh) {
      ++tally.meshes;
      tally.triangles += sv.mesh.triangle_count();
      check_mesh_content(sv.mesh, g, missing, 1e-12, true, lc.longitude_x, f, where,
                         &tally.pinches);
    }
    check_node_volume(lc, where, sv.mesh, rsv, g, box, f);
  }
}

}  // namespace

StageFindings check_extraction(const ExtremeCase& c, const Store& store, int threads) {
  StageFindings f;
  const OctreeLayout& layout = store.octree();
  const ResolvedScene scene = resolve_scene(case_scene(c, store.manifest()), store.manifest(), c.name);
  const std::vector<NodeReference> ranges = reference_ranges(c, store);
  ExtractionTally tally;
  UnionTally unions;
  const bool longitude_x = store.manifest().x.kind == AxisKind::kLongitude;
  std::vector<std::string> per_level;
  for (const std::size_t level : levels_to_check(layout)) {
    LevelExtractionOptions options;
    options.level = static_cast<std::uint32_t>(level);
    options.threads = threads;
    options.cache_bytes = 16 << 20;
    LevelExtraction result;
    try {
      result = extract_level(store, scene, options);
    } catch (const Error& e) {
      if (!is_refusal(e)) throw;
      f.refusal = fmt::format("level {}: {}", level, e.what());
      return f;
    }
    const LevelSamples<double> samples = read_level_samples<double>(store, 0, 0, level);
    const LevelCheck lc{store, scene, ranges, samples, level, longitude_x};
    for (const NodeExtraction& node : result.nodes) check_node(lc, node, f, tally);
    if (c.check_unions) check_unions(store, scene, result, level, f, unions);
    per_level.push_back(fmt::format("level {}: {} nodes", level, result.nodes.size()));
  }
  f.summary = fmt::format("{}; {} meshes ({} triangles), {} empty, {} skipped, all checked{}{}",
                          fmt::join(per_level, ", "), tally.meshes, tally.triangles, tally.empty,
                          tally.skipped,
                          tally.pinches ? fmt::format("; {} edges where the region touches itself "
                                                      "(4 triangles each, balanced)", tally.pinches)
                                        : std::string(),
                          c.check_unions ? fmt::format("; {} seamless unions closed, volumes "
                                                       "within {:.2g} of VTK's table clip "
                                                       "(boxes every level, limits level 0)",
                                                       unions.count, unions.worst)
                                         : std::string());
  return f;
}

namespace {

serve::ServerConfig check_server_config(const std::filesystem::path& root, int threads) {
  serve::ServerConfig config;
  config.root = root;
  config.listen = net::Endpoint{"127.0.0.1", 0};
  std::mt19937_64 random(std::random_device{}());
  config.token = fmt::format("{:016x}", random());
  config.threads = static_cast<unsigned>(std::max(threads, 1));
  config.cache_bytes = 16 << 20;
  config.max_clients = 2;
  config.server_name = "strielad robustness check";
  return config;
}

// The root and the coarse levels first, then level-0 nodes, at most 64 in all.
std::vector<protocol::NodePriority> coarse_first_cut(const OctreeLayout& layout) {
  std::vector<protocol::NodePriority> cut;
  for (NodeId n = static_cast<NodeId>(layout.node_count()); n-- > 0 && cut.size() < 64;) {
    cut.push_back({n, static_cast<float>(cut.size())});
  }
  return cut;
}

// What the server answered so far.
struct ServerAnswers {
  std::map<NodeId, bool> answered;
  std::uint64_t meshes = 0, failures = 0;
  std::string first_failure;
};

// A node's result over the wire against batch extraction of the same node.
void compare_with_batch(const protocol::NodeResult& r, const Store& store,
                        const ResolvedScene& resolved, StageFindings& f, ServerAnswers& answers) {
  const NodeExtraction batch = extract_node(store, nullptr, resolved, 0, r.node);
  if (r.subvolumes.size() != batch.results.size()) {
    f.problem("node {}: {} sub-volumes, batch extraction {}", r.node, r.subvolumes.size(),
              batch.results.size());
    return;
  }
  const NodeGeometry g = node_geometry(store, r.node);
  for (std::size_t s = 0; s < batch.results.size(); ++s) {
    const auto& got = r.subvolumes[s];
    const auto& want = batch.results[s];
    const std::string where = fmt::format("node {} sub-volume {}", r.node, want.subvolume_id);
    if (got.outcome != want.outcome || got.reason != want.reason) {
      f.problem("{}: {} ({}) over the wire, {} ({}) in batch", where,
                node_outcome_name(got.outcome), got.reason, node_outcome_name(want.outcome),
                want.reason);
      continue;
    }
    if (got.mesh.triangles != want.mesh.triangles || got.mesh.face_kinds != want.mesh.face_kinds) {
      f.problem("{}: {} triangles over the wire, {} in batch", where, got.mesh.triangle_count(),
                want.mesh.triangle_count());
      continue;
    }
    if (got.outcome != NodeOutcome::kMesh) continue;
    ++answers.meshes;
    bool missing = false;
    for (float v : want.mesh.attributes.at(0)) missing = missing || std::isnan(v);
    // Positions are quantized to 1/65535 of the mesh's box per axis.
    check_mesh_content(got.mesh, g, missing, 1.0 / 65535.0, false,
                       store.manifest().x.kind == AxisKind::kLongitude, f, where, nullptr);
  }
}

// The scene the server was asked for and what its answers are compared with.
struct ServerCheck {
  const client::ServerClient& client;
  std::size_t cut_size;
  std::chrono::milliseconds timeout;
  std::uint32_t generation;
  const Store& store;
  const ResolvedScene& resolved;
};

// One message from the server; false when no more are to be read (timeout, error).
bool take_message(const std::optional<protocol::Message>& message, const ServerCheck& sc,
                  StageFindings& f, ServerAnswers& answers) {
  if (!message) {
    f.problem("{} of {} nodes answered within {} ms ({})", answers.answered.size(), sc.cut_size,
              sc.timeout.count(), sc.client.close_reason());
    return false;
  }
  if (auto* e = std::get_if<protocol::ErrorMessage>(&*message)) {
    f.problem("server error: {}", e->message);
    return false;
  }
  if (auto* failed = std::get_if<protocol::NodeFailed>(&*message)) {
    answers.answered[failed->node] = true;
    if (answers.failures++ == 0) answers.first_failure = failed->message;
    if (failed->code == protocol::WireError::kInternal) {
      f.problem("node {} failed with an internal error: {}", failed->node, failed->message);
    }
    return true;
  }
  auto* r = std::get_if<protocol::NodeResult>(&*message);
  if (!r) return true;
  if (r->generation != sc.generation) {
    f.problem("node {}: result of generation {}, expected {}", r->node, r->generation,
              sc.generation);
  }
  if (answers.answered.count(r->node) != 0) f.problem("node {} answered twice", r->node);
  answers.answered[r->node] = true;
  compare_with_batch(*r, sc.store, sc.resolved, f, answers);
  return true;
}

}  // namespace

StageFindings check_server(const ExtremeCase& c, const std::filesystem::path& root,
                           const std::string& dataset, int threads,
                           std::chrono::milliseconds timeout) {
  StageFindings f;
  const serve::ServerConfig config = check_server_config(root, threads);
  serve::Server server(config);
  server.start();
  client::ClientOptions options;
  options.client_name = "strielad-bench robustness";
  options.token = *config.token;
  options.timeout = timeout;
  auto client = client::ServerClient::connect(net::Endpoint{"127.0.0.1", server.port()}, options);
  client->open_dataset(dataset);
  const Scene scene = case_scene(c, client->manifest());
  const auto started = client->set_scene(scene);
  const std::vector<protocol::NodePriority> cut = coarse_first_cut(client->octree());
  client->update_cut(cut, {}, {});

  const auto store = Store::open(root / dataset);
  const ResolvedScene resolved = resolve_scene(scene, store->manifest(), c.name);
  const ServerCheck sc{*client, cut.size(), timeout, started.generation, *store, resolved};
  ServerAnswers answers;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (answers.answered.size() < cut.size()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    const auto message = left.count() > 0 ? client->wait(left) : std::nullopt;
    if (!take_message(message, sc, f, answers)) break;
  }
  if (answers.failures > 0 && f.ok()) {
    if (answers.failures == answers.answered.size()) {
      f.refusal = fmt::format("every node failed: {}", answers.first_failure);
    } else {
      f.problem("{} of {} nodes failed, e.g.: {}", answers.failures, answers.answered.size(),
                answers.first_failure);
    }
  }
  f.summary = fmt::format("{} nodes answered, {} meshes, equal to batch extraction",
                          answers.answered.size(), answers.meshes);
  client.reset();
  server.stop();
  return f;
}

}  // namespace strielad::robust
