// SPDX-License-Identifier: Apache-2.0
#include "convert/step_converter.h"

#include <sys/mman.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <vector>

#include "convert/brick_encoder.h"
#include "convert/level_sampler.h"
#include "convert/step_writer.h"
#include "core/error.h"

namespace strielad::build {
namespace {

// Plane buffers reused across slabs and variables. A fresh allocation of a slab (tens of
// MB) per layer is a new mapping every time: page faults, zeroing and unmapping in the
// kernel took a quarter of the conversion's CPU time (perf, 715 x 778 x 150). The pool
// holds no more buffers than the pipeline has slabs alive at once. Buffers are 2 MiB
// aligned and ask for transparent huge pages: the kernel's copy of the input into them
// (read(2), for input read through netCDF) was a quarter of the converter's CPU samples
// on the full paper step with 4 KiB pages and 3% with huge pages, and a whole conversion
// took about 10% less time (perf and A/B runs, 2026-11-23).
class PlaneBufferPool {
 public:
  // A buffer of at least `count` values; it returns to the pool when the last copy of the
  // pointer goes. Not zero-filled.
  template <typename T>
  std::shared_ptr<T[]> acquire(std::size_t count) {
    const std::size_t bytes = count * sizeof(T);
    Buffer buffer;
    {
      std::lock_guard lock(mutex_);
      const auto it = std::find_if(free_.begin(), free_.end(),
                                   [bytes](const Buffer& b) { return b.bytes >= bytes; });
      if (it != free_.end()) {
        buffer = std::move(*it);
        free_.erase(it);
      }
    }
    if (!buffer.data) buffer = Buffer{allocate_huge(bytes), bytes};
    T* values = reinterpret_cast<T*>(buffer.data.release());
    return std::shared_ptr<T[]>(values, [this, bytes = buffer.bytes](T* p) {
      std::lock_guard lock(mutex_);
      free_.push_back(Buffer{Memory(reinterpret_cast<std::byte*>(p)), bytes});
    });
  }

 private:
  struct FreeMemory {
    void operator()(std::byte* p) const { std::free(p); }
  };
  using Memory = std::unique_ptr<std::byte[], FreeMemory>;
  struct Buffer {
    Memory data;
    std::size_t bytes = 0;
  };

