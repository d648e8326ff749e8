// SPDX-License-Identifier: Apache-2.0
// Read access to a brick store (formats/store.md). Opening reads only the manifest; a
// step file's header, footer and section table are read on first use of that step, a
// variable's index section on first use of that variable, and a brick with exactly one
// positioned read of its chunk. A version-5 store's geometry is read the same way: the
// GEOMETRY file on first use of the horizontal coordinates, geometry.bricks (or a step
// file's last section) on first use of the vertical field. All methods are thread-safe.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "format/geometry_file_format.h"
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

  // Variable index variable_count() is the grid geometry's vertical field where the store
  // has one (format/geometry_field.h): index, node_entry and read_brick read it as
  // geometry_index and read_geometry_brick do.
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

  // The vertical geometry field (formats/store.md, "Geometry bricks"): a height or
  // pressure for every sample, stored like a variable. Whether the store has one:
  bool has_geometry_field() const;
  // Its statistics of every node at a step: from geometry.bricks when it does not vary in
  // time (the same for every step), else from the step file's section V (V =
  // variable_count()). Throws kNotFound without a field or for a step outside the store,
  // kCorrupt naming geometry.bricks when it is missing or damaged.
  std::span<const format::IndexEntry> geometry_index(std::uint32_t step) const;
  // One brick of the field, decoded with the field's codec and dtype. A brick that is
  // empty or holds fewer valid samples than the node owns throws kCorrupt naming the
  // file and node; other bricks stay readable.
  Brick read_geometry_brick(std::uint32_t step, NodeId node) const;
  // The same through a shared cache, keyed as variable variable_count() and, for a field
  // that does not vary in time, step format::kGeometryStep, so every step shares it.
  std::shared_ptr<const Brick> read_geometry_brick(std::uint32_t step, NodeId node,
                                                   BrickCache& cache) const;
  // The level-0 2-D longitude, latitude and surface height from the GEOMETRY file, read,
  // decoded and checked against the manifest once; nullptr when the store has no
  // GEOMETRY (neither a curvilinear horizontal nor a surface). Throws kCorrupt,
  // kTruncated or kNotFound naming GEOMETRY; a failed read is tried again next call.
  std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates() const;

  StoreReadCounters counters() const;

  // "STORE/steps/step-000003.bricks" etc., for messages and tools.
  std::filesystem::path step_path(std::uint32_t step) const;
  // "STORE/GEOMETRY" and "STORE/geometry.bricks".
  std::filesystem::path geometry_path() const;
  std::filesystem::path geometry_bricks_path() const;
  // "variable 'ta' node 3 (level 0, index 1,1,0)"; variable_count() names the geometry
  // field: "geometry field node 3 (...)".
  std::string describe_node(std::uint32_t variable, NodeId node) const;

  ~Store();

 private:
  struct StepState;
  Store(std::filesystem::path dir, format::Manifest manifest);
  StepState& step_state(std::uint32_t step) const;  // opened and validated
  StepState& geometry_bricks_state() const;         // geometry.bricks, opened and validated
  // Opens `path` into `s` (locked by the caller) and checks its header and footer
  // against the manifest: `step` and `sections` sections.
  void open_step_file(StepState& s, const std::filesystem::path& path, std::uint32_t step,
                      std::uint32_t sections) const;
  // Index section `section` of an opened step file, loaded once; `label` names it.
  std::span<const format::IndexEntry> section_index(StepState& s, std::uint32_t section,
                                                    std::string_view label) const;
  // The (step file, entry) of a geometry brick.
  StepState& geometry_state(std::uint32_t step) const;
  // Reads and decodes one data or constant brick of an index entry.
  // `what` names the file and node in errors.
  Brick decode_brick(StepState& s, const format::IndexEntry& e, NodeId node, DType dtype,
                     const format::CodecSpec& codec,
                     const std::function<std::string()>& what) const;
  void check_step_and_variable(std::uint32_t step, std::uint32_t variable) const;
  void check_step(std::uint32_t step) const;

  std::filesystem::path dir_;
  format::Manifest manifest_;
  OctreeLayout octree_;
  std::vector<std::unique_ptr<StepState>> steps_;
  std::unique_ptr<StepState> geometry_bricks_;
  mutable std::mutex geometry_mutex_;
  mutable std::shared_ptr<const format::HorizontalCoordinates> coordinates_;
  bool direct_reads_ = false;
  mutable std::atomic<std::uint64_t> chunks_read_{0}, chunk_bytes_{0}, index_bytes_{0},
      device_bytes_{0};
};

}  // namespace strielad
