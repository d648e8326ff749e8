// SPDX-License-Identifier: Apache-2.0
// Fuzzes every step-file decoder: header, footer, section table and index section.
#include <cmath>

#include "core/checksum.h"
#include "core/error.h"
#include "format/step_file_format.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;
using namespace strielad::format;

namespace {

std::vector<std::uint8_t> to_u8(const std::vector<std::byte>& b) {
  return {reinterpret_cast<const std::uint8_t*>(b.data()),
          reinterpret_cast<const std::uint8_t*>(b.data()) + b.size()};
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  std::vector<IndexEntry> entries(4);
  entries[0].min = entries[0].max = NAN;
  entries[1].kind = BrickKind::kConstant;
  entries[1].constant = 1.5;
  entries[1].min = 1.5;
  entries[1].max = 2;
  entries[2].kind = BrickKind::kData;
  entries[2].chunk_offset = 64;
  entries[2].chunk_size = 10;
  entries[2].min = 0;
  entries[2].max = 1;
  entries[3] = entries[1];
  std::vector<SectionEntry> table{{0, SectionCodec::kZstd, 80, 30, 4 * kIndexEntrySize, 7}};
  return {to_u8(encode_step_header({1, 2, 1, 4})),
          to_u8(encode_step_footer({100, 1, 4, 1, 2, 3, 4})),
          to_u8(encode_section_table(table)),
          to_u8(encode_index_section(entries, SectionCodec::kZstd)),
          to_u8(encode_index_section(entries, SectionCodec::kRaw))};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  const auto attempt = [](auto&& f) {
    try {
      f();
    } catch (const Error&) {
    }
  };
  attempt([&] { decode_step_header(bytes, "fuzz"); });
  attempt([&] { decode_step_footer(bytes, "fuzz"); });
  attempt([&] {
    decode_section_table(bytes, static_cast<std::uint32_t>(size / kSectionEntrySize), 4,
                         checksum64(bytes), 64, 1 << 20, "fuzz");
  });
  for (SectionCodec codec : {SectionCodec::kRaw, SectionCodec::kZstd}) {
    attempt([&] {
      const SectionEntry s{0, codec, 100, size, 4 * kIndexEntrySize, checksum64(bytes)};
      decode_index_section(bytes, s, 4, 64, 100, "fuzz");
    });
  }
  return 0;
}
