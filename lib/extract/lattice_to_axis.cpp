// SPDX-License-Identifier: Apache-2.0
#include "extract/lattice_to_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "extract/mesh_metrics.h"
#include "extract/tet_clipper.h"

namespace strielad {

namespace {

struct Trilinear {
  double value;
  Vec3 gradient;  // lattice units
};

template <class Sample>
Trilinear trilinear(const Sample* field, const std::array<std::size_t, 3>& dims, const CellPoint& cp,
                    bool with_gradient) {
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const Sample* b = field + cp.index;
  const double c0 = b[0], c1 = b[1], c2 = b[sy], c3 = b[sy + 1];
  const double c4 = b[sz], c5 = b[sz + 1], c6 = b[sz + sy], c7 = b[sz + sy + 1];
  const double fx = cp.f[0], fy = cp.f[1], fz = cp.f[2];
  // (1 - f) a + f b is a at f = 0 and b at f = 1 exactly (a + f (b - a) need not be b):
  // a vertex on a node face gets the same value from the cell on either side, so the
  // nodes sharing it carry the same attribute bits (and a height placed by one). A
  // corner of weight 0 is left out: a missing (NaN) sample there must not make the
  // value of a vertex on a valid sample or edge missing (0 * NaN is NaN).
  auto lerp = [](double a, double b, double f) {
    return f == 0.0 ? a : f == 1.0 ? b : (1.0 - f) * a + f * b;
  };
  const double x00 = lerp(c0, c1, fx), x10 = lerp(c2, c3, fx);
  const double x01 = lerp(c4, c5, fx), x11 = lerp(c6, c7, fx);
  const double y0 = lerp(x00, x10, fy), y1 = lerp(x01, x11, fy);
  Trilinear t;
  t.value = lerp(y0, y1, fz);
  if (with_gradient) {
    const double dx00 = c1 - c0, dx10 = c3 - c2, dx01 = c5 - c4, dx11 = c7 - c6;
    const double dx0 = dx00 + fy * (dx10 - dx00), dx1 = dx01 + fy * (dx11 - dx01);
    t.gradient[0] = dx0 + fz * (dx1 - dx0);
    t.gradient[1] = (x10 - x00) + fz * ((x11 - x01) - (x10 - x00));
    t.gradient[2] = y1 - y0;
  } else {
    t.gradient = {0, 0, 0};
  }
  return t;
}

// Per group (condition c, then node side 2 * axis + side): the face kind of its triangles.
using GroupKinds = std::array<FaceKind, kMaxConditions + 6>;

GroupKinds group_face_kinds(const NodeSamples& samples, const ConditionSet& set) {
  const std::size_t side_group = set.conditions.size();
  GroupKinds kind_of{};
  for (std::size_t g = 0; g < side_group + 6; ++g) {
    if (g >= side_group) {
      const std::size_t side = g - side_group;
      kind_of[g] = samples.grid_edge[side]          ? FaceKind::kGridBoundary
                   : (set.box_sides >> side) & 1u ? FaceKind::kDomainBox
                                                  : FaceKind::kNodeBoundary;
    } else {
      const ConditionKind k = set.conditions[g].kind;
      kind_of[g] = k == ConditionKind::kBox || k == ConditionKind::kSample ? FaceKind::kDomainBox
                                                                           : FaceKind::kLimit;
    }
  }
  return kind_of;
}

// The builder's triangles and their face kinds. The lattice-space orientation is the
// axis-space one unless an odd number of axes descend.
void copy_triangles(const NodeSamples& samples, const ConditionSet& set, const MeshBuilder& builder,
                    Mesh& mesh) {
  int descending = 0;
  for (int a = 0; a < 3; ++a) descending += samples.coords[a].back() < samples.coords[a].front();
  const std::size_t nt = builder.triangle_count();
  mesh.face_kinds.reserve(nt);
  const GroupKinds kind_of = group_face_kinds(samples, set);
  const auto* triangles = builder.triangles();
  if (descending % 2 == 1) {
    mesh.triangles.reserve(nt);
    for (std::size_t t = 0; t < nt; ++t) {
      mesh.triangles.push_back({triangles[t][0], triangles[t][2], triangles[t][1]});
    }
  } else {
    mesh.triangles.assign(triangles, triangles + nt);
  }
  const std::uint32_t* triangle_groups = builder.triangle_groups();
  for (std::size_t t = 0; t < nt; ++t) mesh.face_kinds.push_back(kind_of[triangle_groups[t]]);
}

// Per axis and cell: the spacing's inverse (normals are covectors: the lattice
// gradient divided by the spacing).
//
// And whether a point strictly inside a cell may round onto one of the cell's ends
// in axis coordinates (c0 + f (c1 - c0) equal to c0 or c1 for 0 < f < 1), which the
// mapping then checks vertex by vertex. Every vertex but the general clipper's
// is a lattice point or a crossing on a lattice edge, whose fraction of its cell along
// each axis is 0, 1, or at least kCrossingSnap (2^-30) away from both (edge_crossing
// snaps nearer crossings to the corner; computing f = p - i costs far less than
// 2^-31 on any lattice under 2^20 samples a side). Rounding onto an end then needs a
// spacing below 2^-21 of the coordinates' magnitude (|f (c1 - c0)| must be under
// half an ulp of c0); an axis whose every spacing is at least 2^-18 of it is safe
// with room to spare (degrees, metres and pascals on any model grid are, by many
// orders of magnitude). `clipped`: the general clipper made vertices, which may.
bool inverse_spacings(const NodeSamples& samples, bool clipped, NodeMeshScratch& scratch) {
  static_assert(kCrossingSnap >= 0x1p-30);
  const auto dims = samples.dims();
  bool may_round = clipped;
  for (int a = 0; a < 3; ++a) {
    auto& inv = scratch.inverse_spacing[a];
    const auto& c = samples.coords[a];
    inv.resize(dims[a] - 1);
    for (std::size_t i = 0; i + 1 < dims[a]; ++i) {
      const double spacing = c[i + 1] - c[i];
      inv[i] = 1.0 / spacing;
      const double magnitude = std::max(std::fabs(c[i]), std::fabs(c[i + 1]));
      may_round = may_round || !(std::fabs(spacing) >= 0x1p-18 * magnitude);
    }
  }
  return may_round;
}

// Per group: the limit field whose gradient gives the normal (with its sign), or
// the fixed lattice normal of a box or node side (unit along one axis).
struct GroupNormal {
  const float* field = nullptr;
  const double* values = nullptr;  // a per-sample condition: minus its gradient
  double sign = 0;
  int axis = -1;  // fixed normal: +-1 along axis
};
using GroupNormals = std::array<GroupNormal, kMaxConditions + 6>;

GroupNormals group_normals(const NodeSamples& samples, const ConditionSet& set) {
  const std::size_t side_group = set.conditions.size();
  GroupNormals group_normal{};
  for (std::size_t g = 0; g < side_group + 6; ++g) {
    GroupNormal& gn = group_normal[g];
    if (g >= side_group) {
      const int side = static_cast<int>(g - side_group);
      gn.axis = side / 2;
      gn.sign = side % 2 == 0 ? -1.0 : 1.0;
    } else {
      const Condition& c = set.conditions[g];
      if (c.kind == ConditionKind::kBox) {
        gn.axis = c.axis;
        gn.sign = c.side == 0 ? -1.0 : 1.0;
      } else if (c.kind == ConditionKind::kSample) {
        gn.values = c.values.data();
        gn.sign = -1.0;  // inside where the condition grows
      } else if (c.kind != ConditionKind::kValidity) {
        gn.field = samples.fields[c.field].data();
        gn.sign = c.kind == ConditionKind::kLimitMin ? -1.0 : 1.0;
      }
    }
  }
  return group_normal;
}

// Each vertex's cell (clamped to the node), its fractions there (scratch.cells) and its
// axis coordinates. Returns whether a point strictly inside a cell rounded onto the
// cell's end: only then can two lattice-distinct vertices share an axis position
// (collapsed_triangles.h). Checked only where it may happen (`may_round`): the check is
// half of this loop's instructions.
bool place_vertices(const NodeSamples& samples, bool may_round, NodeMeshScratch& scratch, Mesh& mesh) {
  const auto dims = samples.dims();
  const MeshBuilder& builder = scratch.builder;
  const std::size_t nv = builder.points.size();
  scratch.cells.resize(nv);
  mesh.positions.resize(nv);
  bool rounded_onto_sample = false;
  auto map_vertices = [&](auto check_rounding) {
    for (std::size_t v = 0; v < nv; ++v) {
      const Vec3& p = builder.points[v];
      CellPoint& cp = scratch.cells[v];
      std::size_t cell[3];
      auto& position = mesh.positions[v];
      for (int a = 0; a < 3; ++a) {
        const double lo = p[a] > 0 ? p[a] : 0.0;  // truncation = floor here
        std::size_t i = static_cast<std::size_t>(lo);
        if (i > dims[a] - 2) i = dims[a] - 2;
        cell[a] = i;
        const double f = p[a] - static_cast<double>(i);
        cp.f[a] = f;
        // The sample's own coordinate at either end of the cell (exact, as the
        // neighbouring node computes it), interpolated inside (selects, not branches:
        // which case applies varies from vertex to vertex).
        const auto& c = samples.coords[a];
        const double c0 = c[i], c1 = c[i + 1];
        const double inner = c0 + f * (c1 - c0);
        double at = f == 0.0 ? c0 : inner;
        at = f == 1.0 ? c1 : at;
        position[a] = at;
        if constexpr (decltype(check_rounding)::value) {
          rounded_onto_sample |= (f != 0.0) & (f != 1.0) & ((inner == c0) | (inner == c1));
        }
      }
      cp.index = (cell[2] * dims[1] + cell[1]) * dims[0] + cell[0];
      cp.cell = {static_cast<std::uint32_t>(cell[0]), static_cast<std::uint32_t>(cell[1]),
                 static_cast<std::uint32_t>(cell[2])};
    }
  };
  if (may_round) {
    map_vertices(std::true_type{});
  } else {
    map_vertices(std::false_type{});
  }
  return rounded_onto_sample;
}

// Normals as covectors in axis coordinates (lattice gradient / spacing), unit length;
// vertices where the gradient is zero or undefined are marked in scratch.needs_fallback.
// Returns whether any is.
bool gradient_normals(const NodeSamples& samples, const GroupNormals& group_normal,
                      NodeMeshScratch& scratch, Mesh& mesh) {
  const auto dims = samples.dims();
  const MeshBuilder& builder = scratch.builder;
  const std::size_t nv = builder.points.size();
  bool any_fallback = false;
  mesh.normals.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const CellPoint& cp = scratch.cells[v];
    const GroupNormal& gn = group_normal[builder.vertex_groups[v]];
    Vec3 n{0, 0, 0};
    if (gn.field != nullptr) {
      const Trilinear t = trilinear(gn.field, dims, cp, true);
      for (int a = 0; a < 3; ++a) n[a] = gn.sign * t.gradient[a] * scratch.inverse_spacing[a][cp.cell[a]];
    } else if (gn.values != nullptr) {
      const Trilinear t = trilinear(gn.values, dims, cp, true);
      for (int a = 0; a < 3; ++a) n[a] = gn.sign * t.gradient[a] * scratch.inverse_spacing[a][cp.cell[a]];
    } else if (gn.axis >= 0) {
      const double value = gn.sign * scratch.inverse_spacing[gn.axis][cp.cell[gn.axis]];
      for (int a = 0; a < 3; ++a) n[a] = a == gn.axis ? value : 0.0;  // no indexed store
    }
    const double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) {
      scratch.needs_fallback[v] = 1;
      any_fallback = true;
    } else {
      const double inv = 1.0 / len;
      mesh.normals[v] = {static_cast<float>(n[0] * inv), static_cast<float>(n[1] * inv),
                         static_cast<float>(n[2] * inv)};
    }
  }
  return any_fallback;
}

