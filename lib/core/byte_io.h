// SPDX-License-Identifier: Apache-2.0
// Explicit little-endian encoding of fixed-width fields. No raw struct dumps: every
// format in formats/ is written and read field by field through these two classes.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace strielad {

static_assert(std::endian::native == std::endian::little,
              "byte_io assumes a little-endian host; add byte swapping to port");

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(static_cast<std::byte>(v)); }
  void u16(std::uint16_t v) { put(&v, sizeof v); }
  void u32(std::uint32_t v) { put(&v, sizeof v); }
  void u64(std::uint64_t v) { put(&v, sizeof v); }
  void i32(std::int32_t v) { put(&v, sizeof v); }
  void f32(float v) { put(&v, sizeof v); }
  void f64(double v) { put(&v, sizeof v); }
  void bytes(std::span<const std::byte> v) { bytes_.insert(bytes_.end(), v.begin(), v.end()); }
  void text(std::string_view v) { put(v.data(), v.size()); }
  void zeros(std::size_t n) { bytes_.insert(bytes_.end(), n, std::byte{0}); }

  std::size_t size() const { return bytes_.size(); }
  const std::vector<std::byte>& data() const { return bytes_; }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  void put(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::byte*>(p);
    bytes_.insert(bytes_.end(), b, b + n);
  }
  std::vector<std::byte> bytes_;
};

// Bounds-checked reader. Every read names its field so that a truncated object gives
// "truncated: <what>: field 'x' at offset 40 needs 8 bytes, only 3 remain".
class ByteReader {
 public:
  ByteReader(std::span<const std::byte> bytes, std::string_view what)
      : bytes_(bytes), what_(what) {}

  std::uint8_t u8(std::string_view field) { return get<std::uint8_t>(field); }
  std::uint16_t u16(std::string_view field) { return get<std::uint16_t>(field); }
  std::uint32_t u32(std::string_view field) { return get<std::uint32_t>(field); }
  std::uint64_t u64(std::string_view field) { return get<std::uint64_t>(field); }
  std::int32_t i32(std::string_view field) { return get<std::int32_t>(field); }
  float f32(std::string_view field) { return get<float>(field); }
  double f64(std::string_view field) { return get<double>(field); }
  std::span<const std::byte> bytes(std::size_t n, std::string_view field) {
    require(n, field);
    auto out = bytes_.subspan(offset_, n);
    offset_ += n;
    return out;
  }
  void skip(std::size_t n, std::string_view field) { bytes(n, field); }

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return bytes_.size() - offset_; }

 private:
  void require(std::size_t n, std::string_view field) const {
    if (n > remaining()) {
      throw make_error(ErrorCode::kTruncated,
                       "{}: field '{}' at offset {} needs {} bytes, only {} remain", what_,
                       field, offset_, n, remaining());
    }
  }
  template <typename T>
  T get(std::string_view field) {
    require(sizeof(T), field);
    T v;
    std::memcpy(&v, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return v;
  }

  std::span<const std::byte> bytes_;
  std::string_view what_;
  std::size_t offset_ = 0;
};

inline std::span<const std::byte> as_bytes_of(std::string_view s) {
  return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}

}  // namespace strielad
