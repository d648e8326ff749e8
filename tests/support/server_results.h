// SPDX-License-Identifier: Apache-2.0
// Client-side helpers shared by the server tests (threaded and MPI): whole-octree cuts,
// collecting one answer per node, and the rapid generation-change scenario.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <vector>

#include "client/server_client.h"
#include "protocol/messages.h"
#include "scene/scene.h"

namespace strielad::testing {

// Every node of the octree, priority = id.
std::vector<protocol::NodePriority> whole_octree(const OctreeLayout& octree);

// One NodeResult per node until `wanted` arrived (a NodeFailed, an ErrorMessage, a
// duplicate, a result of another generation or a timeout fails the test). `order`, if
// given, receives the nodes in arrival order.
std::map<NodeId, protocol::NodeResult> collect_results(
    client::ServerClient& c, std::size_t wanted, std::uint32_t generation,
    std::vector<NodeId>* order = nullptr,
    std::chrono::milliseconds timeout = std::chrono::seconds(60));

// `rounds` generations in quick succession, alternating SetScene(scene) and SetTime
// (steps 1 and 0), each followed by the whole cut `nodes`; every result read meanwhile
// must be of the newest generation. Returns the last generation, none of whose results
// it has read.
std::uint32_t change_generations_rapidly(client::ServerClient& c, const Scene& scene,
                                         const std::vector<protocol::NodePriority>& nodes,
                                         int rounds);

}  // namespace strielad::testing
