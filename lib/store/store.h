// SPDX-License-Identifier: Apache-2.0
// Read access to a brick store (formats/store.md). Opening reads only the manifest; a
// step file's header, footer and section table are read on first use of that step, a
// variable's index section on first use of that variable, and a brick with exactly one
// positioned read of its chunk. All methods are thread-safe.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "format/manifest.h"
#include "format/step_file_format.h"
#include "octree/octree_layout.h"
#include "store/brick.h"

namespace strielad {

class BrickCache;

struct StoreOpenOptions {
  // Open a store whose conversion has not been finalized (steps may be missing).
  bool allow_incomplete = false;
  // Read chunks with O_DIRECT (core/direct_read_file.h): only the 512-byte device blocks
  // a chunk spans come from disk, not whole 4 KiB pages, and nothing goes through the
  // kernel's page cache (the caller's BrickCache is then the only cache). Index
  // sections stay buffered. Where the file system has no direct I/O, reads stay buffered.
  bool direct_reads = false;
};

struct StoreReadCounters {
  std::uint64_t chunks_read = 0;   // data bricks fetched from disk
  std::uint64_t chunk_bytes = 0;   // compressed bytes of those bricks
  std::uint64_t index_bytes = 0;   // bytes of headers, footers, tables and index sections
  std::uint64_t direct_bytes = 0;  // device blocks read for chunks with direct reads
};

class Store {
 public:
  // Throws kNotFound when there is no MANIFEST, kCorrupt/kTruncated/kVersionTooNew when it
  // is damaged, kInvalidArgument when it is incomplete and !allow_incomplete.
  static std::shared_ptr<const Store> open(const std::filesystem::path& dir,
                                           StoreOpenOptions options = {});

  const std::filesystem::path& path() const { return dir_; }
  const format::Manifest& manifest() const { return manifest_; }
  const OctreeLayout& octree() const { return octree_; }
  std::size_t step_count() const { return manifest_.time.values.size(); }
  std::size_t variable_count() const { return manifest_.variables.size(); }

  // Whether the step's file exists (it may still be damaged).
  bool has_step(std::uint32_t step) const;

  // Statistics of every node of a variable at a step (reads its index section once).
  std::span<const format::IndexEntry> index(std::uint32_t step, std::uint32_t variable) const;
  const format::IndexEntry& node_entry(std::uint32_t step, std::uint32_t variable,
                                       NodeId node) const;

  // Reads (and for data bricks decompresses) one brick. A damaged chunk throws kCorrupt
  // naming file, variable and node; other bricks stay readable.
  Brick read_brick(std::uint32_t step, std::uint32_t variable, NodeId node) const;
  // The same through a shared cache.
  std::shared_ptr<const Brick> read_brick(std::uint32_t step, std::uint32_t variable, NodeId node,
                                          BrickCache& cache) const;

  StoreReadCounters counters() const;

  // "STORE/steps/step-000003.bricks" etc., for messages and tools.
  std::filesystem::path step_path(std::uint32_t step) const;
  std::string describe_node(std::uint32_t variable, NodeId node) const;

  ~Store();

 private:
  struct StepState;
  Store(std::filesystem::path dir, format::Manifest manifest);
  StepState& step_state(std::uint32_t step) const;  // opened and validated
  void check_step_and_variable(std::uint32_t step, std::uint32_t variable) const;

  std::filesystem::path dir_;
  format::Manifest manifest_;
  OctreeLayout octree_;
  std::vector<std::unique_ptr<StepState>> steps_;
  bool direct_reads_ = false;
  mutable std::atomic<std::uint64_t> chunks_read_{0}, chunk_bytes_{0}, index_bytes_{0},
      device_bytes_{0};
};

}  // namespace strielad
