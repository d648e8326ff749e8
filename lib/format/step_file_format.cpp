// SPDX-License-Identifier: Apache-2.0
#include "format/step_file_format.h"

#include <zstd.h>

#include <cmath>
#include <cstring>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "core/error.h"

namespace strielad::format {
namespace {

constexpr std::string_view kHeaderMagic = "STRLDSTP";
constexpr std::string_view kEndMagic = "STRLDEND";

void check_magic(std::span<const std::byte> found, std::string_view expected,
                 std::string_view what) {
  if (found.size() != expected.size() ||
      std::memcmp(found.data(), expected.data(), expected.size()) != 0) {
    std::string shown;
    for (std::byte b : found) {
      const char c = static_cast<char>(b);
      shown += (c >= 32 && c < 127) ? c : '?';
    }
    throw make_error(ErrorCode::kCorrupt, "{}: bad magic: expected '{}', found '{}'", what,
                     expected, shown);
  }
}

void check_checksum(std::uint64_t stored, std::uint64_t computed, std::string_view what,
                    std::string_view object) {
  if (stored != computed) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: {} checksum mismatch (stored {:016x}, computed {:016x})", what, object,
                     stored, computed);
  }
}

void check_reserved_zero(std::uint64_t value, std::string_view field, std::string_view what) {
  if (value != 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: reserved field '{}' is {} (must be 0)", what, field,
                     value);
  }
}

void check_exact_size(std::span<const std::byte> bytes, std::size_t size, std::string_view what,
                      std::string_view object) {
  if (bytes.size() < size) {
    throw make_error(ErrorCode::kTruncated, "{}: {} needs {} bytes, only {} present", what, object,
                     size, bytes.size());
  }
  if (bytes.size() > size) {
    throw make_error(ErrorCode::kCorrupt, "{}: {} is {} bytes, expected {}", what, object,
                     bytes.size(), size);
  }
}

void check_version(std::uint32_t version, std::string_view what) {
  if (version > kStepFileFormatVersion) {
    throw make_error(ErrorCode::kVersionTooNew,
                     "{}: format version {} is newer than this reader (max {})", what, version,
                     kStepFileFormatVersion);
  }
  if (version == 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: format version 0 is invalid", what);
  }
}

}  // namespace

std::vector<std::byte> encode_step_header(const StepHeader& h) {
  ByteWriter w;
  w.text(kHeaderMagic);
  w.u32(kStepFileFormatVersion);
  w.u32(kStepHeaderSize);
  w.u64(h.store_id);
  w.u32(h.step);
  w.u32(h.variable_count);
  w.u32(h.node_count);
  w.zeros(20);
  w.u64(checksum64(w.data()));
  return w.take();
}

StepHeader decode_step_header(std::span<const std::byte> bytes, std::string_view what) {
  check_exact_size(bytes, kStepHeaderSize, what, "step header");
  ByteReader r(bytes, what);
  check_magic(r.bytes(8, "magic"), kHeaderMagic, what);
  check_version(r.u32("format_version"), what);
  const std::uint32_t header_size = r.u32("header_size");
  if (header_size != kStepHeaderSize) {
    throw make_error(ErrorCode::kCorrupt, "{}: header_size is {} (expected {})", what, header_size,
                     kStepHeaderSize);
  }
  StepHeader h;
  h.store_id = r.u64("store_id");
  h.step = r.u32("step");
  h.variable_count = r.u32("variable_count");
  h.node_count = r.u32("node_count");
  for (int i = 0; i < 5; ++i) check_reserved_zero(r.u32("reserved"), "reserved", what);
  check_checksum(r.u64("header_checksum"), checksum64(bytes.first(56)), what, "step header");
  return h;
}

std::vector<std::byte> encode_step_footer(const StepFooter& f) {
  ByteWriter w;
  w.u64(f.section_table_offset);
  w.u32(f.variable_count);
  w.u32(f.node_count);
  w.u64(f.store_id);
  w.u32(f.step);
  w.u32(0);
  w.u64(f.section_table_checksum);
  w.u64(f.chunk_bytes);
  w.u64(checksum64(w.data()));
  w.text(kEndMagic);
  return w.take();
}

