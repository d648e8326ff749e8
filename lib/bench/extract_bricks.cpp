// SPDX-License-Identifier: Apache-2.0
#include "bench/extract_bricks.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "bench/latency_stats.h"
#include "bench/stopwatch.h"
#include "core/error.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extraction.h"
#include "extract/node_extractor.h"
#include "peers/openvdb_volume_to_mesh.h"
#include "peers/vtk_paper_pipeline.h"
#include "store/store.h"

namespace strielad::bench {

double ExtractCase::threshold() const {
  const CaseLimit& l = limits.at(select);
  return std::isfinite(l.min) ? l.min : l.max;
}

std::string case_label(const std::vector<CaseLimit>& limits) {
  std::string out;
  for (const CaseLimit& l : limits) {
    if (!out.empty()) out += " and ";
    if (std::isfinite(l.min) && std::isfinite(l.max)) {
      out += fmt::format("{} <= {} <= {}", l.min, l.var, l.max);
    } else if (std::isfinite(l.min)) {
      out += fmt::format("{} >= {}", l.var, l.min);
    } else {
      out += fmt::format("{} <= {}", l.var, l.max);
    }
  }
  return out;
}

std::vector<ExtractCase> default_brick_cases() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<ExtractCase> cases = {
      {"cloud", "", {{"clw", 1e-5, kInf}}, 0},
      {"dense", "", {{"ta", -kInf, 260.0}}, 0},
      {"three", "", {{"clw", 1e-5, kInf}, {"ta", -kInf, 273.15}, {"ua", 0.0, kInf}}, 0},
  };
  for (auto& c : cases) c.label = case_label(c.limits);
  return cases;
}

std::vector<ExtractCase> default_level_cases() {
  auto cases = default_brick_cases();
  cases.pop_back();
  return cases;
}

std::size_t BrickGroup::index_of(std::string_view contender) const {
  for (std::size_t i = 0; i < contenders.size(); ++i) {
    if (contenders[i] == contender) return i;
  }
  return std::string::npos;
}

namespace {

// Full-size level-0 nodes whose exact value range straddles the case's threshold.
std::vector<NodeId> candidate_nodes(const Store& store, const ExtractCase& c) {
  const OctreeLayout& octree = store.octree();
  const auto variable =
      static_cast<std::uint32_t>(store.manifest().variable_index(c.limits.at(c.select).var));
  const double t = c.threshold();
  const auto entries = store.index(0, variable);
  std::vector<NodeId> out;
  const std::size_t count = octree.level(0).node_count();
  for (std::size_t i = 0; i < count; ++i) {
    const auto id = static_cast<NodeId>(octree.level(0).first_node + i);
    const IndexBox box = octree.level_box(octree.key(id));
    bool full = true;
    for (int a = 0; a < 3; ++a) full = full && box.extent(a) == octree.brick() + 1u;
    if (!full) continue;
    const format::IndexEntry& e = entries[id];
    if (e.has_valid_data() && e.min < t && t < e.max) out.push_back(id);
  }
  return out;
}

struct Loaded {
  NodeSamples samples;
  ExtractRequest request;
  std::size_t select_field = 0;
  double node_volume = 0;
};

Loaded load_node(const Store& store, const ExtractCase& c, NodeId node) {
  Loaded out;
  const NodeGeometry g = node_geometry(store, node);
  out.samples.coords = g.coords;
  out.samples.grid_edge = g.grid_edge;
  out.node_volume = 1;
  for (int a = 0; a < 3; ++a) {
    out.node_volume *= std::fabs(g.coords[a].back() - g.coords[a].front());
  }
  std::vector<std::string> vars;
  out.request.subvolume_id = 1;
  for (std::size_t i = 0; i < c.limits.size(); ++i) {
    const CaseLimit& l = c.limits[i];
    auto it = std::find(vars.begin(), vars.end(), l.var);
    if (it == vars.end()) {
      const auto v = static_cast<std::uint32_t>(store.manifest().variable_index(l.var));
      out.samples.fields.push_back(store.read_brick(0, v, node).to_vector<float>());
      vars.push_back(l.var);
      it = vars.end() - 1;
    }
    const auto field = static_cast<std::uint32_t>(it - vars.begin());
    out.request.limits.push_back({field, l.min, l.max});
    if (i == c.select) out.select_field = field;
  }
  return out;
}

// vtkFlyingEdges3D's open iso-surface closed by the paper pipeline's node-face
// triangles: the two meet on the node's faces at the same lattice-edge crossings, so the
// difference to the paper's volume is the difference of the limit surfaces alone.
// FlyingEdges orients towards larger values (outward of field <= iso).
double closed_flying_edges_volume(const Mesh& fe, const Mesh& paper, bool region_is_above) {
  Mesh m;
  m.positions = fe.positions;
  m.triangles = fe.triangles;
  if (region_is_above) {
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
  }
  const auto offset = static_cast<std::uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), paper.positions.begin(), paper.positions.end());
  for (std::size_t t = 0; t < paper.triangles.size(); ++t) {
    if (paper.face_kinds[t] == FaceKind::kLimit) continue;
    const auto& tri = paper.triangles[t];
    m.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
  }
  return enclosed_volume(m);
}

}  // namespace

