// SPDX-License-Identifier: Apache-2.0
// A worker rank of strielad-serve under MPI (ranks 1..N-1; docs/cluster.md). It opens
// the stores itself, by name under the same root as rank 0 (the root must be on a file
// system every node shares), keeps its own brick cache, and runs the nodes rank 0 sends
// it (lib/serve/mpi_messages.h):
//
//   * the MPI thread (the caller) receives tasks, cancels and the stop, and sends replies;
//   * `threads` executor threads run serve::run_node_task / prefetch_node_task, extract
//     tasks before prefetches; each task has its own std::stop_source, which a cancel
//     from rank 0 triggers while the task runs (extraction checks it between bricks).
//
// Rank 0 sends a generation's scene once (lib/serve/mpi_messages.h, kScene); the worker
// parses and resolves it once, at its first task, and its other tasks share it.
#pragma once

#include <cstdint>
#include <filesystem>

#include "serve/mpi_runtime.h"

namespace strielad::serve {

struct MpiWorkerOptions {
  std::filesystem::path root;
  unsigned threads = 0;  // tasks run at once; 0 = one per hardware thread
  std::uint64_t cache_bytes = 1ull << 30;
  bool direct_reads = false;  // StoreOpenOptions::direct_reads
};

// Serves rank 0 until it sends the stop, then returns 0; returns 1 when the worker could
// not serve at all (the root is missing here), after telling rank 0 and being stopped.
// On the thread that made `runtime`.
int run_mpi_worker(const MpiRuntime& runtime, const MpiWorkerOptions& options);

}  // namespace strielad::serve
