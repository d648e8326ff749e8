// SPDX-License-Identifier: Apache-2.0
#include "extract/node_extraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>

#include "core/error.h"
#include "format/geometry_field.h"
#include "grid/longitude_turns.h"
#include "extract/geographic_conditions.h"
#include "extract/node_extractor.h"
#include "extract/slice_extraction.h"
#include "store/brick_cache.h"
#include "store/store.h"

namespace strielad {

std::string_view node_outcome_name(NodeOutcome outcome) {
  switch (outcome) {
    case NodeOutcome::kMesh: return "mesh";
    case NodeOutcome::kEmpty: return "empty";
    case NodeOutcome::kSkippedValueRange: return "skipped-value-range";
    case NodeOutcome::kSkippedDomain: return "skipped-domain";
    case NodeOutcome::kSkippedNoData: return "skipped-no-data";
  }
  return "unknown";
}

NodeGeometry node_geometry(const Store& store, NodeId node) {
  const OctreeLayout& octree = store.octree();
  const NodeKey key = octree.key(node);
  const IndexBox box = octree.level_box(key);
  const format::Manifest& m = store.manifest();
  const std::array<const Axis*, 3> axes{&m.x, &m.y, &m.z};
  NodeGeometry g;
  const LevelShape& shape = octree.level(key.level);
  for (int a = 0; a < 3; ++a) {
    g.grid_edge[2 * a] = box.lo[a] == 0;
    g.grid_edge[2 * a + 1] = box.hi[a] + 1 >= shape.samples[a];
    for (std::size_t c = box.lo[a]; c <= box.hi[a]; ++c) {
      g.fine[a].push_back(octree.fine_index(key.level, a, c));
      g.coords[a].push_back(axes[a]->values[g.fine[a].back()]);
    }
  }
  return g;
}

bool limit_excludes_node(const format::IndexEntry& entry, const ResolvedLimit& limit) {
  return !entry.has_valid_data() || entry.max < limit.min || entry.min > limit.max;
}

namespace {

// Why the limit's range excludes the node, or "" when it may not.
std::string range_miss(const format::IndexEntry& e, const ResolvedLimit& limit,
                       const format::Manifest& m) {
  if (limit_excludes_node(e, limit)) {
    return fmt::format("{} in [{}, {}] never within [{}, {}]", format::variable_name(m, limit.variable),
                       e.min, e.max, limit.min, limit.max);
  }
  return "";
}

bool disjoint(const std::vector<double>& coords, const AxisRange& range) {
  const double lo = std::min(coords.front(), coords.back());
  const double hi = std::max(coords.front(), coords.back());
  return range.hi < lo || range.lo > hi;
}

// What extraction of one sub-volume needs: the limits that may cut the node, and on a
// longitude x axis the whole turns at which its longitude range meets the node
// (grid/longitude_turns.h; {0} otherwise).
struct SubVolumePlan {
  std::size_t subvolume;
  std::vector<ResolvedLimit> limits;
  std::vector<int> turns{0};
  // A geographic box on a mapped grid: its conditions at the node's horizontal samples.
  std::vector<std::vector<double>> geographic{};
  // A geographic height range on terrain-following levels that may cut the node: two
  // conditions on the geometry's height field, h - lo and hi - h.
  std::optional<AxisRange> geometry_height{};
};

// A geographic height range on the node, from the index of the geometry's height field:
// the node is skipped when the field's range misses it; no condition is needed when the
// field lies within it.
std::optional<AxisRange> plan_geometry_height(const Store& store, const AxisRange& height,
                                              std::uint32_t step, NodeId node,
                                              SubVolumeResult& r) {
  const format::Manifest& m = store.manifest();
  const std::uint32_t field = *format::geometry_field_variable(m);
  const format::IndexEntry& e = store.node_entry(step, field, node);
  if (limit_excludes_node(e, ResolvedLimit{field, height.lo, height.hi})) {
    r.outcome = NodeOutcome::kSkippedDomain;
    r.reason = fmt::format("height range [{}, {}] misses the node ({} in [{}, {}])", height.lo,
                           height.hi, format::variable_name(m, field), e.min, e.max);
    return std::nullopt;
  }
  if (e.min >= height.lo && e.max <= height.hi) return std::nullopt;
  return height;
}

bool bounded(const AxisRange& r) {
  return r.lo != -std::numeric_limits<double>::infinity() ||
         r.hi != std::numeric_limits<double>::infinity();
}

// Decides per sub-volume from the index and the geometry alone: fills the skipped
// results' outcome and reason, returns the plans of the others.
std::vector<SubVolumePlan> plan_subvolumes(const Store& store, const ResolvedScene& scene,
                                           std::uint32_t step, const NodeGeometry& geometry,
                                           NodeId node, std::vector<SubVolumeResult>& results) {
  const format::Manifest& m = store.manifest();
  const std::array<std::string_view, 3> axis_names{m.x.name, m.y.name, m.z.name};
  std::vector<SubVolumePlan> plans;
  results.resize(scene.subvolumes.size());
  for (std::size_t i = 0; i < scene.subvolumes.size(); ++i) {
    const ResolvedSubVolume& sv = scene.subvolumes[i];
    SubVolumeResult& r = results[i];
    r.subvolume_id = sv.id;
    SubVolumePlan plan{i, {}};
    const bool wraps = m.x.kind == AxisKind::kLongitude && bounded(sv.box[0]);
    if (wraps) {
      const auto& x = geometry.coords[0];
      plan.turns = longitude_turns(sv.box[0].lo, sv.box[0].hi, x.front(), x.back());
    }
    for (int a = 0; a < 3 && r.reason.empty(); ++a) {
      if (a == 0 ? plan.turns.empty() : disjoint(geometry.coords[a], sv.box[a])) {
        r.outcome = NodeOutcome::kSkippedDomain;
        r.reason = fmt::format("{} range [{}, {}] misses the node", axis_names[a], sv.box[a].lo,
                               sv.box[a].hi);
      }
    }
    if (sv.geographic && r.reason.empty()) {
      plan.geographic = geographic_conditions(*sv.geographic, *GeoLocation::of(store), geometry.fine[0],
                                              geometry.fine[1]);
      // A condition below zero at every sample: its interpolant is below zero everywhere.
      for (const auto& c : plan.geographic) {
        if (std::all_of(c.begin(), c.end(), [](double v) { return v < 0; })) {
          r.outcome = NodeOutcome::kSkippedDomain;
          r.reason = fmt::format("geographic box{}{} misses the node",
                                 sv.geographic->lon ? fmt::format(" lon [{}, {}]", sv.geographic->lon->lo, sv.geographic->lon->hi) : "",
                                 sv.geographic->lat ? fmt::format(" lat [{}, {}]", sv.geographic->lat->lo, sv.geographic->lat->hi) : "");
          break;
        }
      }
    }
    if (sv.geometry_height && r.reason.empty()) {
      plan.geometry_height = plan_geometry_height(store, *sv.geometry_height, step, node, r);
    }
    for (const ResolvedLimit& limit : sv.limits) {
      if (!r.reason.empty()) break;
      const format::IndexEntry& e = store.node_entry(step, limit.variable, node);
      if (!e.has_valid_data()) {
        r.outcome = NodeOutcome::kSkippedNoData;
        r.reason = fmt::format("{} has no valid sample in the node", format::variable_name(m, limit.variable));
        break;
      }
      r.reason = range_miss(e, limit, m);
      if (!r.reason.empty()) {
        r.outcome = NodeOutcome::kSkippedValueRange;
        break;
      }
      // A constant brick (no fill: every sample equals the constant) inside the limit:
      // the limit cannot cut the node and its brick is not needed.
      const bool inside = e.kind == format::BrickKind::kConstant && e.constant >= limit.min &&
                          e.constant <= limit.max;
      if (!inside) plan.limits.push_back(limit);
    }
    if (r.reason.empty()) plans.push_back(std::move(plan));
  }
  return plans;
}

// A node with a single sample along some axis (a grid of one level, say) has no cells:
// no region of it has volume, so every sub-volume that is not skipped is empty, as a
// domain range with lo = hi is (formats/scene.md, "Semantics"). No brick is read.
bool has_no_cells(const NodeGeometry& geometry) {
  for (const auto& coords : geometry.coords) {
    if (coords.size() < 2) return true;
  }
  return false;
}

void check_node(const Store& store, NodeId node) {
  if (!store.octree().contains(node)) {
    throw make_error(ErrorCode::kNotFound, "node {} is not in the octree of {} ({} nodes)", node,
                     store.path().string(), store.octree().node_count());
  }
}

void throw_if_stopped(const std::stop_token& stop, const Store& store, NodeId node) {
  if (stop.stop_requested()) {
    throw make_error(ErrorCode::kCancelled, "{}: extraction of node {} cancelled",
                     store.path().string(), node);
  }
}

// Float buffers for the node's fields, taken from the caller's pool (a fresh vector
// per brick would be allocated and zeroed before every copy). Returned on scope exit.
class FieldBuffers {
 public:
  FieldBuffers(NodeSamples& ns, std::vector<std::vector<float>>& pool) : ns_(ns), pool_(pool) {}
  ~FieldBuffers() {
    for (auto& f : ns_.fields) pool_.push_back(std::move(f));
  }
  FieldBuffers(const FieldBuffers&) = delete;
  FieldBuffers& operator=(const FieldBuffers&) = delete;

