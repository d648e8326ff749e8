// SPDX-License-Identifier: Apache-2.0
#include "extract/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace strielad {

namespace {

bool nonzero_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(sub(b, a), sub(c, a));
  return n[0] != 0 || n[1] != 0 || n[2] != 0;
}

std::uint64_t hash_of(std::uint32_t group, const Vec3& p) {
  std::uint64_t b[3];
  std::memcpy(b, p.data(), sizeof b);
  std::uint64_t h = group * 0x9E3779B97F4A7C15ull;
  h ^= b[0] * 0xC2B2AE3D27D4EB4Full;
  h = (h ^ (h >> 29)) * 0xBF58476D1CE4E5B9ull;
  h ^= b[1] * 0x165667B19E3779F9ull;
  h = (h ^ (h >> 32)) * 0x94D049BB133111EBull;
  h ^= b[2] * 0x9E3779B97F4A7C15ull;
  return h ^ (h >> 31);
}

}  // namespace

void MeshBuilder::reset() {
  largest_ = std::max(largest_, points.size());
  points.clear();
  vertex_groups.clear();
  triangle_count_ = 0;
  hashing_ = false;
  maybe_unused_ = false;
}

void MeshBuilder::grow_triangles() {
  const std::size_t size = std::max<std::size_t>(4096, 2 * triangles_.size());
  triangles_.resize(size);
  triangle_groups_.resize(size);
}

void MeshBuilder::drop_unused_vertices() {
  if (!maybe_unused_) return;
  constexpr std::uint32_t kUnused = ~std::uint32_t{0};
  renumber_.assign(points.size(), kUnused);
  for (std::size_t t = 0; t < triangle_count_; ++t) {
    for (std::uint32_t v : triangles_[t]) renumber_[v] = 0;
  }
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (renumber_[v] == kUnused) continue;
    renumber_[v] = next;
    points[next] = points[v];
    vertex_groups[next] = vertex_groups[v];
    ++next;
  }
  points.resize(next);
  vertex_groups.resize(next);
  for (std::size_t t = 0; t < triangle_count_; ++t) {
    for (std::uint32_t& v : triangles_[t]) v = renumber_[v];
  }
  hashing_ = false;  // the position index is stale
  maybe_unused_ = false;
}

// Indexes every vertex in a table of at least twice `room` slots. Slots of earlier
// tables (other stamps) count as empty, so a large table costs nothing to reuse.
void MeshBuilder::index_all(std::size_t room) {
  std::size_t want = 1024;
  while (want < room * 2) want *= 2;
  if (slots_.size() < want) slots_.resize(want);
  if (++hash_stamp_ == 0) {
    std::fill(slots_.begin(), slots_.end(), HashSlot{});
    hash_stamp_ = 1;
  }
  mask_ = want - 1;
  for (std::size_t v = 0; v < points.size(); ++v) {
    std::size_t i = hash_of(vertex_groups[v], points[v]) & mask_;
    bool duplicate = false;
    while (slots_[i].stamp == hash_stamp_ && !duplicate) {
      const std::uint32_t u = slots_[i].vertex;
      duplicate = vertex_groups[u] == vertex_groups[v] && points[u] == points[v];
      if (!duplicate) i = (i + 1) & mask_;
    }
    if (!duplicate) slots_[i] = HashSlot{hash_stamp_, static_cast<std::uint32_t>(v)};
  }
}

std::uint32_t MeshBuilder::vertex(std::uint32_t group, const Vec3& p) {
  if (!hashing_) {
    hashing_ = true;
    // Room for as many vertices as the largest extraction so far had: growing the
    // table re-indexes every vertex.
    index_all(std::max(points.size(), largest_));
  }
  std::size_t i = hash_of(group, p) & mask_;
  while (slots_[i].stamp == hash_stamp_) {
    const std::uint32_t v = slots_[i].vertex;
    if (vertex_groups[v] == group && points[v] == p) return v;
    i = (i + 1) & mask_;
  }
  const auto v = static_cast<std::uint32_t>(points.size());
  points.push_back(p);
  vertex_groups.push_back(group);
  slots_[i] = HashSlot{hash_stamp_, v};
  if (points.size() * 2 > mask_ + 1) index_all(points.size() * 2);
  return v;
}

void MeshBuilder::fan(std::uint32_t group, const std::uint32_t* ids, std::size_t m) {
  // Fan from the first apex whose triangles all have area.
  std::size_t apex = 0;
  bool all_good = false;
  for (; apex < m && !all_good; ++apex) {
    all_good = true;
    for (std::size_t i = 1; i + 1 < m && all_good; ++i) {
      all_good = has_area(ids[apex], ids[(apex + i) % m], ids[(apex + i + 1) % m]);
    }
    if (all_good) break;
  }
  if (!all_good) {
    apex = 0;
    maybe_unused_ = true;
  }
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const std::size_t b = (apex + i) % m, c = (apex + i + 1) % m;
    if (!all_good && !has_area(ids[apex], ids[b], ids[c])) continue;
    triangle(group, ids[apex], ids[b], ids[c]);
  }
}

void MeshBuilder::polygon(std::uint32_t group, Vec3* pts, std::size_t count, const Vec3& outward,
                          std::uint32_t* indices) {
  std::size_t m = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (m > 0 && pts[i] == pts[m - 1]) continue;
    if (indices) indices[m] = indices[i];
    pts[m++] = pts[i];
  }
  while (m > 1 && pts[m - 1] == pts[0]) --m;
  if (m < 3) return;
  Vec3 normal{0, 0, 0};  // Newell
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& a = pts[i];
    const Vec3& b = pts[i + 1 == m ? 0 : i + 1];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  const double facing = normal[0] * outward[0] + normal[1] * outward[1] + normal[2] * outward[2];
  if (facing == 0.0 || !std::isfinite(facing)) return;
  if (facing < 0) {
    std::reverse(pts, pts + m);
    if (indices) std::reverse(indices, indices + m);
  }
  // Fan from the first apex whose triangles all have area.
  std::size_t apex = 0;
  bool all_good = false;
  for (; apex < m && !all_good; ++apex) {
    all_good = true;
    for (std::size_t i = 1; i + 1 < m && all_good; ++i) {
      all_good = nonzero_area(pts[apex], pts[(apex + i) % m], pts[(apex + i + 1) % m]);
    }
    if (all_good) break;
  }
  if (!all_good) {
    apex = 0;
    maybe_unused_ = true;
  }
  auto id = [&](std::size_t i) { return indices ? indices[i] : vertex(group, pts[i]); };
  const std::uint32_t first = id(apex);
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const std::size_t b = (apex + i) % m, c = (apex + i + 1) % m;
    if (!all_good && !nonzero_area(pts[apex], pts[b], pts[c])) continue;
    triangle(group, first, id(b), id(c));
  }
}

}  // namespace strielad
