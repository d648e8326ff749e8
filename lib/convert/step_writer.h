// SPDX-License-Identifier: Apache-2.0
// Assembles one step file (formats/store.md, "Step file") through a temporary sibling:
// header, chunks as they come, then per-variable index sections, section table and
// footer; commit() publishes it atomically.
#pragma once

#include <filesystem>
#include <vector>

#include "convert/brick_encoder.h"
#include "core/file_io.h"
#include "format/step_file_format.h"

namespace strielad::build {

class StepWriter {
 public:
  StepWriter(const std::filesystem::path& path, const format::StepHeader& header);

  // Appends a brick of `variable` and records its entry (chunk offset filled in).
  void add_brick(std::uint32_t variable, NodeId node, EncodedBrick brick);
  // Writes index sections, section table and footer, then renames into place.
  void commit();

  std::uint64_t chunk_bytes() const { return chunk_bytes_; }
  const std::vector<format::IndexEntry>& entries(std::uint32_t variable) const {
    return entries_.at(variable);
  }

 private:
  format::StepHeader header_;
  AtomicOutputFile file_;
  std::vector<std::vector<format::IndexEntry>> entries_;
  std::vector<std::vector<bool>> written_;
  std::uint64_t chunk_bytes_ = 0;
};

}  // namespace strielad::build
