// SPDX-License-Identifier: Apache-2.0
// The working memory of one thread's extractions, for the calls that are given none
// (extract_node_mesh, extract_node and extract_slice_mesh without a scratch argument):
// kept across calls so that a node costs no fresh pages. Callers that extract on
// several threads at once give each thread its own ExtractScratch instead.
#pragma once

#include <vector>

#include "extract/node_mesh_scratch.h"

namespace strielad {

struct ExtractScratch {
  NodeMeshScratch mesh;
  // Float buffers for a node's fields (extract_node), handed back after each node: a
  // fresh vector per brick would be allocated and zeroed before every copy.
  std::vector<std::vector<float>> field_buffers;
};

// This thread's scratch (one per thread, made on first use).
ExtractScratch& this_thread_scratch();

}  // namespace strielad