StepFooter decode_step_footer(std::span<const std::byte> bytes, std::string_view what) {
  check_exact_size(bytes, kStepFooterSize, what, "step footer");
  check_magic(bytes.subspan(56, 8), kEndMagic, what);
  ByteReader r(bytes, what);
  StepFooter f;
  f.section_table_offset = r.u64("section_table_offset");
  f.variable_count = r.u32("variable_count");
  f.node_count = r.u32("node_count");
  f.store_id = r.u64("store_id");
  f.step = r.u32("step");
  const std::uint32_t reserved = r.u32("reserved");
  f.section_table_checksum = r.u64("section_table_checksum");
  f.chunk_bytes = r.u64("chunk_bytes");
  check_checksum(r.u64("footer_checksum"), checksum64(bytes.first(48)), what, "step footer");
  check_reserved_zero(reserved, "reserved", what);
  return f;
}

std::vector<std::byte> encode_section_table(std::span<const SectionEntry> entries) {
  ByteWriter w;
  for (const SectionEntry& e : entries) {
    w.u32(e.variable);
    w.u32(static_cast<std::uint32_t>(e.codec));
    w.u64(e.offset);
    w.u64(e.stored_size);
    w.u64(e.raw_size);
    w.u64(e.checksum);
    w.u64(0);
  }
  return w.take();
}

std::vector<SectionEntry> decode_section_table(std::span<const std::byte> bytes,
                                               std::uint32_t variable_count,
                                               std::uint32_t node_count,
                                               std::uint64_t expected_checksum,
                                               std::uint64_t section_region_begin,
                                               std::uint64_t section_region_end,
                                               std::string_view what) {
  check_exact_size(bytes, std::size_t{variable_count} * kSectionEntrySize, what, "section table");
  check_checksum(expected_checksum, checksum64(bytes), what, "section table");
  ByteReader r(bytes, what);
  std::vector<SectionEntry> out(variable_count);
  for (std::uint32_t v = 0; v < variable_count; ++v) {
    SectionEntry& e = out[v];
    e.variable = r.u32("variable");
    const std::uint32_t codec = r.u32("codec");
    e.offset = r.u64("offset");
    e.stored_size = r.u64("stored_size");
    e.raw_size = r.u64("raw_size");
    e.checksum = r.u64("checksum");
    check_reserved_zero(r.u64("reserved"), "reserved", what);
    if (e.variable != v) {
      throw make_error(ErrorCode::kCorrupt, "{}: section table entry {} names variable {}", what, v,
                       e.variable);
    }
    if (codec > 1) {
      throw make_error(ErrorCode::kCorrupt, "{}: section of variable {} has unknown codec {}", what,
                       v, codec);
    }
    e.codec = static_cast<SectionCodec>(codec);
    if (e.raw_size != std::uint64_t{node_count} * kIndexEntrySize) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: section of variable {} has raw size {} (expected {} for {} nodes)",
                       what, v, e.raw_size, std::uint64_t{node_count} * kIndexEntrySize,
                       node_count);
    }
    if (e.offset < section_region_begin || e.offset > section_region_end ||
        e.stored_size > section_region_end - e.offset) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: section of variable {} at offset {} size {} lies outside [{}, {})",
                       what, v, e.offset, e.stored_size, section_region_begin, section_region_end);
    }
  }
  return out;
}

