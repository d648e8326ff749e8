// SPDX-License-Identifier: Apache-2.0
#include "support/server_results.h"

#include <gtest/gtest.h>

namespace strielad::testing {

std::vector<protocol::NodePriority> whole_octree(const OctreeLayout& octree) {
  std::vector<protocol::NodePriority> nodes;
  for (NodeId n = 0; n < octree.node_count(); ++n) nodes.push_back({n, float(n)});
  return nodes;
}

std::map<NodeId, protocol::NodeResult> collect_results(client::ServerClient& c, std::size_t wanted,
                                                       std::uint32_t generation,
                                                       std::vector<NodeId>* order,
                                                       std::chrono::milliseconds timeout) {
  std::map<NodeId, protocol::NodeResult> results;
  while (results.size() < wanted) {
    auto m = c.wait(timeout);
    if (!m) {
      ADD_FAILURE() << "timed out with " << results.size() << " of " << wanted
                    << " results: " << c.close_reason();
      break;
    }
    if (auto* f = std::get_if<protocol::NodeFailed>(&*m)) {
      ADD_FAILURE() << "node " << f->node << " failed: " << f->message;
      continue;
    }
    if (auto* e = std::get_if<protocol::ErrorMessage>(&*m)) {
      ADD_FAILURE() << "error: " << e->message;
      break;
    }
    auto* r = std::get_if<protocol::NodeResult>(&*m);
    if (!r) continue;
    EXPECT_EQ(r->generation, generation);
    EXPECT_FALSE(results.contains(r->node)) << "node " << r->node << " sent twice";
    if (order) order->push_back(r->node);
    results[r->node] = std::move(*r);
  }
  return results;
}

std::uint32_t change_generations_rapidly(client::ServerClient& c, const Scene& scene,
                                         const std::vector<protocol::NodePriority>& nodes,
                                         int rounds) {
  std::uint32_t generation = 0;
  for (int round = 0; round < rounds; ++round) {
    const auto started = round % 2 ? c.set_time(round % 4 == 1 ? 1 : 0) : c.set_scene(scene);
    generation = started.generation;
    c.update_cut(nodes, {}, {});
    // The last generation's results are the caller's to collect: a poll here could take
    // some of them away (seen once in CI, where the server answered within the poll loop).
    if (round + 1 == rounds) break;
    while (auto m = c.poll()) {
      if (auto* r = std::get_if<protocol::NodeResult>(&*m)) {
        EXPECT_EQ(r->generation, generation);
      }
      if (auto* e = std::get_if<protocol::ErrorMessage>(&*m)) {
        ADD_FAILURE() << e->message;
      }
    }
  }
  return generation;
}

}  // namespace strielad::testing