  // Appends the brick's samples as floats (missing = NaN), as Brick::to_vector<float>,
  // except that float64 values beyond the float range are clamped to +-FLT_MAX: a valid
  // sample stays valid (an infinity would read as missing and poison attributes).
  void add(const Brick& brick) {
    std::vector<float> out;
    if (!pool_.empty()) {
      out = std::move(pool_.back());
      pool_.pop_back();
    }
    out.resize(brick.sample_count());
    if (brick.kind == format::BrickKind::kData && brick.dtype == DType::kFloat32) {
      std::memcpy(out.data(), brick.bytes.data(), brick.bytes.size());
    } else {
      constexpr double kMax = std::numeric_limits<float>::max();
      for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = static_cast<float>(std::clamp(brick.sample(i), -kMax, kMax));  // NaN stays NaN
      }
    }
    ns_.fields.push_back(std::move(out));
  }

 private:
  NodeSamples& ns_;
  std::vector<std::vector<float>>& pool_;
};

// On a periodic longitude axis the faces on the grid's first and last meridian are the
// seam: where the node's part of the longitude range goes on across it, the node across
// the seam holds the rest and the faces are shared (node-boundary); where it does not
// (no range, or one ending there) they are the region's edge in this frame (grid-edge).
void seam_faces(const NodeGeometry& geometry, const std::array<double, 2>& range,
                std::array<bool, 6>& grid_edge) {
  const auto& x = geometry.coords[0];
  const double lo = std::min(x.front(), x.back()), hi = std::max(x.front(), x.back());
  const bool ascending = x.back() >= x.front();
  // Sides 0 and 1 are the node's first and last sample along x.
  for (int side = 0; side < 2; ++side) {
    if (!geometry.grid_edge[side]) continue;
    const bool at_low_end = (side == 0) == ascending;
    const bool beyond = at_low_end ? range[0] < lo : range[1] > hi;
    grid_edge[side] = !(beyond && std::isfinite(range[0]) && std::isfinite(range[1]));
  }
}

// `piece` appended to `mesh` (vertices, triangles, face kinds, normals, attributes).
void append_mesh(Mesh& mesh, Mesh piece) {
  if (mesh.positions.empty()) {
    mesh = std::move(piece);
    return;
  }
  const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), piece.positions.begin(), piece.positions.end());
  mesh.normals.insert(mesh.normals.end(), piece.normals.begin(), piece.normals.end());
  for (const auto& t : piece.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  mesh.face_kinds.insert(mesh.face_kinds.end(), piece.face_kinds.begin(), piece.face_kinds.end());
  for (std::size_t a = 0; a < mesh.attributes.size() && a < piece.attributes.size(); ++a) {
    mesh.attributes[a].insert(mesh.attributes[a].end(), piece.attributes[a].begin(),
                              piece.attributes[a].end());
  }
}

