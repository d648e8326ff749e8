// SPDX-License-Identifier: Apache-2.0
// Turns the samples of one node into an index entry and (for data bricks) a compressed
// chunk: decides the brick kind and, at level 0, computes the exact statistics.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "convert/level_sampler.h"
#include "format/manifest.h"
#include "format/step_file_format.h"
#include "octree/octree_layout.h"

namespace strielad::build {

struct EncodedBrick {
  format::IndexEntry entry;          // chunk_offset is filled in by the step writer
  std::vector<std::byte> chunk;      // empty unless entry.kind == kData
  // A data brick of a lossy variable that zfp did not code within the bound, kept as a
  // codec-chain chunk (lossless) instead.
  bool lossy_fallback = false;
};

// Statistics of a node: min/max over the covered samples, valid count over owned ones.
struct NodeStats {
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t valid_count = 0;
  void merge(const NodeStats& other);
};

// For a variable with fpzip on, which coder a data brick tries depends on its share of
// zero samples (either sign): below the first, fpzip alone when it at least halves the
// brick; below the second, fpzip and the Blosc chain, the smaller kept; from the second
// up, the Blosc chain alone.
inline constexpr double kFpzipAloneBelowZeroShare = 0.5;
inline constexpr double kFpzipTriedBelowZeroShare = 0.8;

// zfp's fixed-accuracy errors stay far below its tolerance (0.04 to 0.25 of it on the
// sample: BENCHMARKS.md, "lossy"), so a lossy brick is coded with zfp's tolerance at these
// multiples of the bound in turn, keeping the first chunk whose every sample is within the
// bound: 8x suits the dense fields, cloud water mostly needs 4x, 1x is zfp's own promise.
inline constexpr std::array<double, 3> kZfpAccuracyLadder{8.0, 4.0, 1.0};

// For a variable with a lossy codec (format::CodecSpec::zfp), each data brick is a zfp
// chunk when zfp codes it within the bound (decoded and compared, store/zfp_chunk.h) into
// fewer bytes than the codec chain; otherwise the codec chain's chunk, and a brick that
// missed the bound counts as a fallback.
//
// Encodes the brick `box` (inclusive, level-grid indices) held in `planes`. When
// `owned` is given (level 0) the statistics are computed from the samples: min/max over
// `box`, valid_count over `owned`; otherwise (coarse levels) `stats`, the merged
// statistics of the node's children, with min/max widened to the brick's own valid
// samples.
template <typename T>
EncodedBrick encode_brick(const PlaneBlock<T>& planes, const IndexBox& box,
                          const IndexBox* owned, NodeStats stats, const format::CodecSpec& codec);

extern template EncodedBrick encode_brick<float>(const PlaneBlock<float>&, const IndexBox&,
                                                 const IndexBox*, NodeStats,
                                                 const format::CodecSpec&);
extern template EncodedBrick encode_brick<double>(const PlaneBlock<double>&, const IndexBox&,
                                                  const IndexBox*, NodeStats,
                                                  const format::CodecSpec&);

}  // namespace strielad::build
