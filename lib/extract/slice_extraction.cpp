// SPDX-License-Identifier: Apache-2.0
#include "extract/slice_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "format/geometry_field.h"
#include "extract/conditions.h"
#include "extract/node_extractor.h"
#include "store/store.h"

namespace strielad {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t sample_index(const std::array<std::size_t, 3>& dims, const std::size_t (&l)[3]) {
  return (l[2] * dims[1] + l[1]) * dims[0] + l[0];
}

bool has_cells(const std::array<std::size_t, 3>& dims) {
  return dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2;
}

// The plane coords[axis] = value as a grid of the node's samples along the two other
// axes (see the header).
Mesh axis_plane(const NodeSamples& ns, const SliceRequest& rq) {
  Mesh mesh;
  mesh.subvolume_id = rq.slice_id;
  mesh.attribute_names = {rq.colour_name};
  mesh.attributes.resize(1);
  const auto dims = ns.dims();
  if (!has_cells(dims)) return mesh;
  const int a = rq.axis, u = (a + 1) % 3, w = (a + 2) % 3;
  const double s = fractional_index(ns.coords[a], rq.value);
  if (!(s >= 0) || s > static_cast<double>(dims[a] - 1)) return mesh;
  const std::size_t nu = dims[u], nw = dims[w];
  mesh.positions.resize(nu * nw);
  mesh.normals.assign(nu * nw, std::array<float, 3>{0, 0, 0});
  auto& values = mesh.attributes[0];
  values.resize(nu * nw);
  std::array<double, 3> lattice{};
  lattice[a] = s;
  for (std::size_t k = 0; k < nw; ++k) {
    for (std::size_t j = 0; j < nu; ++j) {
      const std::size_t v = k * nu + j;
      auto& p = mesh.positions[v];
      p[a] = rq.value;  // exactly on the plane
      p[u] = ns.coords[u][j];
      p[w] = ns.coords[w][k];
      mesh.normals[v][a] = 1.0f;
      lattice[u] = static_cast<double>(j);
      lattice[w] = static_cast<double>(k);
      values[v] = static_cast<float>(field_at_lattice(ns, rq.colour_field, lattice));
    }
  }
  // Counter-clockwise seen from +axis: (u, w) turn like (x, y) about z in lattice
  // coordinates; a descending u or w axis mirrors that in axis coordinates.
  const bool u_descends = ns.coords[u].back() < ns.coords[u].front();
  const bool w_descends = ns.coords[w].back() < ns.coords[w].front();
  const bool flip = u_descends != w_descends;
  mesh.triangles.reserve(2 * (nu - 1) * (nw - 1));
  for (std::size_t k = 0; k + 1 < nw; ++k) {
    for (std::size_t j = 0; j + 1 < nu; ++j) {
      const auto v00 = static_cast<std::uint32_t>(k * nu + j);
      const auto v10 = v00 + 1;
      const auto v01 = static_cast<std::uint32_t>(v00 + nu);
      const auto v11 = v01 + 1;
      if (flip) {
        mesh.triangles.push_back({v00, v11, v10});
        mesh.triangles.push_back({v00, v01, v11});
      } else {
        mesh.triangles.push_back({v00, v10, v11});
        mesh.triangles.push_back({v00, v11, v01});
      }
    }
  }
  mesh.face_kinds.assign(mesh.triangles.size(), FaceKind::kSlice);
  return mesh;
}

// The iso-level as the limit faces of the region {level >= value}.
Mesh level_surface(const NodeSamples& ns, const SliceRequest& rq, NodeMeshScratch& scratch) {
  Mesh out;
  out.subvolume_id = rq.slice_id;
  out.attribute_names = {rq.colour_name};
  out.attributes.resize(1);
  if (!has_cells(ns.dims())) return out;
  ExtractRequest request;
  request.subvolume_id = rq.slice_id;
  request.limits.push_back({rq.level_field, rq.value, kUnbounded});
  const Mesh region = extract_node_mesh(ns, request, scratch);
  const std::size_t nv = region.vertex_count();
  // Per vertex: usable (the level field is defined there) and its colour.
  std::vector<std::uint8_t> usable(nv, 0);
  std::vector<float> colour(nv, 0.0f);
  for (std::size_t v = 0; v < nv; ++v) {
    std::array<double, 3> lattice{};
    for (int a = 0; a < 3; ++a) lattice[a] = fractional_index(ns.coords[a], region.positions[v][a]);
    usable[v] = std::isfinite(field_at_lattice(ns, rq.level_field, lattice)) ? 1 : 0;
    colour[v] = static_cast<float>(field_at_lattice(ns, rq.colour_field, lattice));
  }
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renumber(nv, kUnused);
  for (std::size_t t = 0; t < region.triangle_count(); ++t) {
    if (region.face_kinds[t] != FaceKind::kLimit) continue;
    const auto& tri = region.triangles[t];
    if (!usable[tri[0]] || !usable[tri[1]] || !usable[tri[2]]) continue;
    std::array<std::uint32_t, 3> mapped{};
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& r = renumber[tri[c]];
      if (r == kUnused) {
        r = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(region.positions[tri[c]]);
        out.normals.push_back(region.normals[tri[c]]);
        out.attributes[0].push_back(colour[tri[c]]);
      }
      mapped[c] = r;
    }
    out.triangles.push_back(mapped);
  }
  out.face_kinds.assign(out.triangles.size(), FaceKind::kSlice);
  return out;
}

