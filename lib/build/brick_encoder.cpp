// SPDX-License-Identifier: Apache-2.0
#include "build/brick_encoder.h"

#include <cmath>
#include <cstring>

#include "core/checksum.h"
#include "store/brick_codec.h"

namespace strielad::build {

void NodeStats::merge(const NodeStats& o) {
  valid_count += o.valid_count;
  if (std::isnan(o.min)) return;
  if (std::isnan(min) || o.min < min) min = o.min;
  if (std::isnan(max) || o.max > max) max = o.max;
}

template <typename T>
EncodedBrick encode_brick(const PlaneBlock<T>& planes, const IndexBox& box, const IndexBox* owned,
                          NodeStats stats, const format::CodecSpec& codec) {
  std::vector<T> samples;
  samples.reserve(box.count());
  if (owned) stats = NodeStats{};
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z) {
    for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y) {
      const T* row = &planes.at(box.lo[0], y, z);
      const std::size_t n = box.extent(0);
      samples.insert(samples.end(), row, row + n);
      if (!owned) continue;
      const bool owned_row = z >= owned->lo[2] && z <= owned->hi[2] && y >= owned->lo[1] &&
                             y <= owned->hi[1];
      for (std::size_t i = 0; i < n; ++i) {
        const T v = row[i];
        if (std::isnan(v)) continue;
        const double d = static_cast<double>(v);
        if (std::isnan(stats.min) || d < stats.min) stats.min = d;
        if (std::isnan(stats.max) || d > stats.max) stats.max = d;
        const std::size_t x = box.lo[0] + i;
        if (owned_row && x >= owned->lo[0] && x <= owned->hi[0]) ++stats.valid_count;
      }
    }
  }

  EncodedBrick out;
  out.entry.valid_count = stats.valid_count;
  out.entry.min = stats.min;
  out.entry.max = stats.max;

  bool all_missing = true, all_equal = true;
  for (const T& v : samples) {
    if (!std::isnan(v)) all_missing = false;
    if (std::memcmp(&v, &samples.front(), sizeof(T)) != 0) all_equal = false;
  }
  if (all_missing) {
    out.entry.kind = format::BrickKind::kEmpty;
  } else if (all_equal) {  // bitwise equal and not NaN (NaN would be all_missing)
    out.entry.kind = format::BrickKind::kConstant;
    out.entry.constant = static_cast<double>(samples.front());
  } else {
    out.entry.kind = format::BrickKind::kData;
    const std::span<const std::byte> raw(reinterpret_cast<const std::byte*>(samples.data()),
                                         samples.size() * sizeof(T));
    out.chunk = compress_brick(raw, sizeof(T) == 4 ? DType::kFloat32 : DType::kFloat64, codec);
    out.entry.chunk_size = static_cast<std::uint32_t>(out.chunk.size());
    out.entry.chunk_checksum = checksum64(out.chunk);
  }
  return out;
}

template EncodedBrick encode_brick<float>(const PlaneBlock<float>&, const IndexBox&,
                                          const IndexBox*, NodeStats, const format::CodecSpec&);
template EncodedBrick encode_brick<double>(const PlaneBlock<double>&, const IndexBox&,
                                           const IndexBox*, NodeStats, const format::CodecSpec&);

}  // namespace strielad::build
