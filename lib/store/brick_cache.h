// SPDX-License-Identifier: Apache-2.0
// A bytes-bounded LRU cache of decoded bricks, shared by every reader of any store in the
// process. Sharded by key hash so concurrent readers rarely contend. Memory held is at
// most the budget plus one brick per shard (a brick larger than a shard's budget is
// returned but not kept).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "store/brick.h"

namespace strielad {

class Store;

struct BrickKey {
  const Store* store = nullptr;
  std::uint32_t step = 0;
  std::uint32_t variable = 0;
  NodeId node = 0;
  friend bool operator==(const BrickKey&, const BrickKey&) = default;
};

struct BrickKeyHash {
  std::size_t operator()(const BrickKey& k) const noexcept;
};

struct BrickCacheStats {
  std::uint64_t hits = 0, misses = 0, evictions = 0;
  std::uint64_t bytes = 0, budget = 0, entries = 0;
  double hit_rate() const { return hits + misses ? double(hits) / double(hits + misses) : 0.0; }
};

class BrickCache {
 public:
  explicit BrickCache(std::uint64_t budget_bytes, std::size_t shards = 16);

  // Returns the cached brick or calls `load` (outside any lock; concurrent misses of one
  // key may load it twice, the first insert wins). Errors from `load` propagate and
  // nothing is cached.
  std::shared_ptr<const Brick> get_or_load(const BrickKey& key,
                                           const std::function<Brick()>& load);
  // The cached brick or nullptr; counts a hit or a miss.
  std::shared_ptr<const Brick> find(const BrickKey& key);
  bool contains(const BrickKey& key) const;  // no counting, no LRU update
  void clear();

  BrickCacheStats stats() const;

 private:
  struct Shard {
    mutable std::mutex mutex;
    std::list<std::pair<BrickKey, std::shared_ptr<const Brick>>> lru;  // front = newest
    std::unordered_map<BrickKey, decltype(lru)::iterator, BrickKeyHash> map;
    std::uint64_t bytes = 0;
  };
  Shard& shard_for(const BrickKey& key) const;
  void insert(Shard& shard, const BrickKey& key, std::shared_ptr<const Brick> brick);

  std::uint64_t budget_;
  std::uint64_t shard_budget_;
  mutable std::vector<Shard> shards_;
  std::atomic<std::uint64_t> hits_{0}, misses_{0}, evictions_{0};
};

}  // namespace strielad