// Each attribute field trilinear at every vertex.
void interpolate_attributes(const NodeSamples& samples, const std::vector<const float*>& attribute_data,
                            const NodeMeshScratch& scratch, Mesh& mesh) {
  const auto dims = samples.dims();
  const std::size_t nv = scratch.builder.points.size();
  for (std::size_t a = 0; a < attribute_data.size(); ++a) {
    auto& out = mesh.attributes[a];
    out.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) {
      out[v] = static_cast<float>(trilinear(attribute_data[a], dims, scratch.cells[v], false).value);
    }
  }
}

// Area-weighted face normals in axis coordinates where a field gradient is zero or
// undefined (+z where those vanish too).
void face_normals_where_no_gradient(NodeMeshScratch& scratch, Mesh& mesh) {
  const std::size_t nv = mesh.positions.size();
  scratch.fallback.assign(nv, Vec3{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    if (!scratch.needs_fallback[t[0]] && !scratch.needs_fallback[t[1]] && !scratch.needs_fallback[t[2]]) {
      continue;
    }
    const Vec3 n = area_normal(mesh, t);
    for (std::uint32_t v : t) {
      for (int a = 0; a < 3; ++a) scratch.fallback[v][a] += n[a];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (!scratch.needs_fallback[v]) continue;
    Vec3 n = scratch.fallback[v];
    double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) {
      n = {0, 0, 1};
      len = 1;
    }
    mesh.normals[v] = {static_cast<float>(n[0] / len), static_cast<float>(n[1] / len),
                       static_cast<float>(n[2] / len)};
  }
}

}  // namespace

bool lattice_mesh_to_axis(const NodeSamples& samples, const ConditionSet& set,
                          const std::vector<std::uint32_t>& attribute_fields, bool clipped,
                          bool axis_normals, NodeMeshScratch& scratch, Mesh& mesh) {
  MeshBuilder& builder = scratch.builder;
  builder.drop_unused_vertices();
  const std::size_t nv = builder.points.size();
  copy_triangles(samples, set, builder, mesh);
  std::vector<const float*> attribute_data;
  for (std::uint32_t f : attribute_fields) attribute_data.push_back(samples.fields[f].data());
  const bool may_round = inverse_spacings(samples, clipped, scratch);
  const bool rounded_onto_sample = place_vertices(samples, may_round, scratch, mesh);
  if (axis_normals) {
    scratch.needs_fallback.assign(nv, 0);
    const GroupNormals group_normal = group_normals(samples, set);
    if (gradient_normals(samples, group_normal, scratch, mesh)) face_normals_where_no_gradient(scratch, mesh);
  } else {
    mesh.normals.assign(nv, {0.0f, 0.0f, 1.0f});
  }
  interpolate_attributes(samples, attribute_data, scratch, mesh);
  return rounded_onto_sample;
}

}  // namespace strielad