void add_stats(ExtractStats& total, const ExtractStats& s) {
  total.cells += s.cells;
  total.inside_cells += s.inside_cells;
  total.cut_cells += s.cut_cells;
  total.table_cells += s.table_cells;
  total.simple_tets += s.simple_tets;
  total.clipped_tets += s.clipped_tets;
  total.conditions = std::max(total.conditions, s.conditions);
  total.empty_by_condition = total.empty_by_condition || s.empty_by_condition;
}


// The slices to extract, in scene order; the others are decided here, from the index
// and the geometry alone (no brick read).
std::vector<std::size_t> plan_slices(const Store& store, const ResolvedScene& scene, std::uint32_t step,
                                     const NodeGeometry& geometry, NodeId node,
                                     std::vector<SliceResult>& slices) {
  std::vector<std::size_t> plans;
  slices.resize(scene.slices.size());
  for (std::size_t i = 0; i < scene.slices.size(); ++i) {
    if (!skip_slice(store, scene.slices[i], step, geometry, node, slices[i])) plans.push_back(i);
  }
  return plans;
}

// The node's fields as NodeSamples fields: each needed brick fetched once, on first use.
struct NodeFields {
  const Store& store;
  BrickCache* cache;
  std::uint32_t step;
  NodeId node;
  const std::stop_token& stop;
  NodeSamples& ns;
  FieldBuffers& buffers;
  std::uint32_t& bricks_used;
  std::map<std::uint32_t, std::uint32_t> field_of{};  // variable -> NodeSamples field

