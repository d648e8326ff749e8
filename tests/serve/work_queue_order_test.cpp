// SPDX-License-Identifier: Apache-2.0
// The scheduler's queue: nearest first, ties in arrival order, remove and reprioritize
// anywhere in the heap, and a new generation drops everything pending.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include "serve/work_queue.h"

namespace strielad::serve {
namespace {

std::vector<NodeId> drain(WorkQueue& q) {
  std::vector<NodeId> order;
  while (auto item = q.pop()) order.push_back(item->node);
  return order;
}

TEST(WorkQueueOrder, PopsSmallestPriorityFirst) {
  WorkQueue q;
  q.add(10, 5.0f);
  q.add(11, 1.0f);
  q.add(12, 3.0f);
  EXPECT_EQ(drain(q), (std::vector<NodeId>{11, 12, 10}));
  EXPECT_TRUE(q.empty());
}

TEST(WorkQueueOrder, EqualPrioritiesLeaveInArrivalOrder) {
  WorkQueue q;
  for (NodeId n : {7u, 3u, 9u, 1u}) q.add(n, 2.0f);
  EXPECT_EQ(drain(q), (std::vector<NodeId>{7, 3, 9, 1}));
}

TEST(WorkQueueOrder, AddingAQueuedNodeAgainChangesNothing) {
  WorkQueue q;
  EXPECT_TRUE(q.add(4, 1.0f));
  EXPECT_FALSE(q.add(4, 0.5f));
  EXPECT_EQ(q.size(), 1u);
  EXPECT_EQ(q.priority(4), 1.0f);
}

TEST(WorkQueueOrder, ReprioritizeMovesANodeBothWays) {
  WorkQueue q;
  for (NodeId n = 0; n < 8; ++n) q.add(n, float(n));
  EXPECT_TRUE(q.reprioritize(7, -1.0f));
  EXPECT_TRUE(q.reprioritize(0, 100.0f));
  EXPECT_FALSE(q.reprioritize(42, 0.0f));
  EXPECT_EQ(drain(q), (std::vector<NodeId>{7, 1, 2, 3, 4, 5, 6, 0}));
}

TEST(WorkQueueOrder, RemovedNodesAreNeverPopped) {
  WorkQueue q;
  for (NodeId n = 0; n < 6; ++n) q.add(n, float(6 - n));
  EXPECT_TRUE(q.remove(5));  // the top
  EXPECT_TRUE(q.remove(0));  // the bottom
  EXPECT_FALSE(q.remove(5));
  EXPECT_EQ(drain(q), (std::vector<NodeId>{4, 3, 2, 1}));
}

TEST(WorkQueueOrder, NewGenerationDropsPendingItems) {
  WorkQueue q;
  q.add(1, 1.0f);
  q.add(2, 2.0f);
  EXPECT_EQ(q.start_generation(5), 2u);
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.contains(1));
  q.add(3, 1.0f);
  const auto item = q.pop();
  ASSERT_TRUE(item);
  EXPECT_EQ(item->generation, 5u);
  EXPECT_EQ(item->node, 3u);
}

// Random inserts, removals, reprioritizations and pops against a plain ordered map.
TEST(WorkQueueOrder, MatchesAReferenceModelUnderRandomOperations) {
  std::mt19937 rng(1234);
  WorkQueue q;
  std::map<NodeId, std::pair<float, std::uint64_t>> model;  // node -> (priority, seq)
  std::uint64_t seq = 0;
  for (int step = 0; step < 20000; ++step) {
    const NodeId node = rng() % 300;
    const float priority = float(rng() % 50);
    switch (rng() % 4) {
      case 0: {
        const bool added = q.add(node, priority);
        EXPECT_EQ(added, !model.contains(node));
        if (added) model[node] = {priority, seq++};
        break;
      }
      case 1:
        EXPECT_EQ(q.remove(node), model.erase(node) == 1);
        break;
      case 2: {
        const bool known = model.contains(node);
        EXPECT_EQ(q.reprioritize(node, priority), known);
        if (known) model[node].first = priority;
        break;
      }
      default: {
        const auto item = q.pop();
        ASSERT_EQ(item.has_value(), !model.empty());
        if (!item) break;
        const auto best = std::min_element(model.begin(), model.end(), [](auto& a, auto& b) {
          return a.second.first < b.second.first ||
                 (a.second.first == b.second.first && a.second.second < b.second.second);
        });
        EXPECT_EQ(item->priority, best->second.first);
        // Equal priorities after a reprioritize keep the original arrival order.
        EXPECT_EQ(item->node, best->first);
        model.erase(best);
      }
    }
    ASSERT_EQ(q.size(), model.size());
  }
}

}  // namespace
}  // namespace strielad::serve
