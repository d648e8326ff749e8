// SPDX-License-Identifier: Apache-2.0
#include "convert/conversion_limits.h"

#include <blosc.h>
#include <tbb/info.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"

namespace strielad::build {
namespace {

// Samples of the largest brick of a level-0 layout with brick size `brick`.
double largest_brick_samples(const Dims3& grid, double brick) {
  return std::min(brick + 1, double(grid.x)) * std::min(brick + 1, double(grid.y)) *
         std::min(brick + 1, double(grid.z));
}

std::string gigabytes(double bytes) {
  return bytes >= 1e8 ? fmt::format("{:.1f} GB", bytes / 1e9)
                      : fmt::format("{:.1f} MB", bytes / 1e6);
}

}  // namespace

std::uint64_t max_chunk_bytes() { return BLOSC_MAX_BUFFERSIZE; }

void check_brick_fits_chunk(const OctreeLayout& layout, DType dtype, std::string_view variable) {
  const Dims3 grid = layout.grid();
  const double size = double(dtype_size(dtype));
  const double limit = double(max_chunk_bytes());
  const double bytes = largest_brick_samples(grid, layout.brick()) * size;
  if (bytes <= limit) return;
  std::uint32_t fits = 2;
  while (fits < layout.brick() && largest_brick_samples(grid, fits + 1) * size <= limit) ++fits;
  const auto edge = [&](std::size_t n) { return std::min<std::size_t>(layout.brick() + 1, n); };
  throw make_error(ErrorCode::kInvalidArgument,
                   "brick {}: the largest brick of variable '{}' holds {}x{}x{} {} samples ({}), "
                   "more than a Blosc chunk can hold ({} bytes); use --brick {} or smaller",
                   layout.brick(), variable, edge(grid.x), edge(grid.y), edge(grid.z),
                   dtype_name(dtype), gigabytes(bytes), max_chunk_bytes(), fits);
}

ConversionMemory estimate_conversion_memory(const OctreeLayout& layout, DType dtype,
                                            std::size_t source_bytes, int threads) {
  const Dims3 g = layout.grid();
  const double size = double(dtype_size(dtype));
  const int workers = threads > 0 ? threads : std::max(1, tbb::info::default_concurrency());
  ConversionMemory m;
  m.slabs = std::max(2, workers);
  const double planes = std::min(double(g.z), double(layout.brick()) + 3);
  const double slab_samples = double(g.x) * double(g.y) * planes;
  m.slab_bytes = slab_samples * size;
  const auto level_bytes = [&](std::size_t l) {
    if (l >= layout.level_count()) return 0.0;
    const auto& s = layout.level(l).samples;
    return double(s[0]) * double(s[1]) * double(s[2]) * size;
  };
  if (layout.level_count() > 1) m.coarse_bytes = 2 * level_bytes(1) + level_bytes(2);
  const double brick = largest_brick_samples(g, layout.brick()) * size;
  // Slabs in flight and their encoded bricks, the slab kept for the next one's overlap,
  // one raw read buffer, the coarse levels, per-thread brick scratch (samples, residual,
  // chunk).
  m.total_bytes = (2.0 * m.slabs + 1) * m.slab_bytes + slab_samples * double(source_bytes) +
                  m.coarse_bytes + 3.0 * workers * brick;
  return m;
}

std::uint64_t available_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  std::uint64_t bytes = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : 0;
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");  // cgroup v2; "max" when unlimited
  std::uint64_t limit = 0;
  if (cgroup >> limit && limit > 0) bytes = bytes ? std::min(bytes, limit) : limit;
  return bytes;
}

void check_conversion_memory(const OctreeLayout& layout, DType dtype, std::size_t source_bytes,
                             int threads, std::uint64_t limit_bytes, std::string_view variable) {
  const std::uint64_t limit = limit_bytes ? limit_bytes : available_memory_bytes();
  if (limit == 0) return;
  const ConversionMemory m = estimate_conversion_memory(layout, dtype, source_bytes, threads);
  if (m.total_bytes <= double(limit)) return;
  const Dims3 g = layout.grid();
  throw make_error(
      ErrorCode::kUnsupported,
      "grid {}x{}x{}: variable '{}' ({}) needs about {} of memory to convert ({} slabs in "
      "flight of {} each: {} plane{} of {}x{} samples; coarse levels {}), more than the {} "
      "{}; convert with fewer --threads (at least 2 slabs stay in flight), raise "
      "--memory-limit (the estimate assumes data that does not compress), or split the "
      "input into lon/lat tiles (e.g. ncks -d lon,0,{})",
      g.x, g.y, g.z, variable, dtype_name(dtype), gigabytes(m.total_bytes), m.slabs,
      gigabytes(m.slab_bytes), std::min<std::size_t>(g.z, layout.brick() + 3),
      std::min<std::size_t>(g.z, layout.brick() + 3) == 1 ? "" : "s", g.x, g.y,
      gigabytes(m.coarse_bytes), gigabytes(double(limit)),
      limit_bytes ? "allowed" : "this machine has", g.x / 2);
}

}  // namespace strielad::build
