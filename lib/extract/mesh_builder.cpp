// SPDX-License-Identifier: Apache-2.0
#include "extract/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace strielad {

namespace {

bool has_area(const Vec3& a, const Vec3& b, const Vec3& c) {
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

MeshBuilder::MeshBuilder() {
  slots_.assign(1024, 0);
  mask_ = slots_.size() - 1;
}

void MeshBuilder::grow() {
  std::vector<std::uint32_t> old(slots_.size() * 2, 0);
  old.swap(slots_);
  mask_ = slots_.size() - 1;
  for (std::uint32_t s : old) {
    if (s == 0) continue;
    std::size_t i = hash_of(vertex_groups[s - 1], points[s - 1]) & mask_;
    while (slots_[i] != 0) i = (i + 1) & mask_;
    slots_[i] = s;
  }
}

std::uint32_t MeshBuilder::vertex(std::uint32_t group, const Vec3& p) {
  std::size_t i = hash_of(group, p) & mask_;
  while (slots_[i] != 0) {
    const std::uint32_t v = slots_[i] - 1;
    if (vertex_groups[v] == group && points[v] == p) return v;
    i = (i + 1) & mask_;
  }
  const auto v = static_cast<std::uint32_t>(points.size());
  points.push_back(p);
  vertex_groups.push_back(group);
  slots_[i] = v + 1;
  if (points.size() * 2 > slots_.size()) grow();
  return v;
}

void MeshBuilder::begin_edges(std::size_t slots) {
  struct ThreadEdges {
    std::vector<EdgeSlot> slots;
    std::uint32_t stamp = 0;
  };
  static thread_local ThreadEdges cache;
  if (cache.slots.size() < slots) cache.slots.resize(slots);
  if (++cache.stamp == 0) {  // wrapped: forget every slot
    std::fill(cache.slots.begin(), cache.slots.end(), EdgeSlot{});
    cache.stamp = 1;
  }
  edges_ = cache.slots.data();
  stamp_ = cache.stamp;
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
      all_good = has_area(pts[apex], pts[(apex + i) % m], pts[(apex + i + 1) % m]);
    }
    if (all_good) break;
  }
  if (!all_good) apex = 0;
  auto id = [&](std::size_t i) { return indices ? indices[i] : vertex(group, pts[i]); };
  const std::uint32_t first = id(apex);
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const std::size_t b = (apex + i) % m, c = (apex + i + 1) % m;
    if (!all_good && !has_area(pts[apex], pts[b], pts[c])) continue;
    triangles.push_back({first, id(b), id(c)});
    triangle_groups.push_back(group);
  }
}

}  // namespace strielad