  // The NodeSamples field of `variable` (the grid geometry's field included: Store reads it
  // under its index, format/geometry_field.h), its brick read now if it is not yet.
  std::uint32_t field(std::uint32_t variable) {
    const auto [it, inserted] = field_of.try_emplace(variable, static_cast<std::uint32_t>(ns.fields.size()));
    if (inserted) {
      throw_if_stopped(stop, store, node);
      std::shared_ptr<const Brick> brick =
          cache ? store.read_brick(step, variable, node, *cache)
                : std::make_shared<const Brick>(store.read_brick(step, variable, node));
      ++bricks_used;
      const std::size_t samples = ns.sample_count();
      if (brick->sample_count() != samples) {
        throw make_error(ErrorCode::kCorrupt, "{}: brick holds {} samples, the node has {}",
                         store.describe_node(variable, node), brick->sample_count(), samples);
      }
      buffers.add(*brick);
    }
    return it->second;
  }
};

// The scene's attributes as fields of the node's samples, and their names.
struct Attributes {
  std::vector<std::uint32_t> fields;
  std::vector<std::string> names;
};

// One sub-volume's request in the node, without its domain box (set per longitude turn).
ExtractRequest subvolume_request(const ResolvedSubVolume& sv, const SubVolumePlan& plan,
                                 const Attributes& attributes, NodeMeshOptions mesh_options,
                                 NodeFields& fields) {
  ExtractRequest request;
  request.subvolume_id = sv.id;
  for (const ResolvedLimit& limit : plan.limits) {
    request.limits.push_back({fields.field(limit.variable), limit.min, limit.max});
  }
  request.attribute_fields = attributes.fields;
  request.attribute_names = attributes.names;
  request.merge_face_squares = mesh_options.merge_face_squares;
  request.axis_normals = mesh_options.axis_normals;
  // A height range: conditions on the geometry's height at every sample.
  if (plan.geometry_height) {
    const std::uint32_t f = fields.field(*format::geometry_field_variable(fields.store.manifest()));
    const std::vector<float>& h = fields.ns.fields[f];
    std::vector<double> above(h.size()), below(h.size());
    for (std::size_t s = 0; s < h.size(); ++s) {
      above[s] = double(h[s]) - plan.geometry_height->lo;
      below[s] = plan.geometry_height->hi - double(h[s]);
    }
    request.sample_conditions.push_back(std::move(above));
    request.sample_conditions.push_back(std::move(below));
  }
  // Geographic conditions per horizontal sample, the same on every level of the node.
  const std::size_t samples = fields.ns.sample_count();
  for (const auto& horizontal : plan.geographic) {
    std::vector<double>& c = request.sample_conditions.emplace_back();
    c.reserve(samples);
    for (std::size_t z = 0; z < fields.ns.coords[2].size(); ++z) c.insert(c.end(), horizontal.begin(), horizontal.end());
  }
  return request;
}

// One sub-volume's mesh in the node: one piece per whole longitude turn its box meets,
// shifted back by that turn.
void extract_subvolume(const Store& store, const ResolvedSubVolume& sv, const SubVolumePlan& plan,
                       const NodeGeometry& geometry, const Attributes& attributes,
                       NodeMeshOptions mesh_options, NodeFields& fields, NodeMeshScratch& scratch,
                       SubVolumeResult& r) {
  ExtractRequest request = subvolume_request(sv, plan, attributes, mesh_options, fields);
  NodeSamples& ns = fields.ns;
  for (const int turn : plan.turns) {
    const double shift = kFullTurn * turn;
    for (int a = 0; a < 3; ++a) request.box[a] = {sv.box[a].lo, sv.box[a].hi};
    request.box[0] = {sv.box[0].lo - shift, sv.box[0].hi - shift};
    ns.grid_edge = geometry.grid_edge;
    if (store.manifest().x.periodic) seam_faces(geometry, request.box[0], ns.grid_edge);
    ExtractStats stats;
    Mesh piece = extract_node_mesh(ns, request, scratch, &stats);
    for (auto& p : piece.positions) p[0] += shift;
    append_mesh(r.mesh, std::move(piece));
    add_stats(r.stats, stats);
  }
  r.mesh.subvolume_id = sv.id;
  r.mesh.attribute_names = attributes.names;
  r.outcome = r.mesh.empty() ? NodeOutcome::kEmpty : NodeOutcome::kMesh;
}