  // `bytes` rounded up to whole 2 MiB pages, not zero-filled.
  static Memory allocate_huge(std::size_t bytes) {
    constexpr std::size_t kHuge = std::size_t{2} << 20;
    const std::size_t rounded = (std::max<std::size_t>(bytes, 1) + kHuge - 1) / kHuge * kHuge;
    auto* p = static_cast<std::byte*>(std::aligned_alloc(kHuge, rounded));
    if (p == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without huge pages it works the same
#endif
    return Memory(p);
  }
  std::mutex mutex_;
  std::vector<Buffer> free_;
};

struct Context {
  PlaneBufferPool& buffers;
  const format::Manifest& manifest;
  const OctreeLayout& layout;
  ingest::SlabReader& reader;
  std::uint32_t step;
  StepWriter& writer;
  StepCounts& counts;
  const ProgressFn& progress;
};

void count_kind(StepCounts& c, const format::IndexEntry& e) {
  switch (e.kind) {
    case format::BrickKind::kEmpty: ++c.empty; break;
    case format::BrickKind::kConstant: ++c.constant; break;
    case format::BrickKind::kData: ++c.data; break;
  }
}

template <typename T>
struct Slab {
  std::shared_ptr<T[]> planes;  // not zero-filled: every plane is read or copied in
  std::size_t z_begin = 0, z_end = 0;  // planes held [z_begin, z_end)
  std::uint32_t layer = 0;
  std::vector<EncodedBrick> bricks;
};

std::array<bool, 3> halved_between(const OctreeLayout& layout, std::size_t fine_level) {
  std::array<bool, 3> h{};
  for (int a = 0; a < 3; ++a) {
    h[a] = layout.level(fine_level + 1).stride[a] != layout.level(fine_level).stride[a];
  }
  return h;
}

// Coarse planes whose centre plane lies in the fine planes [f0, f1] (inclusive);
// `last` extends the range to the end of the coarse grid.
std::pair<std::size_t, std::size_t> coarse_planes_for(std::size_t f0, std::size_t f1, bool halved,
                                                      bool last, std::size_t coarse_n) {
  if (!halved) return {f0, last ? coarse_n : f1 + 1};
  return {(f0 + 1) / 2, last ? coarse_n : f1 / 2 + 1};
}

template <typename T>
void convert_variable(Context& ctx, std::uint32_t v) {
  const OctreeLayout& layout = ctx.layout;
  const LevelShape& l0 = layout.level(0);
  const std::size_t nx = l0.samples[0], ny = l0.samples[1], nz = l0.samples[2];
  const std::size_t plane = nx * ny;
  const std::size_t B = layout.brick();
  const format::CodecSpec& codec = ctx.manifest.codec_of(v);
  const bool has_coarse = layout.level_count() > 1;
  const std::size_t src_size = source_type_size(ctx.manifest.variables[v].source_type);

  std::vector<T> coarse;
  std::array<std::size_t, 3> coarse_dims{};
  std::array<bool, 3> halved{};
  if (has_coarse) {
    coarse_dims = layout.level(1).samples;
    coarse.resize(coarse_dims[0] * coarse_dims[1] * coarse_dims[2]);
    halved = halved_between(layout, 0);
  }
  std::vector<NodeStats> stats(l0.node_count());

  // Level 0: read slabs in order (netCDF is serial), encode in parallel, append in order.
  std::uint32_t next_layer = 0;
  std::shared_ptr<T[]> previous;
  std::size_t prev_begin = 0, prev_end = 0;
  const std::size_t tokens = std::max(2, tbb::this_task_arena::max_concurrency());
  tbb::parallel_pipeline(
      tokens,
      tbb::make_filter<void, std::shared_ptr<Slab<T>>>(
          tbb::filter_mode::serial_in_order,
          [&](tbb::flow_control& fc) -> std::shared_ptr<Slab<T>> {
            if (next_layer == l0.nodes[2]) {
              fc.stop();
              return nullptr;
            }
            auto s = std::make_shared<Slab<T>>();
            s->layer = next_layer++;
            const std::size_t z_lo = std::size_t{s->layer} * B;
            const std::size_t z_hi = std::min(z_lo + B, nz - 1);
            s->z_begin = z_lo > 0 ? z_lo - 1 : 0;
            s->z_end = std::min(nz - 1, z_hi + 1) + 1;
            // Every slab asks for the largest size (B + 3 planes), so a buffer fits any layer.
            s->planes = ctx.buffers.acquire<T>(std::min(B + 3, nz) * plane);
            std::size_t read_from = s->z_begin;
            if (previous && prev_begin <= s->z_begin && prev_end > s->z_begin) {
              const std::size_t keep = std::min(prev_end, s->z_end) - s->z_begin;
              std::memcpy(s->planes.get(), previous.get() + (s->z_begin - prev_begin) * plane,
                          keep * plane * sizeof(T));
              read_from = s->z_begin + keep;
            }
            if (read_from < s->z_end) {
              std::span<T> out(s->planes.get() + (read_from - s->z_begin) * plane,
                               (s->z_end - read_from) * plane);
              ctx.reader.read(v, ctx.step, read_from, s->z_end, out);
              const std::uint64_t bytes = out.size() * src_size;
              ctx.counts.input_bytes += bytes;
              if (ctx.progress) ctx.progress(bytes);
            }
            previous = s->planes;
            prev_begin = s->z_begin;
            prev_end = s->z_end;
            return s;
          }) &
          tbb::make_filter<std::shared_ptr<Slab<T>>, std::shared_ptr<Slab<T>>>(
              tbb::filter_mode::parallel,
              [&](std::shared_ptr<Slab<T>> s) {
                const PlaneBlock<T> block{s->planes.get(), {nx, ny, s->z_end - s->z_begin},
                                          s->z_begin, nz};
                const std::size_t per_layer = l0.nodes[0] * l0.nodes[1];
                s->bricks.resize(per_layer);
                tbb::parallel_for(std::size_t{0}, per_layer, [&](std::size_t i) {
                  const NodeKey key{0,
                                    {static_cast<std::uint32_t>(i % l0.nodes[0]),
                                     static_cast<std::uint32_t>(i / l0.nodes[0]), s->layer}};
                  const IndexBox owned = layout.owned_fine_box(key);
                  s->bricks[i] = encode_brick(block, layout.level_box(key), &owned, {}, codec);
                });
                if (has_coarse) {
                  const IndexBox owned = layout.owned_fine_box(NodeKey{0, {0, 0, s->layer}});
                  const bool last = s->layer + 1 == l0.nodes[2];
                  const auto [c0, c1] =
                      coarse_planes_for(owned.lo[2], owned.hi[2], halved[2], last, coarse_dims[2]);
                  downsample_planes(block, halved, coarse, coarse_dims, c0, c1);
                }
                return s;
              }) &
          tbb::make_filter<std::shared_ptr<Slab<T>>, void>(
              tbb::filter_mode::serial_in_order, [&](std::shared_ptr<Slab<T>> s) {
                const std::size_t per_layer = l0.nodes[0] * l0.nodes[1];
                for (std::size_t i = 0; i < per_layer; ++i) {
                  const NodeId id = static_cast<NodeId>(l0.first_node + s->layer * per_layer + i);
                  const format::IndexEntry& e = s->bricks[i].entry;
                  stats[id - l0.first_node] = NodeStats{e.min, e.max, e.valid_count};
                  count_kind(ctx.counts, e);
                  ctx.counts.chunk_bytes += s->bricks[i].chunk.size();
                  ctx.writer.add_brick(v, id, std::move(s->bricks[i]));
                }
              }));

  // Coarser levels: dense grids, statistics merged from the children.
  for (std::size_t l = 1; l < layout.level_count(); ++l) {
    const LevelShape& shape = layout.level(l);
    const LevelShape& below = layout.level(l - 1);
    std::vector<NodeStats> level_stats(shape.node_count());
    for (std::size_t i = 0; i < shape.node_count(); ++i) {
      for (NodeId child : layout.children(static_cast<NodeId>(shape.first_node + i))) {
        level_stats[i].merge(stats[child - below.first_node]);
      }
    }
    const PlaneBlock<T> block{coarse.data(), coarse_dims, 0, coarse_dims[2]};
    std::vector<EncodedBrick> bricks(shape.node_count());
    tbb::parallel_for(std::size_t{0}, shape.node_count(), [&](std::size_t i) {
      const NodeKey key = layout.key(static_cast<NodeId>(shape.first_node + i));
      bricks[i] = encode_brick(block, layout.level_box(key), nullptr, level_stats[i], codec);
    });
    for (std::size_t i = 0; i < bricks.size(); ++i) {
      count_kind(ctx.counts, bricks[i].entry);
      ctx.counts.chunk_bytes += bricks[i].chunk.size();
      ctx.writer.add_brick(v, static_cast<NodeId>(shape.first_node + i), std::move(bricks[i]));
    }
    if (l + 1 < layout.level_count()) {
      const auto next_dims = layout.level(l + 1).samples;
      std::vector<T> next(next_dims[0] * next_dims[1] * next_dims[2]);
      downsample_planes(block, halved_between(layout, l), next, next_dims, 0, next_dims[2]);
      coarse = std::move(next);
      coarse_dims = next_dims;
    }
    stats = std::move(level_stats);
  }
}

}  // namespace

std::size_t source_type_size(std::string_view type) {
  if (type == "byte" || type == "ubyte" || type == "char") return 1;
  if (type == "short" || type == "ushort") return 2;
  if (type == "int" || type == "uint" || type == "float") return 4;
  if (type == "double" || type == "int64" || type == "uint64") return 8;
  return 4;
}

StepCounts convert_step(const format::Manifest& manifest, const OctreeLayout& layout,
                        ingest::SlabReader& reader, std::uint32_t step,
                        const std::filesystem::path& out_path, const ProgressFn& progress) {
  StepCounts counts;
  format::StepHeader header;
  header.store_id = manifest.store_id;
  header.step = step;
  header.variable_count = static_cast<std::uint32_t>(manifest.variables.size());
  header.node_count = static_cast<std::uint32_t>(layout.node_count());
  StepWriter writer(out_path, header);
  PlaneBufferPool buffers;
  Context ctx{buffers, manifest, layout, reader, step, writer, counts, progress};
  for (std::uint32_t v = 0; v < header.variable_count; ++v) {
    if (manifest.variables[v].dtype == DType::kFloat32) {
      convert_variable<float>(ctx, v);
    } else {
      convert_variable<double>(ctx, v);
    }
  }
  writer.commit();
  counts.file_bytes = std::filesystem::file_size(out_path);
  return counts;
}

}  // namespace strielad::build
