// SPDX-License-Identifier: Apache-2.0
#include "extract/node_extractor.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/error.h"
#include "extract/conditions.h"
#include "extract/mesh_builder.h"
#include "extract/tet_clipper.h"

namespace strielad {

namespace {


// Set bits of a 4-bit mask (std::popcount is a library call without -mpopcnt).
constexpr std::array<int, 16> kBits4{0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};

// The six Kuhn tetrahedra of a cell: corners as cube indices (bit 0 x, 1 y, 2 z), in
// ascending order, which is also ascending sample order.
constexpr std::array<std::array<int, 4>, 6> kTets{{{0, 1, 3, 7},
                                                   {0, 1, 5, 7},
                                                   {0, 2, 3, 7},
                                                   {0, 2, 6, 7},
                                                   {0, 4, 5, 7},
                                                   {0, 4, 6, 7}}};

// Trilinear value and lattice-space gradient of a field at lattice position p.
struct Trilinear {
  double value;
  Vec3 gradient;
};

Trilinear trilinear(const std::vector<float>& field, const std::array<std::size_t, 3>& dims,
                    const Vec3& p) {
  std::array<std::size_t, 3> i{};
  Vec3 f{};
  for (int a = 0; a < 3; ++a) {
    const double fl = std::floor(p[a]);
    const double clamped = std::clamp(fl, 0.0, static_cast<double>(dims[a] - 2));
    i[a] = static_cast<std::size_t>(clamped);
    f[a] = p[a] - clamped;
  }
  double c[8];
  for (int k = 0; k < 8; ++k) {
    const std::size_t x = i[0] + (k & 1), y = i[1] + ((k >> 1) & 1), z = i[2] + ((k >> 2) & 1);
    c[k] = field[(z * dims[1] + y) * dims[0] + x];
  }
  const double fx = f[0], fy = f[1], fz = f[2];
  const double x00 = c[0] + fx * (c[1] - c[0]), x10 = c[2] + fx * (c[3] - c[2]);
  const double x01 = c[4] + fx * (c[5] - c[4]), x11 = c[6] + fx * (c[7] - c[6]);
  const double y0 = x00 + fy * (x10 - x00), y1 = x01 + fy * (x11 - x01);
  Trilinear t;
  t.value = y0 + fz * (y1 - y0);
  const double dx00 = c[1] - c[0], dx10 = c[3] - c[2], dx01 = c[5] - c[4], dx11 = c[7] - c[6];
  const double dx0 = dx00 + fy * (dx10 - dx00), dx1 = dx01 + fy * (dx11 - dx01);
  t.gradient[0] = dx0 + fz * (dx1 - dx0);
  t.gradient[1] = (x10 - x00) + fz * ((x11 - x01) - (x10 - x00));
  t.gradient[2] = y1 - y0;
  return t;
}

// Axis coordinate of lattice coordinate p along axis `coords`, and the cell spacing.
std::pair<double, double> to_axis(const std::vector<double>& coords, double p) {
  const std::size_t n = coords.size();
  const double fl = std::clamp(std::floor(p), 0.0, static_cast<double>(n - 2));
  const std::size_t i = static_cast<std::size_t>(fl);
  const double f = p - fl;
  const double spacing = coords[i + 1] - coords[i];
  if (f == 0.0) return {coords[i], spacing};
  if (f == 1.0) return {coords[i + 1], spacing};
  return {coords[i] + f * spacing, spacing};
}

}  // namespace

Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request,
                       ExtractStats* stats) {
  const auto dims = samples.dims();
  const ConditionSet set = build_conditions(samples, request);
  if (request.attribute_fields.size() != request.attribute_names.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sub-volume {}: {} attribute fields but {} names", request.subvolume_id,
                     request.attribute_fields.size(), request.attribute_names.size());
  }
  for (std::uint32_t f : request.attribute_fields) {
    if (f >= samples.fields.size() || samples.fields[f].size() != samples.sample_count()) {
      throw make_error(ErrorCode::kInvalidArgument, "sub-volume {}: attribute field {} missing",
                       request.subvolume_id, f);
    }
  }
  Mesh mesh;
  mesh.subvolume_id = request.subvolume_id;
  mesh.attribute_names = request.attribute_names;
  mesh.attributes.resize(request.attribute_fields.size());
  ExtractStats local;
  local.cells = (dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
  local.conditions = set.conditions.size();
  local.empty_by_condition = set.empty;
  if (set.empty) {
    if (stats) *stats = local;
    return mesh;
  }

  const std::size_t c_count = set.conditions.size();
  const std::uint32_t side_group = static_cast<std::uint32_t>(c_count);  // + 2 * axis + side
  MeshBuilder builder;
  TetClipper clipper;
  std::vector<Vec3> pts;
  pts.reserve(64);

  const std::size_t sx = 1, sy = dims[0], sz = dims[0] * dims[1];
  const std::array<std::size_t, 8> offsets{0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
  const std::uint64_t all = set.all;

  // Node-boundary triangle of a tetrahedron face or a cell face, oriented outward.
  auto boundary_face = [&](int axis, int side, const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 tri[3]{a, b, c};
    Vec3 outward{0, 0, 0};
    outward[axis] = side == 0 ? -1.0 : 1.0;
    builder.polygon(side_group + static_cast<std::uint32_t>(2 * axis + side), tri, 3, outward);
  };

  builder.begin_edges(samples.sample_count() * 7);
  for (std::size_t z = 0; z + 1 < dims[2]; ++z) {
    for (std::size_t y = 0; y + 1 < dims[1]; ++y) {
      // A row of cells: skip it whole when a condition fails on all four sample rows,
      // and visit only its end cells when every condition holds on all of them.
      const std::uint64_t* r0 = &set.inside[(z * dims[1] + y) * dims[0]];
      const std::uint64_t* r1 = r0 + sy;
      const std::uint64_t* r2 = r0 + sz;
      const std::uint64_t* r3 = r0 + sz + sy;
      std::uint64_t row_or = 0, row_and = all;
      for (std::size_t x = 0; x < dims[0]; ++x) {
        const std::uint64_t o = r0[x] | r1[x] | r2[x] | r3[x];
        const std::uint64_t a = r0[x] & r1[x] & r2[x] & r3[x];
        row_or |= o;
        row_and &= a;
      }
      if ((row_or & all) != all) continue;
      const bool row_inside = row_and == all;
      const bool row_on_yz_boundary = y == 0 || y + 2 == dims[1] || z == 0 || z + 2 == dims[2];
      for (std::size_t x = 0; x + 1 < dims[0]; ++x) {
        if (row_inside && !row_on_yz_boundary && x != 0 && x + 2 != dims[0]) {
          ++local.inside_cells;  // wholly inside, no face on the node boundary: nothing to emit
          continue;
        }
        const std::size_t base = (z * dims[1] + y) * dims[0] + x;
        std::array<std::uint64_t, 8> masks;
        std::uint64_t all_and = all, any_or = 0;
        for (int k = 0; k < 8; ++k) {
          masks[k] = set.inside[base + offsets[k]];
          all_and &= masks[k];
          any_or |= masks[k];
        }
        if ((any_or & all) != all) continue;  // a condition fails at every corner
        const std::array<std::size_t, 3> cell{x, y, z};
        int boundary = 0;  // bit 2*axis+side
        for (int a = 0; a < 3; ++a) {
          if (cell[a] == 0) boundary |= 1 << (2 * a);
          if (cell[a] + 2 == dims[a]) boundary |= 1 << (2 * a + 1);
        }
        auto corner_pos = [&](int k) {
          return Vec3{static_cast<double>(x + (k & 1)), static_cast<double>(y + ((k >> 1) & 1)),
                      static_cast<double>(z + ((k >> 2) & 1))};
        };
        if (all_and == all) {
          ++local.inside_cells;
          // Cell faces on the node boundary, split along the face's min-max diagonal
          // like the Kuhn tetrahedra split them.
          for (int a = 0; a < 3 && boundary != 0; ++a) {
            const int u = 1 << ((a + 1) % 3), v = 1 << ((a + 2) % 3);
            for (int side = 0; side < 2; ++side) {
              if (!(boundary & (1 << (2 * a + side)))) continue;
              const int o = side == 0 ? 0 : (1 << a);
              boundary_face(a, side, corner_pos(o), corner_pos(o | u), corner_pos(o | u | v));
              boundary_face(a, side, corner_pos(o), corner_pos(o | u | v), corner_pos(o | v));
            }
          }
          continue;
        }
        ++local.cut_cells;
        for (const auto& tet : kTets) {
          std::uint64_t t_and = all, t_or = 0;
          for (int k : tet) {
            t_and &= masks[k];
            t_or |= masks[k];
          }
          if ((t_or & all) != all) continue;
          const std::array<std::size_t, 4> ids{base + offsets[tet[0]], base + offsets[tet[1]],
                                               base + offsets[tet[2]], base + offsets[tet[3]]};
          const std::array<Vec3, 4> pos{corner_pos(tet[0]), corner_pos(tet[1]),
                                        corner_pos(tet[2]), corner_pos(tet[3])};
          // Node side a tetrahedron face lies on, or -1.
          auto face_side = [&](int opposite) {
            int and_bits = 7, or_bits = 0;
            for (int k = 0; k < 4; ++k) {
              if (k == opposite) continue;
              and_bits &= tet[k];
              or_bits |= tet[k];
            }
            for (int a = 0; a < 3; ++a) {
              if (!(or_bits & (1 << a)) && (boundary & (1 << (2 * a)))) return 2 * a;
              if ((and_bits & (1 << a)) && (boundary & (1 << (2 * a + 1)))) return 2 * a + 1;
            }
            return -1;
          };
          if (t_and == all) {
            if (boundary == 0) continue;
            for (int opposite = 0; opposite < 4; ++opposite) {
              const int side = face_side(opposite);
              if (side < 0) continue;
              std::array<Vec3, 3> f;
              for (int k = 0, j = 0; k < 4; ++k) {
                if (k != opposite) f[j++] = pos[k];
              }
              boundary_face(side / 2, side % 2, f[0], f[1], f[2]);
            }
            continue;
          }
          const std::uint64_t mixed = all & ~t_and;
          if ((mixed & (mixed - 1)) == 0) {
            // One condition crosses: the marching-tetrahedra case, without the general
            // clipper, and the same canonical points.
            ++local.simple_tets;
            const std::size_t c = static_cast<std::size_t>(std::countr_zero(mixed));
            const auto& values = set.conditions[c].values;
            const std::array<double, 4> sv{values[ids[0]], values[ids[1]], values[ids[2]],
                                           values[ids[3]]};
            auto edge_point = [&](int p, int q) {  // p < q
              const double t = sv[p] / (sv[p] - sv[q]);
              std::array<double, 4> w{};
              w[p] = 1.0 - t;
              w[q] = t;
              return lattice_point(pos, w);
            };
            // Lattice edge slot: lower sample * 7 + direction (corner difference 1..7).
            auto edge_slot = [&](int p, int q) {
              return ids[p] * 7 + static_cast<std::size_t>(tet[q] - tet[p] - 1);
            };
            std::uint32_t poly_ids[4];
            int in = 0;
            for (int k = 0; k < 4; ++k) in |= (sv[k] >= 0 ? 1 : 0) << k;
            Vec3 poly[4];
            std::size_t m = 0;
            const int n_in = kBits4[in];
            if (n_in == 1 || n_in == 3) {
              const int lone = std::countr_zero(static_cast<unsigned>(n_in == 1 ? in : ~in & 15));
              for (int k = 0; k < 4; ++k) {
                if (k == lone) continue;
                const int p = std::min(k, lone), q = std::max(k, lone);
                poly[m] = edge_point(p, q);
                poly_ids[m] = builder.edge_vertex(static_cast<std::uint32_t>(c), edge_slot(p, q), poly[m]);
                ++m;
              }
            } else {
              int a = -1, b = -1, cc = -1, d = -1;
              for (int k = 0; k < 4; ++k) {
                if (in & (1 << k)) (a < 0 ? a : b) = k;
                else (cc < 0 ? cc : d) = k;
              }
              for (const auto& [u, v] : {std::pair{a, cc}, {a, d}, {b, d}, {b, cc}}) {
                const int p = std::min(u, v), q = std::max(u, v);
                poly[m] = edge_point(p, q);
                poly_ids[m] = builder.edge_vertex(static_cast<std::uint32_t>(c), edge_slot(p, q), poly[m]);
                ++m;
              }
            }
            // Gradient: Kuhn edges are unit steps along one axis each.
            Vec3 outward{0, 0, 0};
            for (int k = 0; k < 3; ++k) {
              const int axis = std::countr_zero(static_cast<unsigned>(tet[k + 1] ^ tet[k]));
              outward[axis] = sv[k] - sv[k + 1];
            }
            builder.polygon(static_cast<std::uint32_t>(c), poly, m, outward, poly_ids);
            // Faces on the node boundary: the triangle's inside part (Sutherland-Hodgman
            // by the one condition, crossings from the same canonical points).
            for (int opposite = 0; boundary != 0 && opposite < 4; ++opposite) {
              const int side = face_side(opposite);
              if (side < 0) continue;
              int f[3];
              for (int k = 0, j = 0; k < 4; ++k) {
                if (k != opposite) f[j++] = k;
              }
              Vec3 clipped[4];
              std::size_t q = 0;
              for (int i = 0; i < 3; ++i) {
                const int cur = f[i], nxt = f[(i + 1) % 3];
                const bool cin = (in >> cur) & 1, nin = (in >> nxt) & 1;
                if (cin) clipped[q++] = pos[cur];
                if (cin != nin) clipped[q++] = edge_point(std::min(cur, nxt), std::max(cur, nxt));
              }
              Vec3 face_out{0, 0, 0};
              face_out[side / 2] = side % 2 == 0 ? -1.0 : 1.0;
              builder.polygon(side_group + static_cast<std::uint32_t>(side), clipped, q, face_out);
            }
            continue;
          }
          ++local.clipped_tets;
          if (!clipper.clip(ids, pos, set, all & ~t_and)) continue;
          const auto& loop = clipper.loop();
          for (const auto& face : clipper.faces()) {
            Vec3 outward;
            std::uint32_t group;
            if (face.tag < 4) {
              const int side = face_side(face.tag);
              if (side < 0) continue;
              outward = {0, 0, 0};
              outward[side / 2] = side % 2 == 0 ? -1.0 : 1.0;
              group = side_group + static_cast<std::uint32_t>(side);
            } else {
              const std::size_t c = static_cast<std::size_t>(face.tag - 4);
              const Vec3 g = clipper.gradient(c);
              outward = {-g[0], -g[1], -g[2]};
              group = static_cast<std::uint32_t>(c);
            }
            pts.clear();
            for (std::uint32_t i = 0; i < face.count; ++i) {
              pts.push_back(clipper.position(loop[face.first + i]));
            }
            builder.polygon(group, pts.data(), pts.size(), outward);
          }
        }
      }
    }
  }

  // Lattice to axis coordinates, normals, attributes.
  int descending = 0;
  for (int a = 0; a < 3; ++a) descending += samples.coords[a].back() < samples.coords[a].front();
  const std::size_t nv = builder.points.size();
  mesh.positions.resize(nv);
  mesh.normals.assign(nv, {0.f, 0.f, 0.f});
  std::vector<Vec3> spacing(nv);
  std::vector<Vec3> positions(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    for (int a = 0; a < 3; ++a) {
      const auto [coord, h] = to_axis(samples.coords[a], builder.points[v][a]);
      positions[v][a] = coord;
      spacing[v][a] = h;
      mesh.positions[v][a] = coord;
    }
  }
  mesh.triangles = std::move(builder.triangles);
  if (descending % 2 == 1) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  mesh.face_kinds.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t g = builder.triangle_groups[t];
    mesh.face_kinds[t] = g >= side_group ? (samples.grid_edge[g - side_group] ? FaceKind::kGridBoundary
                                                                             : FaceKind::kNodeBoundary)
                         : set.conditions[g].kind == ConditionKind::kBox ? FaceKind::kDomainBox
                                                                          : FaceKind::kLimit;
  }
  // Area-weighted face normals in axis coordinates: the fallback where a field
  // gradient is zero or undefined.
  std::vector<Vec3> fallback(nv, Vec3{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    const Vec3 n = cross(sub(positions[t[1]], positions[t[0]]), sub(positions[t[2]], positions[t[0]]));
    for (std::uint32_t v : t) {
      for (int a = 0; a < 3; ++a) fallback[v][a] += n[a];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t g = builder.vertex_groups[v];
    Vec3 lattice_normal{0, 0, 0};  // a covector in lattice coordinates
    if (g >= side_group) {
      const int side = static_cast<int>(g - side_group);
      lattice_normal[side / 2] = side % 2 == 0 ? -1.0 : 1.0;
    } else {
      const Condition& c = set.conditions[g];
      if (c.kind == ConditionKind::kBox) {
        lattice_normal[c.axis] = c.side == 0 ? -1.0 : 1.0;
      } else if (c.kind != ConditionKind::kValidity) {
        const Trilinear t = trilinear(samples.fields[c.field], dims, builder.points[v]);
        const double sign = c.kind == ConditionKind::kLimitMin ? -1.0 : 1.0;
        for (int a = 0; a < 3; ++a) lattice_normal[a] = sign * t.gradient[a];
      }
    }
    Vec3 n{};
    for (int a = 0; a < 3; ++a) n[a] = lattice_normal[a] / spacing[v][a];
    double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) {
      n = fallback[v];
      len = std::sqrt(dot(n, n));
    }
    if (!(len > 0) || !std::isfinite(len)) {
      n = {0, 0, 1};
      len = 1;
    }
    mesh.normals[v] = {static_cast<float>(n[0] / len), static_cast<float>(n[1] / len),
                       static_cast<float>(n[2] / len)};
  }
  for (std::size_t a = 0; a < request.attribute_fields.size(); ++a) {
    auto& out = mesh.attributes[a];
    out.resize(nv);
    const auto& field = samples.fields[request.attribute_fields[a]];
    for (std::size_t v = 0; v < nv; ++v) {
      out[v] = static_cast<float>(trilinear(field, dims, builder.points[v]).value);
    }
  }
  if (stats) *stats = local;
  return mesh;
}

}  // namespace strielad