double trilinear_region_volume(const NodeSamples& samples, const ExtractRequest& request,
                               int subsamples) {
  const auto dims = samples.dims();
  const std::size_t sx = 1, sy = dims[0], sz = dims[0] * dims[1];
  const std::array<std::size_t, 8> offsets{0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
  const std::size_t n_limits = request.limits.size();
  std::vector<std::array<float, 8>> corners(n_limits);
  const double step = 1.0 / subsamples;
  double volume = 0;
  for (std::size_t z = 0; z + 1 < dims[2]; ++z) {
    const double hz = std::fabs(samples.coords[2][z + 1] - samples.coords[2][z]);
    for (std::size_t y = 0; y + 1 < dims[1]; ++y) {
      const double hy = std::fabs(samples.coords[1][y + 1] - samples.coords[1][y]);
      for (std::size_t x = 0; x + 1 < dims[0]; ++x) {
        const double cell = hz * hy * std::fabs(samples.coords[0][x + 1] - samples.coords[0][x]);
        const std::size_t base = (z * dims[1] + y) * dims[0] + x;
        bool all_inside = true, outside = false;
        for (std::size_t l = 0; l < n_limits && !outside; ++l) {
          const ExtractLimit& lim = request.limits[l];
          const auto& f = samples.fields[lim.field];
          int in = 0;
          for (int k = 0; k < 8; ++k) {
            const float v = f[base + offsets[k]];
            corners[l][k] = v;
            in += (v >= lim.min && v <= lim.max) ? 1 : 0;
          }
          // NaN corners count as neither: such a cell is sub-sampled (NaN is outside).
          bool below = true, above = true;
          for (int k = 0; k < 8; ++k) {
            below = below && corners[l][k] < lim.min;
            above = above && corners[l][k] > lim.max;
          }
          outside = below || above;
          all_inside = all_inside && in == 8;
        }
        if (outside) continue;
        if (all_inside) {
          volume += cell;
          continue;
        }
        int hits = 0;
        for (int k = 0; k < subsamples; ++k) {
          const double fz = (k + 0.5) * step;
          for (int j = 0; j < subsamples; ++j) {
            const double fy = (j + 0.5) * step;
            for (int i = 0; i < subsamples; ++i) {
              const double fx = (i + 0.5) * step;
              bool ok = true;
              for (std::size_t l = 0; l < n_limits && ok; ++l) {
                const auto& c = corners[l];
                const double x00 = c[0] + fx * (c[1] - c[0]), x10 = c[2] + fx * (c[3] - c[2]);
                const double x01 = c[4] + fx * (c[5] - c[4]), x11 = c[6] + fx * (c[7] - c[6]);
                const double y0 = x00 + fy * (x10 - x00), y1 = x01 + fy * (x11 - x01);
                const double v = y0 + fz * (y1 - y0);
                ok = v >= request.limits[l].min && v <= request.limits[l].max;
              }
              hits += ok ? 1 : 0;
            }
          }
        }
        volume += cell * hits / (double(subsamples) * subsamples * subsamples);
      }
    }
  }
  return volume;
}

NodeSamples no_surface_samples(const NodeSamples& samples, std::size_t field, double iso,
                               bool region_is_above) {
  NodeSamples out = samples;
  const double step = std::fabs(iso) + 1;
  std::fill(out.fields.at(field).begin(), out.fields.at(field).end(),
            static_cast<float>(region_is_above ? iso - step : iso + step));
  return out;
}

namespace {

// The contenders of a group on `c`: the kernel and the paper pipeline, plus the
// single-threshold peers when the case has one limit.
BrickGroup plan_group(const Store& store, const ExtractCase& c, const BrickGroupOptions& options) {
  BrickGroup g;
  g.extract_case = c;
  g.brick = store.octree().brick();
  g.repeat = std::max(1, options.repeat);
  g.contenders = {kKernel, kPaper};
  if (c.one_limit()) {
    g.contenders.push_back(kFlyingEdges);
    if (options.openvdb) g.contenders.push_back(kOpenVdb);
  }
  return g;
}

// Up to options.bricks candidate nodes drawn at random (seeded), in node order.
std::vector<NodeId> pick_nodes(const Store& store, const ExtractCase& c,
                               const BrickGroupOptions& options, BrickGroup& g) {
  std::vector<NodeId> nodes = candidate_nodes(store, c);
  g.candidates = nodes.size();
  std::mt19937_64 rng(options.seed);
  std::shuffle(nodes.begin(), nodes.end(), rng);
  if (nodes.size() > options.bricks) nodes.resize(options.bricks);
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

void expect_nothing(const Mesh& m, const std::string& who, NodeId node) {
  if (m.triangle_count() != 0) {
    throw make_error(ErrorCode::kInternal,
                     "bench: {} made {} triangles on node {} with nothing to extract", who,
                     m.triangle_count(), node);
  }
}

// One brick's turns: its samples, the same samples with nothing to extract (kernel and
// FlyingEdges also run on those, right after their own turn), and the first round's meshes.
struct BrickTurns {
  BrickTurns(const Loaded& samples, NodeId id, double threshold)
      : in(samples), node(id), iso(threshold) {}

  const Loaded& in;
  NodeId node;
  double iso;
  bool with_no_surface = false;
  NodeSamples empty;
  peers::PaperPipelineOptions paper_options;
  std::vector<std::vector<double>> no_surface_rounds;
  Mesh kernel_mesh, paper_mesh, fe_mesh;
};

// Contender `i` (`who`) once on the brick in round `r`; its seconds.
double time_turn(const std::string& who, std::size_t i, int r, BrickTurns& t, BrickRun& run) {
  const Loaded& in = t.in;
  if (who == kKernel) {
    ExtractStats stats;
    const Stopwatch w;
    Mesh m = extract_node_mesh(in.samples, in.request, &stats);
    const double seconds = w.seconds();
    if (r == 0) {
      run.kernel_stats = stats;
      t.kernel_mesh = std::move(m);
    }
    if (t.with_no_surface) {
      const Stopwatch e;
      const Mesh none = extract_node_mesh(t.empty, in.request, nullptr);
      t.no_surface_rounds[i].push_back(e.seconds());
      if (r == 0) expect_nothing(none, who, t.node);
    }
    return seconds;
  }
  if (who == kPaper) {
    peers::PeerResult p = peers::run_paper_pipeline(in.samples, in.request, t.paper_options);
    if (r == 0) t.paper_mesh = std::move(p.mesh);
    return p.seconds;
  }
  if (who == kFlyingEdges) {
    peers::PeerResult p = peers::run_flying_edges(in.samples, in.select_field, t.iso, {1});
    if (r == 0) t.fe_mesh = std::move(p.mesh);
    const peers::PeerResult none = peers::run_flying_edges(t.empty, in.select_field, t.iso, {1});
    t.no_surface_rounds[i].push_back(none.seconds);
    if (r == 0) expect_nothing(none.mesh, who, t.node);
    return p.seconds;
  }
  peers::PeerResult p =
      peers::run_openvdb_volume_to_mesh(in.samples, in.select_field, t.iso, {.threads = 1});
  if (r == 0) run.triangles[i] = run.limit_triangles[i] = p.mesh.triangle_count();
  return p.seconds;
}

// Triangles, volumes and cleanliness of the first round's meshes, and the reference volume.
void measure_meshes(const BrickGroup& g, const BrickTurns& t, bool region_is_above,
                    BrickRun& run) {
  const std::size_t ik = g.index_of(kKernel), ip = g.index_of(kPaper);
  run.triangles[ik] = t.kernel_mesh.triangle_count();
  run.volume[ik] = enclosed_volume(t.kernel_mesh);
  run.kernel_clean = check_mesh(t.kernel_mesh).clean();
  run.reference_volume = trilinear_region_volume(t.in.samples, t.in.request, kReferenceSubsamples);
  run.triangles[ip] = t.paper_mesh.triangle_count();
  auto limit_count = [](const Mesh& m) {
    return static_cast<std::uint64_t>(
        std::count(m.face_kinds.begin(), m.face_kinds.end(), FaceKind::kLimit));
  };
  run.limit_triangles[ik] = limit_count(t.kernel_mesh);
  run.limit_triangles[ip] = limit_count(t.paper_mesh);
  run.volume[ip] = enclosed_volume(t.paper_mesh);
  if (const std::size_t ife = g.index_of(kFlyingEdges); ife != std::string::npos) {
    run.triangles[ife] = run.limit_triangles[ife] = t.fe_mesh.triangle_count();
    run.volume[ife] = closed_flying_edges_volume(t.fe_mesh, t.paper_mesh, region_is_above);
  }
}

// Every contender `g.repeat` times on one node, taking turns, then the meshes measured.
BrickRun run_brick(const Store& store, const BrickGroup& g, NodeId node) {
  const ExtractCase& c = g.extract_case;
  const bool region_is_above = std::isfinite(c.limits.at(c.select).min);
  const std::size_t n_contenders = g.contenders.size();
  const Loaded in = load_node(store, c, node);
  BrickRun run;
  run.node = node;
  const auto dims = in.samples.dims();
  run.cells = std::uint64_t(dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
  run.node_volume = in.node_volume;
  run.rounds.assign(n_contenders, {});
  run.triangles.assign(n_contenders, 0);
  run.limit_triangles.assign(n_contenders, 0);
  run.volume.assign(n_contenders, std::numeric_limits<double>::quiet_NaN());

  BrickTurns t(in, node, c.threshold());
  t.with_no_surface = g.index_of(kFlyingEdges) != std::string::npos;
  if (t.with_no_surface) {
    t.empty = no_surface_samples(in.samples, in.select_field, t.iso, region_is_above);
  }
  t.paper_options.threads = 1;
  t.paper_options.measure = false;
  t.no_surface_rounds.resize(n_contenders);
  for (int r = 0; r < g.repeat; ++r) {
    // Contenders take turns: each round starts with the next one.
    for (std::size_t k = 0; k < n_contenders; ++k) {
      const std::size_t i = (k + static_cast<std::size_t>(r)) % n_contenders;
      run.rounds[i].push_back(time_turn(g.contenders[i], i, r, t, run));
    }
  }
  for (std::size_t i = 0; i < n_contenders; ++i) {
    run.seconds.push_back(median(run.rounds[i]));
    run.no_surface_seconds.push_back(t.no_surface_rounds[i].empty()
                                         ? std::numeric_limits<double>::quiet_NaN()
                                         : median(t.no_surface_rounds[i]));
  }
  measure_meshes(g, t, region_is_above, run);
  return run;
}

}  // namespace

BrickGroup run_brick_group(const Store& store, const ExtractCase& c,
                           const BrickGroupOptions& options) {
  const Stopwatch clock;
  BrickGroup g = plan_group(store, c, options);
  const std::vector<NodeId> nodes = pick_nodes(store, c, options, g);
  spdlog::info("bench: {} ({}), brick {}: {} of {} cut nodes, {} round(s), contenders {}", c.name,
               c.label, g.brick, nodes.size(), g.candidates, g.repeat,
               fmt::join(g.contenders, ", "));
  for (std::size_t b = 0; b < nodes.size(); ++b) {
    g.runs.push_back(run_brick(store, g, nodes[b]));
    if ((b + 1) % 50 == 0 && b + 1 < nodes.size()) {
      spdlog::info("bench:   {}/{} bricks, {:.0f} s", b + 1, nodes.size(), clock.seconds());
    }
  }
  g.seconds = clock.seconds();
  return g;
}

}  // namespace strielad::bench
