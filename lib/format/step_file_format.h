// SPDX-License-Identifier: Apache-2.0
// Encoding and decoding of the step file's fixed structures (formats/store.md, "Step
// file"). Plain structs and free functions over byte spans: no file I/O here, so every
// decoder can be fuzzed. Decoders throw strielad::Error (kCorrupt, kTruncated,
// kVersionTooNew) whose message starts with `what` (the file and structure).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace strielad::format {

// Step files have their own version: their layout is unchanged in store format versions
// 2 and 3 (version 2 changed only the manifest: how a chunk is decoded is the variable's
// codec, and the header's store_id ties the file to that manifest; version 3 gave the
// reserved byte 13 of an index entry a meaning, the chunk coding, which older readers
// reject as a non-zero reserved byte), so they are still version 1.
inline constexpr std::uint32_t kStepFileFormatVersion = 1;
inline constexpr std::size_t kStepHeaderSize = 64;
// The header and footer `step` of geometry.bricks, the step-file-layout file holding a
// time-invariant geometry field (formats/store.md, "Geometry bricks"): never a time step.
inline constexpr std::uint32_t kGeometryStep = 0xFFFFFFFF;
inline constexpr std::size_t kStepFooterSize = 64;
inline constexpr std::size_t kSectionEntrySize = 48;
inline constexpr std::size_t kIndexEntrySize = 56;

struct StepHeader {
  std::uint64_t store_id = 0;
  std::uint32_t step = 0;
  std::uint32_t variable_count = 0;
  std::uint32_t node_count = 0;
  friend bool operator==(const StepHeader&, const StepHeader&) = default;
};

struct StepFooter {
  std::uint64_t section_table_offset = 0;
  std::uint32_t variable_count = 0;
  std::uint32_t node_count = 0;
  std::uint64_t store_id = 0;
  std::uint32_t step = 0;
  std::uint64_t section_table_checksum = 0;
  std::uint64_t chunk_bytes = 0;
  friend bool operator==(const StepFooter&, const StepFooter&) = default;
};

enum class SectionCodec : std::uint32_t { kRaw = 0, kZstd = 1 };

struct SectionEntry {
  std::uint32_t variable = 0;
  SectionCodec codec = SectionCodec::kZstd;
  std::uint64_t offset = 0;
  std::uint64_t stored_size = 0;
  std::uint64_t raw_size = 0;
  std::uint64_t checksum = 0;
  friend bool operator==(const SectionEntry&, const SectionEntry&) = default;
};

enum class BrickKind : std::uint8_t { kEmpty = 0, kConstant = 1, kData = 2 };

// How a data brick's chunk is coded (formats/store.md, "Brick kinds"): the variable's codec
// chain (predictor + Blosc), an fpzip chunk (store version 3, a codec with fpzip), or a
// lossy zfp chunk (store version 6, a codec with zfp).
enum class ChunkCoding : std::uint8_t { kCodec = 0, kFpzip = 1, kZfp = 2 };

struct IndexEntry {
  std::uint64_t chunk_offset = 0;
  std::uint32_t chunk_size = 0;
  BrickKind kind = BrickKind::kEmpty;
  ChunkCoding coding = ChunkCoding::kCodec;  // kCodec unless kind is kData
  std::uint64_t chunk_checksum = 0;
  std::uint64_t valid_count = 0;
  double min = 0, max = 0;
  double constant = 0;

  bool has_valid_data() const { return min == min; }  // min is NaN when nothing is valid
};

std::vector<std::byte> encode_step_header(const StepHeader& header);
StepHeader decode_step_header(std::span<const std::byte> bytes, std::string_view what);

std::vector<std::byte> encode_step_footer(const StepFooter& footer);
StepFooter decode_step_footer(std::span<const std::byte> bytes, std::string_view what);

std::vector<std::byte> encode_section_table(std::span<const SectionEntry> entries);
// Checks the table's checksum against `expected_checksum` and each entry's structure:
// variable numbering, codec, raw size for `node_count` entries, and that every section
// lies within [section_region_begin, section_region_end).
std::vector<SectionEntry> decode_section_table(std::span<const std::byte> bytes,
                                               std::uint32_t variable_count,
                                               std::uint32_t node_count,
                                               std::uint64_t expected_checksum,
                                               std::uint64_t section_region_begin,
                                               std::uint64_t section_region_end,
                                               std::string_view what);

// Index sections: the stored bytes (zstd-compressed unless codec is kRaw).
std::vector<std::byte> encode_index_section(std::span<const IndexEntry> entries,
                                            SectionCodec codec);
// Verifies the stored bytes' checksum, decompresses, decodes and validates every entry
// (chunks must lie within [chunk_region_begin, chunk_region_end)).
std::vector<IndexEntry> decode_index_section(std::span<const std::byte> stored,
                                             const SectionEntry& section,
                                             std::uint32_t node_count,
                                             std::uint64_t chunk_region_begin,
                                             std::uint64_t chunk_region_end,
                                             std::string_view what);

}  // namespace strielad::format
