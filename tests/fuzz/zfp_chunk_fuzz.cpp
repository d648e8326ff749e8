// SPDX-License-Identifier: Apache-2.0
// Fuzzes the zfp chunk decoder (formats/store.md, "zfp chunks (version 6)") on 5x5x5
// float32 and 1x5x5 float64 bricks: it must decode or reject as corrupt, never crash, and
// never hand zfp more than its zero-padded copy of the stream ("What zfp sees"). The
// fuzzer recomputes the stream checksum with ease, so hostile streams and runs reach zfp.
// libzfp is not instrumented: the input sits flush against an inaccessible page, so a
// read of the chunk past its end faults instead of going unseen.
#include <cmath>

#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "store/zfp_chunk.h"
#include "support/guarded_bytes.h"

using namespace strielad;

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  std::vector<std::vector<std::uint8_t>> seeds;
  std::vector<float> narrow(5 * 5 * 5);
  std::vector<double> wide(1 * 5 * 5);
  for (std::size_t i = 0; i < narrow.size(); ++i) {
    narrow[i] = (i % 11 == 3) ? std::nanf("") : 280.f + std::sin(float(i) * 0.3f);
  }
  for (std::size_t i = 0; i < wide.size(); ++i) wide[i] = (i % 7 == 0) ? std::nan("") : 1e-3 * double(i);
  const auto add = [&](const ZfpCodingResult& r) {
    if (r.outcome == ZfpOutcome::kCoded) {
      seeds.emplace_back(reinterpret_cast<const std::uint8_t*>(r.chunk.data()),
                         reinterpret_cast<const std::uint8_t*>(r.chunk.data()) + r.chunk.size());
    }
  };
  for (const double tol : {0.5, 0.01}) {
    add(compress_brick_zfp(std::as_bytes(std::span(narrow)), DType::kFloat32, BrickDims{5, 5, 5},
                           tol, tol));
    add(compress_brick_zfp(std::as_bytes(std::span(wide)), DType::kFloat64, BrickDims{1, 5, 5},
                           tol * 1e-3, tol * 1e-3));
  }
  return seeds;
}

// kInternal would be a finding (an inconsistency between the checks and zfp).
static void decode(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                   std::span<std::byte> out) {
  try {
    decompress_brick_zfp(chunk, dtype, dims, out, "fuzz");
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kInternal) __builtin_trap();
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static testing::GuardedBytes guarded(std::size_t{1} << 20);
  if (size > guarded.capacity()) return 0;
  const std::span<const std::byte> chunk =
      guarded.place(std::span(reinterpret_cast<const std::byte*>(data), size));
  std::vector<std::byte> narrow(5 * 5 * 5 * 4), wide(1 * 5 * 5 * 8);
  decode(chunk, DType::kFloat32, BrickDims{5, 5, 5}, narrow);
  decode(chunk, DType::kFloat64, BrickDims{1, 5, 5}, wide);
  return 0;
}