void check_field(const NodeSamples& ns, std::uint32_t field, const SliceRequest& rq,
                 std::string_view role) {
  if (field >= ns.fields.size() || ns.fields[field].size() != ns.sample_count()) {
    throw make_error(ErrorCode::kInvalidArgument, "slice {}: {} field {} missing", rq.slice_id,
                     role, field);
  }
}

std::string axis_name(const format::Manifest& m, int axis) {
  return axis == 0 ? m.x.name : axis == 1 ? m.y.name : m.z.name;
}

}  // namespace

double field_at_lattice(const NodeSamples& samples, std::uint32_t field,
                        const std::array<double, 3>& p) {
  const auto dims = samples.dims();
  const float* f = samples.fields[field].data();
  std::size_t cell[3];
  double fraction[3];
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2) {
      cell[a] = 0;
      fraction[a] = 0;
      continue;
    }
    const double last = static_cast<double>(dims[a] - 1);
    const double c = std::clamp(p[a], 0.0, last);
    const std::size_t i = std::min(static_cast<std::size_t>(c), dims[a] - 2);
    cell[a] = i;
    fraction[a] = c - static_cast<double>(i);
  }
  double sum = 0;
  for (int k = 0; k < 8; ++k) {
    double weight = 1;
    std::size_t l[3];
    for (int a = 0; a < 3; ++a) {
      const bool upper = (k >> a) & 1;
      weight *= upper ? fraction[a] : 1.0 - fraction[a];
      l[a] = cell[a] + (upper ? 1 : 0);
    }
    if (weight == 0) continue;
    const float v = f[sample_index(dims, l)];
    if (std::isnan(v)) return kNaN;
    sum += weight * static_cast<double>(v);
  }
  return sum;
}

Mesh extract_slice_mesh(const NodeSamples& samples, const SliceRequest& request,
                        NodeMeshScratch& scratch) {
  check_field(samples, request.colour_field, request, "colour");
  if (request.axis >= 0) {
    if (request.axis > 2) {
      throw make_error(ErrorCode::kInvalidArgument, "slice {}: axis {} is not 0, 1 or 2",
                       request.slice_id, request.axis);
    }
    return axis_plane(samples, request);
  }
  check_field(samples, request.level_field, request, "level");
  return level_surface(samples, request, scratch);
}

Mesh extract_slice_mesh(const NodeSamples& samples, const SliceRequest& request) {
  return extract_slice_mesh(samples, request, this_thread_scratch().mesh);
}

bool skip_slice(const Store& store, const ResolvedSlice& slice, std::uint32_t step,
                const NodeGeometry& geometry, NodeId node, SliceResult& result) {
  const format::Manifest& m = store.manifest();
  result.slice_id = slice.id;
  result.outcome = NodeOutcome::kEmpty;
  result.reason.clear();
  // Decided from the node's box first: a node the plane misses needs no index look-up
  // and no brick (the plane's position is known without data).
  if (!slice.is_level()) {
    const auto& coords = geometry.coords[static_cast<std::size_t>(slice.axis)];
    const double s = fractional_index(coords, slice.value);
    const double last = static_cast<double>(coords.size() - 1);
    const std::string name = axis_name(m, slice.axis);
    if (s < 0 || s > last) {
      result.outcome = NodeOutcome::kSkippedDomain;
      result.reason = fmt::format("plane {} = {} misses the node ({} {} .. {})", name, slice.value,
                                  name, coords.front(), coords.back());
      return true;
    }
    if (coords.size() >= 2 && s == last && !geometry.grid_edge[2 * slice.axis + 1]) {
      result.outcome = NodeOutcome::kSkippedDomain;
      result.reason = fmt::format(
          "plane {} = {} lies on the node's upper {} face, which the neighbouring node draws",
          name, slice.value, name);
      return true;
    }
  } else {
    const format::IndexEntry& e = store.node_entry(step, slice.level_variable, node);
    const std::string& name = format::variable_name(m, slice.level_variable);
    if (!e.has_valid_data()) {
      result.outcome = NodeOutcome::kSkippedNoData;
      result.reason = fmt::format("{} has no valid sample in the node", name);
      return true;
    }
    if (slice.value < e.min || slice.value > e.max) {
      result.outcome = NodeOutcome::kSkippedValueRange;
      result.reason = fmt::format("{} in [{}, {}] never equals {}", name, e.min, e.max, slice.value);
      return true;
    }
  }
  const format::IndexEntry& colour = store.node_entry(step, slice.variable, node);
  if (!colour.has_valid_data()) {
    result.outcome = NodeOutcome::kSkippedNoData;
    result.reason = fmt::format("{} has no valid sample in the node", format::variable_name(m, slice.variable));
    return true;
  }
  return false;
}

}  // namespace strielad