// One slice's mesh in the node.
void extract_slice(const Store& store, const ResolvedSlice& slice, NodeFields& fields,
                   NodeMeshScratch& scratch, SliceResult& r) {
  SliceRequest request;
  request.slice_id = slice.id;
  request.axis = slice.axis;
  request.value = slice.value;
  if (slice.is_level()) request.level_field = fields.field(slice.level_variable);
  request.colour_field = fields.field(slice.variable);
  request.colour_name = format::variable_name(store.manifest(), slice.variable);
  r.mesh = extract_slice_mesh(fields.ns, request, scratch);
  r.outcome = r.mesh.empty() ? NodeOutcome::kEmpty : NodeOutcome::kMesh;
}

}  // namespace

std::vector<std::uint32_t> node_brick_variables(const Store& store, const ResolvedScene& scene,
                                                std::uint32_t step, NodeId node) {
  check_node(store, node);
  std::vector<SubVolumeResult> results;
  const NodeGeometry geometry = node_geometry(store, node);
  const std::vector<SubVolumePlan> plans =
      plan_subvolumes(store, scene, step, geometry, node, results);
  std::vector<std::uint32_t> variables;
  if (has_no_cells(geometry)) return variables;
  if (!plans.empty()) variables = scene.attributes;
  for (const SubVolumePlan& plan : plans) {
    for (const ResolvedLimit& limit : plan.limits) variables.push_back(limit.variable);
  }
  for (const ResolvedSlice& slice : scene.slices) {
    SliceResult skipped;
    if (skip_slice(store, slice, step, geometry, node, skipped)) continue;
    if (slice.is_level()) variables.push_back(slice.level_variable);
    variables.push_back(slice.variable);
  }
  std::sort(variables.begin(), variables.end());
  variables.erase(std::unique(variables.begin(), variables.end()), variables.end());
  return variables;
}

NodeExtraction extract_node(const Store& store, BrickCache* cache, const ResolvedScene& scene,
                            std::uint32_t step, NodeId node, ExtractScratch& scratch,
                            std::stop_token stop, NodeMeshOptions mesh_options) {
  check_node(store, node);
  throw_if_stopped(stop, store, node);
  NodeExtraction out;
  out.node = node;
  const NodeGeometry geometry = node_geometry(store, node);
  const std::vector<SubVolumePlan> plans =
      plan_subvolumes(store, scene, step, geometry, node, out.results);
  const std::vector<std::size_t> slice_plans = plan_slices(store, scene, step, geometry, node, out.slices);
  if (plans.empty() && slice_plans.empty()) return out;
  if (has_no_cells(geometry)) {
    for (const SubVolumePlan& plan : plans) out.results[plan.subvolume].outcome = NodeOutcome::kEmpty;
    return out;  // slices not skipped stay kEmpty
  }

  NodeSamples ns;
  ns.coords = geometry.coords;
  ns.grid_edge = geometry.grid_edge;
  FieldBuffers buffers(ns, scratch.field_buffers);
  NodeFields fields{store, cache, step, node, stop, ns, buffers, out.bricks_used};
  const format::Manifest& m = store.manifest();
  Attributes attributes;
  // The scene's attributes are per-vertex values of sub-volume meshes only.
  for (std::uint32_t v : plans.empty() ? std::vector<std::uint32_t>{} : scene.attributes) {
    attributes.fields.push_back(fields.field(v));
    attributes.names.push_back(format::variable_name(m, v));
  }
  for (const SubVolumePlan& plan : plans) {
    throw_if_stopped(stop, store, node);
    extract_subvolume(store, scene.subvolumes[plan.subvolume], plan, geometry, attributes,
                      mesh_options, fields, scratch.mesh, out.results[plan.subvolume]);
  }
  for (const std::size_t i : slice_plans) {
    throw_if_stopped(stop, store, node);
    extract_slice(store, scene.slices[i], fields, scratch.mesh, out.slices[i]);
  }
  return out;
}

NodeExtraction extract_node(const Store& store, BrickCache* cache, const ResolvedScene& scene,
                            std::uint32_t step, NodeId node, std::stop_token stop,
                            NodeMeshOptions mesh_options) {
  return extract_node(store, cache, scene, step, node, this_thread_scratch(), std::move(stop),
                      mesh_options);
}

}  // namespace strielad
