// SPDX-License-Identifier: Apache-2.0
#include "format/step_file_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/checksum.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using testing::expect_error;

StepHeader sample_header() { return StepHeader{0x1234567890abcdefull, 7, 3, 51393}; }

TEST(StepFileFormatTest, HeaderRoundTrip) {
  const auto bytes = encode_step_header(sample_header());
  ASSERT_EQ(bytes.size(), kStepHeaderSize);
  EXPECT_EQ(decode_step_header(bytes, "h"), sample_header());
}

TEST(StepFileFormatTest, GeometryBricksHeaderAndFooterCarryTheGeometryStep) {
  const StepHeader header{0x1234567890abcdefull, kGeometryStep, 1, 51393};
  EXPECT_EQ(decode_step_header(encode_step_header(header), "geometry.bricks"), header);
  const StepFooter footer{64, 1, 51393, 0x1234567890abcdefull, kGeometryStep, 5, 6};
  EXPECT_EQ(decode_step_footer(encode_step_footer(footer), "geometry.bricks").step, kGeometryStep);
}

TEST(StepFileFormatTest, HeaderCorruptMagic) {
  auto bytes = encode_step_header(sample_header());
  bytes[0] = std::byte{'X'};
  expect_error([&] { decode_step_header(bytes, "f.bricks"); }, ErrorCode::kCorrupt,
               {"f.bricks", "bad magic", "XTRLDSTP"});
}

TEST(StepFileFormatTest, HeaderCorruptChecksum) {
  auto bytes = encode_step_header(sample_header());
  bytes[20] ^= std::byte{0x01};
  expect_error([&] { decode_step_header(bytes, "f.bricks"); }, ErrorCode::kCorrupt,
               {"step header checksum mismatch"});
}

TEST(StepFileFormatTest, HeaderInvalidVersion) {
  auto bytes = encode_step_header(sample_header());
  bytes[8] = std::byte{2};
  expect_error([&] { decode_step_header(bytes, "f.bricks"); }, ErrorCode::kVersionTooNew,
               {"version 2 is newer than this reader (max 1)"});
  bytes[8] = std::byte{0};
  expect_error([&] { decode_step_header(bytes, "f.bricks"); }, ErrorCode::kCorrupt, {"version 0"});
}

TEST(StepFileFormatTest, HeaderTruncated) {
  const auto bytes = encode_step_header(sample_header());
  expect_error([&] { decode_step_header(std::span(bytes).first(40), "f.bricks"); },
               ErrorCode::kTruncated, {"needs 64 bytes, only 40"});
}

TEST(StepFileFormatTest, HeaderNonZeroReservedIsRejected) {
  auto bytes = encode_step_header(sample_header());
  bytes[40] = std::byte{1};
  // Re-seal the checksum so that only the reserved rule can reject it.
  const std::uint64_t sum = checksum64(std::span(bytes).first(56));
  std::memcpy(bytes.data() + 56, &sum, 8);
  expect_error([&] { decode_step_header(bytes, "f.bricks"); }, ErrorCode::kCorrupt, {"reserved"});
}

TEST(StepFileFormatTest, FooterRoundTripAndCorruption) {
  StepFooter f{1000, 3, 99, 0xabcull, 4, 0x55ull, 900};
  auto bytes = encode_step_footer(f);
  ASSERT_EQ(bytes.size(), kStepFooterSize);
  EXPECT_EQ(decode_step_footer(bytes, "f"), f);
  auto flipped = bytes;
  flipped[3] ^= std::byte{0x10};
  expect_error([&] { decode_step_footer(flipped, "f"); }, ErrorCode::kCorrupt, {"footer checksum"});
  auto magic = bytes;
  magic[63] = std::byte{'?'};
  expect_error([&] { decode_step_footer(magic, "f"); }, ErrorCode::kCorrupt, {"bad magic"});
}

std::vector<IndexEntry> sample_entries() {
  std::vector<IndexEntry> e(3);
  e[0].kind = BrickKind::kEmpty;
  e[0].min = e[0].max = std::nan("");
  e[1].kind = BrickKind::kConstant;
  e[1].constant = 0.0;
  e[1].min = 0.0;
  e[1].max = 0.25;
  e[1].valid_count = 10;
  e[2].kind = BrickKind::kData;
  e[2].chunk_offset = 64;
  e[2].chunk_size = 100;
  e[2].chunk_checksum = 77;
  e[2].min = -3;
  e[2].max = 1e30;
  e[2].valid_count = 1000;
  return e;
}

SectionEntry section_for(const std::vector<std::byte>& stored, SectionCodec codec) {
  return SectionEntry{0, codec, 200, stored.size(), 3 * kIndexEntrySize, checksum64(stored)};
}