std::vector<std::byte> encode_index_section(std::span<const IndexEntry> entries,
                                            SectionCodec codec) {
  ByteWriter w;
  for (const IndexEntry& e : entries) {
    w.u64(e.chunk_offset);
    w.u32(e.chunk_size);
    w.u8(static_cast<std::uint8_t>(e.kind));
    w.u8(static_cast<std::uint8_t>(e.coding));
    w.zeros(2);
    w.u64(e.chunk_checksum);
    w.u64(e.valid_count);
    w.f64(e.min);
    w.f64(e.max);
    w.f64(e.constant);
  }
  std::vector<std::byte> raw = w.take();
  if (codec == SectionCodec::kRaw) return raw;
  std::vector<std::byte> out(ZSTD_compressBound(raw.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 3);
  if (ZSTD_isError(n)) {
    throw make_error(ErrorCode::kInternal, "zstd compression of an index section failed: {}",
                     ZSTD_getErrorName(n));
  }
  out.resize(n);
  return out;
}

std::vector<IndexEntry> decode_index_section(std::span<const std::byte> stored,
                                             const SectionEntry& section,
                                             std::uint32_t node_count,
                                             std::uint64_t chunk_region_begin,
                                             std::uint64_t chunk_region_end,
                                             std::string_view what) {
  check_exact_size(stored, section.stored_size, what, "index section");
  check_checksum(section.checksum, checksum64(stored), what, "index section");
  const std::size_t raw_size = std::size_t{node_count} * kIndexEntrySize;
  std::vector<std::byte> raw;
  std::span<const std::byte> view = stored;
  if (section.codec == SectionCodec::kZstd) {
    const unsigned long long frame = ZSTD_getFrameContentSize(stored.data(), stored.size());
    if (frame == ZSTD_CONTENTSIZE_ERROR || frame != raw_size) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: index section is not a zstd frame of {} bytes", what, raw_size);
    }
    raw.resize(raw_size);
    const std::size_t n = ZSTD_decompress(raw.data(), raw.size(), stored.data(), stored.size());
    if (ZSTD_isError(n) || n != raw_size) {
      throw make_error(ErrorCode::kCorrupt, "{}: index section does not decompress: {}", what,
                       ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size");
    }
    view = raw;
  }
  check_exact_size(view, raw_size, what, "decompressed index section");
  ByteReader r(view, what);
  std::vector<IndexEntry> out(node_count);
  for (std::uint32_t n = 0; n < node_count; ++n) {
    IndexEntry& e = out[n];
    e.chunk_offset = r.u64("chunk_offset");
    e.chunk_size = r.u32("chunk_size");
    const std::uint8_t kind = r.u8("kind");
    const std::uint8_t coding = r.u8("coding");
    const std::uint8_t r1 = r.u8("reserved"), r2 = r.u8("reserved");
    e.chunk_checksum = r.u64("chunk_checksum");
    e.valid_count = r.u64("valid_count");
    e.min = r.f64("min");
    e.max = r.f64("max");
    e.constant = r.f64("constant");
    auto bad = [&](std::string_view why) {
      return make_error(ErrorCode::kCorrupt, "{}: index entry of node {}: {}", what, n, why);
    };
    if (r1 | r2) throw bad("reserved bytes are not zero");
    if (kind > 2) throw bad(fmt::format("unknown brick kind {}", kind));
    if (coding > 2) throw bad(fmt::format("unknown chunk coding {}", coding));
    e.kind = static_cast<BrickKind>(kind);
    e.coding = static_cast<ChunkCoding>(coding);
    if (e.coding != ChunkCoding::kCodec && e.kind != BrickKind::kData) {
      throw bad("a brick without data has a chunk coding set");
    }
    if (e.kind == BrickKind::kData) {
      if (e.chunk_size == 0 || e.chunk_offset < chunk_region_begin ||
          e.chunk_offset > chunk_region_end || e.chunk_size > chunk_region_end - e.chunk_offset) {
        throw bad(fmt::format("chunk at offset {} size {} lies outside the chunk region [{}, {})",
                              e.chunk_offset, e.chunk_size, chunk_region_begin, chunk_region_end));
      }
    } else if (e.chunk_offset != 0 || e.chunk_size != 0 || e.chunk_checksum != 0) {
      throw bad("a brick without data has chunk fields set");
    }
    if (e.kind == BrickKind::kConstant && !std::isfinite(e.constant)) {
      throw bad("constant brick value is not finite");
    }
    if (e.kind != BrickKind::kConstant && e.constant != 0) throw bad("constant set on a non-constant brick");
    const bool min_nan = std::isnan(e.min), max_nan = std::isnan(e.max);
    if (min_nan != max_nan) throw bad("exactly one of min and max is NaN");
    if (min_nan && e.valid_count != 0) throw bad("valid samples counted but no value range");
    if (!min_nan && (!(e.min <= e.max) || std::isinf(e.min) || std::isinf(e.max))) {
      throw bad(fmt::format("invalid value range [{}, {}]", e.min, e.max));
    }
    if (min_nan && e.kind != BrickKind::kEmpty) throw bad("a brick with data has no value range");
  }
  return out;
}

}  // namespace strielad::format
