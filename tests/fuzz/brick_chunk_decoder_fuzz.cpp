// SPDX-License-Identifier: Apache-2.0
// Fuzzes the brick chunk decoders behind the chunk checksum (Blosc, then the lorenzo3
// predictor's inverse on 5x5x5 and 1x3x5 bricks; fpzip chunks as float32 and float64):
// they must reject, never crash. The fuzzer recomputes checksums with ease (it learns the
// compared values), so fpzip chunks reach the stream check that stands between hostile
// bytes and fpzip's unbounded decoder (formats/store.md, "What fpzip sees"). libfpzip is
// not instrumented: the input sits flush against an inaccessible page, so a read past it
// by fpzip faults instead of going unseen.
#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "store/brick_codec.h"
#include "store/fpzip_chunk.h"
#include "support/guarded_bytes.h"

using namespace strielad;

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  std::vector<std::vector<std::uint8_t>> seeds;
  std::vector<float> samples(5 * 5 * 5);
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = (i % 7 == 0) ? 0.f : float(i) * 0.5f;
  const std::span<const std::byte> raw(reinterpret_cast<const std::byte*>(samples.data()),
                                       samples.size() * 4);
  for (const char* codec : {"zstd", "lz4", "blosclz"}) {
    for (const char* shuffle : {"byte", "bit"}) {
      const auto c = compress_brick(raw, DType::kFloat32, format::CodecSpec{codec, 5, shuffle});
      seeds.emplace_back(reinterpret_cast<const std::uint8_t*>(c.data()),
                         reinterpret_cast<const std::uint8_t*>(c.data()) + c.size());
      const auto p = compress_brick(raw, DType::kFloat32, BrickDims{5, 5, 5},
                                    format::CodecSpec{codec, 5, shuffle, "lorenzo3"});
      seeds.emplace_back(reinterpret_cast<const std::uint8_t*>(p.data()),
                         reinterpret_cast<const std::uint8_t*>(p.data()) + p.size());
    }
  }
  for (const auto& c : {compress_brick_fpzip(raw, DType::kFloat32, BrickDims{5, 5, 5}),
                        compress_brick_fpzip(raw.first(25 * 8), DType::kFloat64, BrickDims{1, 5, 5}),
                        compress_brick_fpzip(raw.first(15 * 4), DType::kFloat32, BrickDims{1, 3, 5})}) {
    if (c) seeds.emplace_back(reinterpret_cast<const std::uint8_t*>(c->data()),
                              reinterpret_cast<const std::uint8_t*>(c->data()) + c->size());
  }
  return seeds;
}

// An fpzip chunk must decode or be rejected as corrupt. kInternal would mean fpzip read
// other bytes than the stream check walked: the check and fpzip disagree, a finding.
static void decode_fpzip(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                         std::span<std::byte> out) {
  try {
    decompress_brick_fpzip(chunk, dtype, dims, out, "fuzz");
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kInternal) __builtin_trap();
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static testing::GuardedBytes guarded(std::size_t{1} << 20);
  if (size > guarded.capacity()) return 0;
  std::vector<std::byte> out(5 * 5 * 5 * 4);
  const std::span<const std::byte> chunk =
      guarded.place(std::span(reinterpret_cast<const std::byte*>(data), size));
  try {
    decompress_brick(chunk, DType::kFloat32, out, "fuzz");
  } catch (const Error&) {
  }
  const format::CodecSpec lorenzo3{"zstd", 1, "byte", "lorenzo3"};
  for (const BrickDims dims : {BrickDims{5, 5, 5}, BrickDims{1, 3, 5}}) {
    std::vector<std::byte> bytes(dims[0] * dims[1] * dims[2] * 4);
    try {
      decompress_brick(chunk, DType::kFloat32, dims, lorenzo3, bytes, "fuzz");
    } catch (const Error&) {
    }
    decode_fpzip(chunk, DType::kFloat32, dims, bytes);
  }
  std::vector<std::byte> wide(1 * 5 * 5 * 8);
  decode_fpzip(chunk, DType::kFloat64, BrickDims{1, 5, 5}, wide);
  return 0;
}
