// SPDX-License-Identifier: Apache-2.0
#include "convert/step_converter.h"

#include <sys/mman.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <new>
#include <vector>

#include "convert/brick_encoder.h"
#include "convert/level_sampler.h"
#include "convert/step_writer.h"
#include "convert/geometry_field_reader.h"
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

void count_kind(StepCounts& c, const EncodedBrick& b) {
  const format::IndexEntry& e = b.entry;
  c.lossy += e.coding == format::ChunkCoding::kZfp ? 1 : 0;
  c.lossy_fallback += b.lossy_fallback ? 1 : 0;
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

// Reads level-0 planes [z0, z1) of one field of the step into `out`.
template <typename T>
using PlaneReader = std::function<void(std::size_t z0, std::size_t z1, std::span<T> out)>;

// One field of a step file: a variable, or the grid geometry's vertical field.
template <typename T>
struct SectionSource {
  std::uint32_t section = 0;          // its section in the step file
  const format::CodecSpec* codec = nullptr;
  std::size_t source_bytes_per_sample = 4;
  PlaneReader<T> read;
};

// A variable's section: read from the inputs by the SlabReader.
template <typename T>
SectionSource<T> variable_source(Context& ctx, std::uint32_t v) {
  return {v, &ctx.manifest.codec_of(v), source_type_size(ctx.manifest.variables[v].source_type),
          [&ctx, v](std::size_t z0, std::size_t z1, std::span<T> out) {
            ctx.reader.read(v, ctx.step, z0, z1, out);
          }};
}

// One field of one step: level 0 read slab by slab and encoded while the next level
// is downsampled from it; the coarser levels then encoded from dense grids.
template <typename T>
class VariableConversion {
 public:
  VariableConversion(Context& ctx, SectionSource<T> source)
      : ctx_(ctx),
        v_(source.section),
        layout_(ctx.layout),
        l0_(layout_.level(0)),
        nx_(l0_.samples[0]),
        ny_(l0_.samples[1]),
        nz_(l0_.samples[2]),
        plane_(nx_ * ny_),
        brick_(layout_.brick()),
        codec_(*source.codec),
        has_coarse_(layout_.level_count() > 1),
        src_size_(source.source_bytes_per_sample),
        read_(std::move(source.read)),
        stats_(l0_.node_count()) {
    if (has_coarse_) {
      coarse_dims_ = layout_.level(1).samples;
      coarse_.resize(coarse_dims_[0] * coarse_dims_[1] * coarse_dims_[2]);
      halved_ = halved_between(layout_, 0);
    }
  }

  void run() {
    convert_finest_level();
    // Coarser levels: dense grids, statistics merged from the children.
    for (std::size_t l = 1; l < layout_.level_count(); ++l) convert_coarse_level(l);
  }

 private:
  // Level 0: read slabs in order (netCDF is serial), encode in parallel, append in order.
  void convert_finest_level() {
    const std::size_t tokens = std::max(2, tbb::this_task_arena::max_concurrency());
    tbb::parallel_pipeline(
        tokens,
        tbb::make_filter<void, std::shared_ptr<Slab<T>>>(
            tbb::filter_mode::serial_in_order,
            [&](tbb::flow_control& fc) -> std::shared_ptr<Slab<T>> {
              if (next_layer_ == l0_.nodes[2]) {
                fc.stop();
                return nullptr;
              }
              return read_slab(next_layer_++);
            }) &
            tbb::make_filter<std::shared_ptr<Slab<T>>, std::shared_ptr<Slab<T>>>(
                tbb::filter_mode::parallel,
                [&](std::shared_ptr<Slab<T>> s) {
                  encode_slab(*s);
                  return s;
                }) &
            tbb::make_filter<std::shared_ptr<Slab<T>>, void>(
                tbb::filter_mode::serial_in_order,
                [&](std::shared_ptr<Slab<T>> s) { append_slab(*s); }));
  }

  // The planes of one layer of level-0 bricks, with one plane either side: those the
  // previous slab already holds are copied, the rest read.
  std::shared_ptr<Slab<T>> read_slab(std::uint32_t layer) {
    auto s = std::make_shared<Slab<T>>();
    s->layer = layer;
    const std::size_t z_lo = std::size_t{s->layer} * brick_;
    const std::size_t z_hi = std::min(z_lo + brick_, nz_ - 1);
    s->z_begin = z_lo > 0 ? z_lo - 1 : 0;
    s->z_end = std::min(nz_ - 1, z_hi + 1) + 1;
    // Every slab asks for the largest size (B + 3 planes), so a buffer fits any layer.
    s->planes = ctx_.buffers.acquire<T>(std::min(brick_ + 3, nz_) * plane_);
    std::size_t read_from = s->z_begin;
    if (previous_ && prev_begin_ <= s->z_begin && prev_end_ > s->z_begin) {
      const std::size_t keep = std::min(prev_end_, s->z_end) - s->z_begin;
      std::memcpy(s->planes.get(), previous_.get() + (s->z_begin - prev_begin_) * plane_,
                  keep * plane_ * sizeof(T));
      read_from = s->z_begin + keep;
    }
    if (read_from < s->z_end) {
      std::span<T> out(s->planes.get() + (read_from - s->z_begin) * plane_,
                       (s->z_end - read_from) * plane_);
      read_(read_from, s->z_end, out);
      const std::uint64_t bytes = out.size() * src_size_;
      ctx_.counts.input_bytes += bytes;
      if (ctx_.progress) ctx_.progress(bytes);
    }
    previous_ = s->planes;
    prev_begin_ = s->z_begin;
    prev_end_ = s->z_end;
    return s;
  }

  // The slab's bricks encoded in parallel, and its share of level 1 downsampled.
  void encode_slab(Slab<T>& s) {
    const PlaneBlock<T> block{s.planes.get(), {nx_, ny_, s.z_end - s.z_begin}, s.z_begin, nz_};
    const std::size_t per_layer = l0_.nodes[0] * l0_.nodes[1];
    s.bricks.resize(per_layer);
    tbb::parallel_for(std::size_t{0}, per_layer, [&](std::size_t i) {
      const NodeKey key{0,
                        {static_cast<std::uint32_t>(i % l0_.nodes[0]),
                         static_cast<std::uint32_t>(i / l0_.nodes[0]), s.layer}};
      const IndexBox owned = layout_.owned_fine_box(key);
      s.bricks[i] = encode_brick(block, layout_.level_box(key), &owned, {}, codec_);
    });
    if (has_coarse_) {
      const IndexBox owned = layout_.owned_fine_box(NodeKey{0, {0, 0, s.layer}});
      const bool last = s.layer + 1 == l0_.nodes[2];
      const auto [c0, c1] =
          coarse_planes_for(owned.lo[2], owned.hi[2], halved_[2], last, coarse_dims_[2]);
      downsample_planes(block, halved_, coarse_, coarse_dims_, c0, c1);
    }
  }

  // The slab's bricks appended to the step, in node order.
  void append_slab(Slab<T>& s) {
    const std::size_t per_layer = l0_.nodes[0] * l0_.nodes[1];
    for (std::size_t i = 0; i < per_layer; ++i) {
      const NodeId id = static_cast<NodeId>(l0_.first_node + s.layer * per_layer + i);
      const format::IndexEntry& e = s.bricks[i].entry;
      stats_[id - l0_.first_node] = NodeStats{e.min, e.max, e.valid_count};
      count_kind(ctx_.counts, s.bricks[i]);
      ctx_.counts.chunk_bytes += s.bricks[i].chunk.size();
      ctx_.writer.add_brick(v_, id, std::move(s.bricks[i]));
    }
  }

  // Level l encoded from the dense grid `coarse_`, which is then downsampled to level l + 1.
  void convert_coarse_level(std::size_t l) {
    const LevelShape& shape = layout_.level(l);
    const LevelShape& below = layout_.level(l - 1);
    std::vector<NodeStats> level_stats(shape.node_count());
    for (std::size_t i = 0; i < shape.node_count(); ++i) {
      for (NodeId child : layout_.children(static_cast<NodeId>(shape.first_node + i))) {
        level_stats[i].merge(stats_[child - below.first_node]);
      }
    }
    const PlaneBlock<T> block{coarse_.data(), coarse_dims_, 0, coarse_dims_[2]};
    std::vector<EncodedBrick> bricks(shape.node_count());
    tbb::parallel_for(std::size_t{0}, shape.node_count(), [&](std::size_t i) {
      const NodeKey key = layout_.key(static_cast<NodeId>(shape.first_node + i));
      bricks[i] = encode_brick(block, layout_.level_box(key), nullptr, level_stats[i], codec_);
    });
    for (std::size_t i = 0; i < bricks.size(); ++i) {
      count_kind(ctx_.counts, bricks[i]);
      ctx_.counts.chunk_bytes += bricks[i].chunk.size();
      ctx_.writer.add_brick(v_, static_cast<NodeId>(shape.first_node + i), std::move(bricks[i]));
    }
    if (l + 1 < layout_.level_count()) {
      const auto next_dims = layout_.level(l + 1).samples;
      std::vector<T> next(next_dims[0] * next_dims[1] * next_dims[2]);
      downsample_planes(block, halved_between(layout_, l), next, next_dims, 0, next_dims[2]);
      coarse_ = std::move(next);
      coarse_dims_ = next_dims;
    }
    stats_ = std::move(level_stats);
  }

  Context& ctx_;
  const std::uint32_t v_;
  const OctreeLayout& layout_;
  const LevelShape& l0_;
  const std::size_t nx_, ny_, nz_, plane_;
  const std::size_t brick_;
  const format::CodecSpec& codec_;
  const bool has_coarse_;
  const std::size_t src_size_;
  const PlaneReader<T> read_;

  std::vector<T> coarse_;  // the level below the one being encoded, dense
  std::array<std::size_t, 3> coarse_dims_{};
  std::array<bool, 3> halved_{};
  std::vector<NodeStats> stats_;  // of the level just encoded

  std::uint32_t next_layer_ = 0;
  std::shared_ptr<T[]> previous_;  // the last slab's planes [prev_begin_, prev_end_)
  std::size_t prev_begin_ = 0, prev_end_ = 0;
};

// The geometry field of `step` (time step 0 for a time-invariant one) as `section`, in
// its stored dtype, its columns checked level by level.
void convert_geometry_section(Context& ctx, std::uint32_t step, std::uint32_t section) {
  const format::VerticalGeometry& vertical = ctx.manifest.geometry->vertical;
  auto field = std::make_shared<GeometryFieldReader>(ctx.reader, ctx.manifest, step);
  if (vertical.dtype == DType::kFloat32) {
    VariableConversion<float>(ctx, {section, &vertical.codec, sizeof(double),
                                    [field](std::size_t z0, std::size_t z1, std::span<float> out) {
                                      field->read(z0, z1, out);
                                    }})
        .run();
  } else {
    VariableConversion<double>(ctx, {section, &vertical.codec, sizeof(double),
                                     [field](std::size_t z0, std::size_t z1, std::span<double> out) {
                                       field->read(z0, z1, out);
                                     }})
        .run();
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
  const bool geometry_section = has_time_varying_geometry(manifest);
  if (geometry_section) ++header.variable_count;  // section V: the geometry field
  StepWriter writer(out_path, header);
  PlaneBufferPool buffers;
  Context ctx{buffers, manifest, layout, reader, step, writer, counts, progress};
  for (std::uint32_t v = 0; v < manifest.variables.size(); ++v) {
    if (manifest.variables[v].dtype == DType::kFloat32) {
      VariableConversion<float>(ctx, variable_source<float>(ctx, v)).run();
    } else {
      VariableConversion<double>(ctx, variable_source<double>(ctx, v)).run();
    }
  }
  if (geometry_section) convert_geometry_section(ctx, step, header.variable_count - 1);
  writer.commit();
  counts.file_bytes = std::filesystem::file_size(out_path);
  return counts;
}

StepCounts convert_geometry_bricks(const format::Manifest& manifest, const OctreeLayout& layout,
                                   ingest::SlabReader& reader,
                                   const std::filesystem::path& out_path) {
  StepCounts counts;
  format::StepHeader header;
  header.store_id = manifest.store_id;
  header.step = format::kGeometryStep;
  header.variable_count = 1;
  header.node_count = static_cast<std::uint32_t>(layout.node_count());
  StepWriter writer(out_path, header);
  PlaneBufferPool buffers;
  const ProgressFn no_progress;
  Context ctx{buffers, manifest, layout, reader, 0, writer, counts, no_progress};
  convert_geometry_section(ctx, 0, 0);
  writer.commit();
  counts.file_bytes = std::filesystem::file_size(out_path);
  return counts;
}

}  // namespace strielad::build
