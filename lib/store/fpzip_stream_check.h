// SPDX-License-Identifier: Apache-2.0
// Checks an fpzip stream before fpzip decodes it. fpzip 1.3's decoder trusts its input:
// it reads past the end of the stream, and a cumulative frequency outside its model's
// total indexes the model's tables out of bounds (heap reads and a write), which ends in
// SIGSEGV or a division by zero. Which bytes it reads and which symbols it decodes depend
// only on the stream, the brick's dims and the sample type, never on the decoded values,
// so the walk below runs the same integer range decoding and adaptive model with every
// read bounded, and says whether fpzip would stay inside the stream and its tables.
// formats/store.md, "What fpzip sees", states the argument in full.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad {

// Largest brick side an fpzip chunk may have: fpzip sizes its prediction front with
// 32-bit arithmetic, (n_x + 1) * (n_y + 1) must not wrap.
inline constexpr std::size_t kMaxFpzipBrickSide = std::size_t{1} << 15;

// Walks `stream` (an fpzip stream without an fpzip header, full precision, one field, as
// compress_brick_fpzip writes it) as fpzip's decoder will for a brick of `dims` samples of
// `dtype`. Returns the number of stream bytes fpzip will read (what fpzip_read returns).
// Throws kCorrupt naming `what` when fpzip would read past the stream, when a symbol lies
// outside the model's frequencies, or when a brick side is 0 or above kMaxFpzipBrickSide.
std::size_t check_fpzip_stream(std::span<const std::byte> stream, DType dtype, BrickDims dims,
                               std::string_view what);

}  // namespace strielad
