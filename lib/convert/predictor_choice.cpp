// SPDX-License-Identifier: Apache-2.0
#include "convert/predictor_choice.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "ingest/box_reader.h"
#include "convert/brick_encoder.h"
#include "core/error.h"

namespace strielad::build {
namespace {

struct Sizes {
  bool data = false;
  std::uint64_t none = 0, lorenzo3 = 0;
};

// Reads the bricks nodes[first, end) (one layer along z) through few large boxes of long
// rows: per row of bricks (y) one box from the first brick's to the last brick's x,
// whose rows are contiguous runs in the file (few large reads, also from a cold disk),
// or for filtered input one box over the whole layer, so that each chunk is
// decompressed once (the memory of one converter slab).
template <typename T>
void read_layer(BoxReader& reader, const OctreeLayout& layout, const std::vector<NodeKey>& nodes,
                const std::vector<IndexBox>& boxes, std::size_t first, std::size_t end,
                std::vector<std::vector<T>>& bricks) {
  const LevelShape& l0 = layout.level(0);
  const bool whole_layer = reader.filtered();
  std::unique_ptr<T[]> region;  // not zero-filled: the reader writes all of it
  std::size_t region_size = 0;
  struct Group {
    std::size_t begin, end;
    IndexBox region;
  };
  std::vector<Group> groups;
  for (std::size_t g = first; g < end;) {
    std::size_t g_end = g;  // nodes come z-major, then y: a row of bricks is contiguous
    while (g_end < end && (whole_layer || nodes[g_end].index[1] == nodes[g].index[1])) ++g_end;
    IndexBox r = boxes[g];
    if (whole_layer) {
      r.lo = {0, 0, r.lo[2]};
      r.hi = {l0.samples[0] - 1, l0.samples[1] - 1, r.hi[2]};
    } else {
      r.hi[0] = boxes[g_end - 1].hi[0];
    }
    groups.push_back({g, g_end, r});
    g = g_end;
  }
  for (const Group& group : groups) reader.prefetch(group.region);
  for (const auto& [g, g_end, r] : groups) {
    if (region_size < r.count()) {
      region.reset(new T[r.count()]);
      region_size = r.count();
    }
    reader.read(r, std::span<T>(region.get(), r.count()));
    const std::size_t rx = r.extent(0), ry = r.extent(1);
    for (std::size_t i = g; i < g_end; ++i) {
      const IndexBox& b = boxes[i];
      bricks[i].resize(b.count());
      T* dst = bricks[i].data();
      for (std::size_t z = b.lo[2]; z <= b.hi[2]; ++z)
        for (std::size_t y = b.lo[1]; y <= b.hi[1]; ++y, dst += b.extent(0)) {
          const T* src =
              region.get() + ((z - r.lo[2]) * ry + (y - r.lo[1])) * rx + (b.lo[0] - r.lo[0]);
          std::copy(src, src + b.extent(0), dst);
        }
    }
  }
}

// Layer by layer along z: read, encode both ways, add up; stop early once the sampled
// data bricks make the case clearly (kPredictorClearSaving).
template <typename T>
void sample_bricks(BoxReader& reader, const OctreeLayout& layout,
                   const std::vector<NodeKey>& nodes, const format::CodecSpec& codec,
                   PredictorTrial& trial) {
  std::vector<IndexBox> boxes;
  for (const NodeKey& key : nodes) boxes.push_back(layout.level_box(key));
  std::vector<std::vector<T>> bricks(nodes.size());
  std::vector<Sizes> sizes(nodes.size());
  format::CodecSpec none = codec, lorenzo3 = codec;
  none.predictor = format::kPredictorNone;
  lorenzo3.predictor = format::kPredictorLorenzo3;
  // The trial compares the codec chain alone; fpzip, where asked for, competes with the
  // chosen chain per brick afterwards (build/brick_encoder.cpp).
  none.fpzip = lorenzo3.fpzip = false;
  none.zfp = lorenzo3.zfp = std::nullopt;  // likewise zfp, for a lossy variable
  for (std::size_t first = 0; first < nodes.size();) {
    std::size_t end = first;
    while (end < nodes.size() && nodes[end].index[2] == nodes[first].index[2]) ++end;
    read_layer<T>(reader, layout, nodes, boxes, first, end, bricks);
    tbb::parallel_for(first, end, [&](std::size_t i) {
      const IndexBox local{{0, 0, 0},
                           {boxes[i].extent(0) - 1, boxes[i].extent(1) - 1, boxes[i].extent(2) - 1}};
      const PlaneBlock<T> block{bricks[i].data(),
                                {local.extent(0), local.extent(1), local.extent(2)},
                                0,
                                local.extent(2)};
      // Exactly what the converter does with this brick: empty and constant bricks store
      // no chunk and do not count.
      const EncodedBrick plain = encode_brick(block, local, &local, {}, none);
      if (plain.entry.kind != format::BrickKind::kData) return;
      sizes[i].data = true;
      sizes[i].none = plain.chunk.size();
      sizes[i].lorenzo3 = encode_brick(block, local, &local, {}, lorenzo3).chunk.size();
    });
    for (std::size_t i = first; i < end; ++i) {
      trial.data_bricks += sizes[i].data;
      trial.bytes_none += sizes[i].none;
      trial.bytes_lorenzo3 += sizes[i].lorenzo3;
      std::vector<T>().swap(bricks[i]);
    }
    trial.bricks_sampled = end;
    first = end;
    if (trial.data_bricks >= kPredictorClearMinBricks &&
        std::abs(trial.saving()) >= kPredictorClearSaving) {
      break;
    }
  }
}

}  // namespace

nlohmann::json PredictorTrial::to_json() const {
  return nlohmann::json{{"variable", variable},
                        {"chosen", chosen},
                        {"bricks_sampled", bricks_sampled},
                        {"data_bricks", data_bricks},
                        {"bytes_none", bytes_none},
                        {"bytes_lorenzo3", bytes_lorenzo3},
                        {"saving", saving()},
                        {"seconds", seconds}};
}

std::vector<NodeKey> predictor_sample_nodes(const OctreeLayout& layout,
                                            std::array<std::size_t, 3> per_axis) {
  const LevelShape& l0 = layout.level(0);
  std::array<std::vector<std::uint32_t>, 3> picks;
  for (int a = 0; a < 3; ++a) {
    const std::size_t total = l0.nodes[a];
    const std::size_t n = std::max<std::size_t>(1, std::min(total, per_axis[a]));
    for (std::size_t k = 0; k < n; ++k) {
      picks[a].push_back(static_cast<std::uint32_t>((2 * k + 1) * total / (2 * n)));
    }
  }
  std::vector<NodeKey> out;
  for (std::uint32_t z : picks[2])
    for (std::uint32_t y : picks[1])
      for (std::uint32_t x : picks[0]) out.push_back(NodeKey{0, {x, y, z}});
  return out;
}

std::string_view decide_predictor(std::uint64_t bytes_none, std::uint64_t bytes_lorenzo3) {
  const bool pays = bytes_none > 0 && static_cast<double>(bytes_lorenzo3) <
                                          (1.0 - kLorenzo3MinSaving) * static_cast<double>(bytes_none);
  return pays ? format::kPredictorLorenzo3 : format::kPredictorNone;
}

PredictorTrial choose_predictor(const ingest::InputCatalog& catalog,
                                const ingest::ScanOptions& scan, std::size_t variable,
                                const OctreeLayout& layout, const format::CodecSpec& codec) {
  const auto started = std::chrono::steady_clock::now();
  PredictorTrial trial;
  trial.variable = catalog.variables.at(variable).name;
  BoxReader reader(catalog, scan, variable, 0);
  auto per_axis = kPredictorSamples;
  if (reader.filtered()) per_axis[2] = 1;
  const auto nodes = predictor_sample_nodes(layout, per_axis);
  if (catalog.variables[variable].store_type == DType::kFloat32) {
    sample_bricks<float>(reader, layout, nodes, codec, trial);
  } else {
    sample_bricks<double>(reader, layout, nodes, codec, trial);
  }
  trial.chosen = decide_predictor(trial.bytes_none, trial.bytes_lorenzo3);
  trial.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return trial;
}

}  // namespace strielad::build