TEST(StepFileFormatTest, IndexSectionRoundTripBothCodecs) {
  for (SectionCodec codec : {SectionCodec::kRaw, SectionCodec::kZstd}) {
    const auto stored = encode_index_section(sample_entries(), codec);
    const auto out = decode_index_section(stored, section_for(stored, codec), 3, 64, 200, "s");
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[1].kind, BrickKind::kConstant);
    EXPECT_EQ(out[1].max, 0.25);
    EXPECT_TRUE(std::isnan(out[0].min));
    EXPECT_EQ(out[2].chunk_size, 100u);
    EXPECT_EQ(out[2].max, 1e30);
  }
}

TEST(StepFileFormatTest, IndexEntryChunkCodingRoundTripsAndIsChecked) {
  auto entries = sample_entries();
  entries[2].coding = ChunkCoding::kFpzip;
  auto stored = encode_index_section(entries, SectionCodec::kRaw);
  EXPECT_EQ(stored[2 * kIndexEntrySize + 13], std::byte{1});  // byte 13 of the entry
  const auto out = decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s");
  EXPECT_EQ(out[2].coding, ChunkCoding::kFpzip);
  EXPECT_EQ(out[1].coding, ChunkCoding::kCodec);
  stored[2 * kIndexEntrySize + 13] = std::byte{2};  // a zfp chunk (store version 6)
  EXPECT_EQ(decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s")[2].coding,
            ChunkCoding::kZfp);
  stored[2 * kIndexEntrySize + 13] = std::byte{3};
  expect_error([&] { decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s"); },
               ErrorCode::kCorrupt, {"node 2", "unknown chunk coding 3"});
  stored[2 * kIndexEntrySize + 13] = std::byte{1};
  stored[1 * kIndexEntrySize + 13] = std::byte{1};  // a constant brick has no chunk
  expect_error([&] { decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s"); },
               ErrorCode::kCorrupt, {"node 1", "without data has a chunk coding"});
  stored[1 * kIndexEntrySize + 13] = std::byte{0};
  stored[2 * kIndexEntrySize + 14] = std::byte{1};  // still reserved
  expect_error([&] { decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s"); },
               ErrorCode::kCorrupt, {"node 2", "reserved bytes are not zero"});
}

TEST(StepFileFormatTest, IndexSectionCorruptChecksum) {
  auto stored = encode_index_section(sample_entries(), SectionCodec::kZstd);
  const SectionEntry s = section_for(stored, SectionCodec::kZstd);
  stored[stored.size() / 2] ^= std::byte{0x40};
  expect_error([&] { decode_index_section(stored, s, 3, 64, 200, "s"); }, ErrorCode::kCorrupt,
               {"index section checksum mismatch"});
}

TEST(StepFileFormatTest, IndexEntryChunkOutsideChunkRegionIsRejected) {
  auto entries = sample_entries();
  entries[2].chunk_offset = 150;  // 150 + 100 > 200
  const auto stored = encode_index_section(entries, SectionCodec::kRaw);
  expect_error([&] { decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s"); },
               ErrorCode::kCorrupt, {"node 2", "outside the chunk region"});
}

TEST(StepFileFormatTest, IndexEntryInvertedRangeIsRejected) {
  auto entries = sample_entries();
  entries[1].min = 1;
  entries[1].max = 0;
  const auto stored = encode_index_section(entries, SectionCodec::kRaw);
  expect_error([&] { decode_index_section(stored, section_for(stored, SectionCodec::kRaw), 3, 64, 200, "s"); },
               ErrorCode::kCorrupt, {"node 1", "invalid value range"});
}

TEST(StepFileFormatTest, SectionTableRejectsSectionsOutsideTheirRegion) {
  std::vector<SectionEntry> table{{0, SectionCodec::kZstd, 100, 50, 2 * kIndexEntrySize, 1}};
  const auto bytes = encode_section_table(table);
  EXPECT_EQ(decode_section_table(bytes, 1, 2, checksum64(bytes), 64, 150, "t")[0], table[0]);
  expect_error([&] { decode_section_table(bytes, 1, 2, checksum64(bytes), 64, 120, "t"); },
               ErrorCode::kCorrupt, {"outside"});
  expect_error([&] { decode_section_table(bytes, 1, 3, checksum64(bytes), 64, 150, "t"); },
               ErrorCode::kCorrupt, {"raw size"});
  expect_error([&] { decode_section_table(bytes, 1, 2, 12345, 64, 150, "t"); },
               ErrorCode::kCorrupt, {"section table checksum"});
}

}  // namespace
}  // namespace strielad::format
