// SPDX-License-Identifier: Apache-2.0
#include "store/brick_cache.h"

namespace strielad {

std::size_t BrickKeyHash::operator()(const BrickKey& k) const noexcept {
  std::size_t h = std::hash<const void*>{}(k.store);
  for (std::uint64_t v : {std::uint64_t{k.step}, std::uint64_t{k.variable}, std::uint64_t{k.node}}) {
    h ^= std::hash<std::uint64_t>{}(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  }
  return h;
}

BrickCache::BrickCache(std::uint64_t budget_bytes, std::size_t shards)
    : budget_(budget_bytes),
      shard_budget_(budget_bytes / (shards == 0 ? 1 : shards)),
      shards_(shards == 0 ? 1 : shards) {}

BrickCache::Shard& BrickCache::shard_for(const BrickKey& key) const {
  return shards_[BrickKeyHash{}(key) % shards_.size()];
}

std::shared_ptr<const Brick> BrickCache::find(const BrickKey& key) {
  Shard& s = shard_for(key);
  std::lock_guard lock(s.mutex);
  const auto it = s.map.find(key);
  if (it == s.map.end()) {
    misses_ += 1;
    return nullptr;
  }
  hits_ += 1;
  s.lru.splice(s.lru.begin(), s.lru, it->second);
  return it->second->second;
}

bool BrickCache::contains(const BrickKey& key) const {
  Shard& s = shard_for(key);
  std::lock_guard lock(s.mutex);
  return s.map.count(key) != 0;
}

std::shared_ptr<const Brick> BrickCache::get_or_load(const BrickKey& key,
                                                     const std::function<Brick()>& load) {
  if (auto hit = find(key)) return hit;
  auto brick = std::make_shared<const Brick>(load());
  Shard& s = shard_for(key);
  std::lock_guard lock(s.mutex);
  if (const auto it = s.map.find(key); it != s.map.end()) return it->second->second;
  insert(s, key, brick);
  return brick;
}

void BrickCache::insert(Shard& s, const BrickKey& key, std::shared_ptr<const Brick> brick) {
  const std::uint64_t size = brick->memory_bytes();
  if (size > shard_budget_) return;
  while (s.bytes + size > shard_budget_ && !s.lru.empty()) {
    s.bytes -= s.lru.back().second->memory_bytes();
    s.map.erase(s.lru.back().first);
    s.lru.pop_back();
    evictions_ += 1;
  }
  s.lru.emplace_front(key, std::move(brick));
  s.map.emplace(key, s.lru.begin());
  s.bytes += size;
}

void BrickCache::clear() {
  for (Shard& s : shards_) {
    std::lock_guard lock(s.mutex);
    s.lru.clear();
    s.map.clear();
    s.bytes = 0;
  }
}

BrickCacheStats BrickCache::stats() const {
  BrickCacheStats st;
  st.hits = hits_.load();
  st.misses = misses_.load();
  st.evictions = evictions_.load();
  st.budget = budget_;
  for (const Shard& s : shards_) {
    std::lock_guard lock(s.mutex);
    st.bytes += s.bytes;
    st.entries += s.map.size();
  }
  return st;
}

}  // namespace strielad
