// SPDX-License-Identifier: Apache-2.0
#include "bench/brick_read_bench.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>

#include "bench/netcdf_region_reader.h"
#include "bench/page_cache.h"
#include "bench/proc_io.h"
#include "bench/stopwatch.h"
#include "core/direct_read_file.h"
#include "core/error.h"
#include "store/store.h"
#include "peers/delayed_region_reader.h"

namespace strielad::bench {
namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// Bytes a read is seen to fetch from disk, by the chosen method.
class DiskMeter {
 public:
  DiskMeter(DiskByteMethod method, std::filesystem::path file)
      : method_(method), file_(std::move(file)) {}
  void start() {
    if (method_ == DiskByteMethod::kProcSelfIo) before_ = read_proc_io().value_or(ProcIo{}).read_bytes;
    else before_ = page_cache_residency(file_).resident_bytes;
  }
  double stop() const {
    const std::uint64_t after = method_ == DiskByteMethod::kProcSelfIo
                                    ? read_proc_io().value_or(ProcIo{}).read_bytes
                                    : page_cache_residency(file_).resident_bytes;
    return after >= before_ ? static_cast<double>(after - before_) : 0.0;
  }

 private:
  DiskByteMethod method_;
  std::filesystem::path file_;
  std::uint64_t before_ = 0;
};

double page_span(std::uint64_t offset, std::uint64_t size, std::uint64_t page) {
  if (size == 0) return 0;
  const std::uint64_t first = offset / page, last = (offset + size - 1) / page;
  return static_cast<double>((last - first + 1) * page);
}

// One pass of reads; `before_each` runs untimed before every read.
ReadSet store_pass(const Store& store, const std::vector<ReadSample>& samples, std::string name,
                   std::string description, const std::function<void()>& before_each,
                   DiskMeter& meter) {
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  ReadSet set{std::move(name), std::move(description), {}, {}, {}, {}};
  for (const auto& s : samples) {
    const auto& e = store.node_entry(0, s.variable, s.node);
    if (before_each) before_each();
    meter.start();
    const Stopwatch clock;
    const Brick b = store.read_brick(0, s.variable, s.node);
    const double us = clock.microseconds();
    set.disk_bytes.push_back(meter.stop());
    set.latency_us.push_back(us);
    set.payload_bytes.push_back(e.chunk_size);
    set.page_bytes.push_back(page_span(e.chunk_offset, e.chunk_size, page));
    if (b.bytes.empty()) throw make_error(ErrorCode::kInternal, "bench: read an empty data brick");
  }
  return set;
}

IndexBox aligned_box(const OctreeLayout& layout, NodeId node) {
  IndexBox box = layout.fine_box(layout.key(node));
  const Dims3 g = layout.grid();
  const std::size_t n[3] = {g.x, g.y, g.z};
  for (int a = 0; a < 3; ++a) box.hi[a] = std::min(box.lo[a] + layout.brick() - 1, n[a] - 1);
  return box;
}

// Reads each sample's box (the brick's (B+1)^3 samples, or its chunk-aligned B^3 ones)
// through `read`, timed and metered, `before_each` (evictions) untimed.
using RegionRead = std::function<void(std::uint32_t variable, const IndexBox&, std::vector<float>&)>;
ReadSet region_pass(const OctreeLayout& layout, const std::vector<ReadSample>& samples,
                    bool brick_box, std::string name, std::string description,
                    const std::function<void()>& before_each, DiskMeter& meter,
                    const RegionRead& read) {
  ReadSet set{std::move(name), std::move(description), {}, {}, {}, {}};
  std::vector<float> out;
  for (const auto& s : samples) {
    const IndexBox box = brick_box ? layout.fine_box(layout.key(s.node)) : aligned_box(layout, s.node);
    if (before_each) before_each();
    meter.start();
    const Stopwatch clock;
    read(s.variable, box, out);
    const double us = clock.microseconds();
    set.disk_bytes.push_back(meter.stop());
    set.latency_us.push_back(us);
    set.payload_bytes.push_back(0);
    set.page_bytes.push_back(0);
  }
  return set;
}

ReadSet netcdf_pass(NetcdfRegionReader& nc, const OctreeLayout& layout,
                    const std::vector<ReadSample>& samples, bool brick_box, std::string name,
                    std::string description, const std::function<void()>& before_each,
                    DiskMeter& meter) {
  return region_pass(layout, samples, brick_box, std::move(name), std::move(description),
                     before_each, meter,
                     [&](std::uint32_t v, const IndexBox& box, std::vector<float>& out) {
                       nc.read_box(v, 0, box, out);
                     });
}

// The same (B+1)^3 samples as each brick through OpenVDB delayed loading, the .vdb files
// evicted before each read; the grids' topology is read at open, before timing.
ReadSet vdb_pass(const BrickReadOptions& o, const Store& store,
                 const std::vector<ReadSample>& samples, DiskByteMethod method) {
  std::vector<std::string> grids;
  for (const auto& v : store.manifest().variables) grids.push_back(v.name);
  peers::DelayedRegionReader reader(o.vdb_files, grids);
  std::vector<EvictableFile> files;
  for (const auto& f : o.vdb_files) files.emplace_back(f);
  DiskMeter meter(method, o.vdb_files.front());
  const auto& layout = store.octree();
  return region_pass(
      layout, samples, true, "openvdb delayed, (B+1)^3 box",
      fmt::format("FloatGrid of level 0 per variable (vdb::write_level_vdb, Blosc), "
                  "io::File::open(delayLoad) with copy-max-bytes 0, topology read at open; "
                  "the brick's {}^3 samples through a ValueAccessor, which loads the 8^3 "
                  "leaves it touches; files evicted before each read",
                  layout.brick() + 1),
      [&] {
        for (const auto& f : files) f.evict();
      },
      meter,
      [&](std::uint32_t v, const IndexBox& box, std::vector<float>& out) {
        reader.read_box(v, box, out);
      });
}

// A fresh reader each time: MANIFEST, step header/footer/section table, one index
// section and one brick, all cold.
ReadSet first_brick_set(const BrickReadOptions& o, const std::vector<ReadSample>& level0,
                        const std::function<void()>& evict) {
  ReadSet first{"store cold first brick",
                "Store::open + step open + index section of the variable + one brick, all files "
                "evicted", {}, {}, {}, {}};
  const auto manifest = o.store / "MANIFEST";
  const std::size_t n = std::min(o.first_brick_reads, level0.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto& s = level0[i];
    evict();
    evict_file(manifest);
    const auto before = read_proc_io();
    const Stopwatch clock;
    const auto fresh = Store::open(o.store);
    const Brick b = fresh->read_brick(0, s.variable, s.node);
    first.latency_us.push_back(clock.microseconds());
    const auto after = read_proc_io();
    first.disk_bytes.push_back(before && after ? static_cast<double>(after->read_bytes - before->read_bytes) : 0);
    first.payload_bytes.push_back(0);
    first.page_bytes.push_back(0);
    (void)b;
  }
  return first;
}

// The same bricks' samples read from the NetCDF input (o.netcdf), cold and warm.
void netcdf_sets(const BrickReadOptions& o, const OctreeLayout& layout,
                 const std::vector<ReadSample>& level0, BrickReadBench& bench) {
  NetcdfRegionReader nc(o.netcdf, o.variables, /*chunk_cache_bytes=*/0);
  EvictableFile nc_file(o.netcdf);
  const auto nc_evict = [&] { nc_file.evict(); };
  DiskMeter nc_meter(bench.method, o.netcdf);
  const auto chunks = nc.chunking(0);
  const std::string chunk_text =
      chunks.size() == 3 ? fmt::format("{}x{}x{} (z,y,x) chunks", chunks[0], chunks[1], chunks[2])
                         : "contiguous";
  // Warm-up: loads HDF5's chunk B-tree into its metadata cache (as the store index is).
  netcdf_pass(nc, layout, level0, true, "warm-up", "", {}, nc_meter);
  const std::string aligned = fmt::format(
      "nc_get_vara_float of the brick's first {}^3 samples (chunk-aligned: one chunk), {}, "
      "deflate 1 + shuffle, chunk cache 0", layout.brick(), chunk_text);
  const std::string whole = fmt::format(
      "nc_get_vara_float of the brick's {}^3 samples (the same samples as the brick: up to 8 "
      "chunks), {}, chunk cache 0", layout.brick() + 1, chunk_text);
  bench.sets.push_back(netcdf_pass(nc, layout, level0, false, "netcdf cold, B^3 box",
                                   aligned + ", file evicted before each read", nc_evict, nc_meter));
  bench.sets.push_back(netcdf_pass(nc, layout, level0, true, "netcdf cold, (B+1)^3 box",
                                   whole + ", file evicted before each read", nc_evict, nc_meter));
  netcdf_pass(nc, layout, level0, false, "warm-up", "", {}, nc_meter);
  bench.sets.push_back(netcdf_pass(nc, layout, level0, false, "netcdf warm, B^3 box",
                                   aligned + ", after a warm-up pass", {}, nc_meter));
}

}  // namespace

const char* disk_byte_method_name(DiskByteMethod m) {
  return m == DiskByteMethod::kProcSelfIo ? "/proc/self/io read_bytes"
                                          : "mincore residency of the file after the read";
}

double ReadSet::mean_disk_bytes() const {
  return disk_bytes.empty() ? 0 : sum(disk_bytes) / static_cast<double>(disk_bytes.size());
}
double ReadSet::mean_payload_bytes() const {
  return payload_bytes.empty() ? 0 : sum(payload_bytes) / static_cast<double>(payload_bytes.size());
}
double ReadSet::amplification() const {
  const double p = sum(payload_bytes);
  return p > 0 ? sum(disk_bytes) / p : std::numeric_limits<double>::quiet_NaN();
}
double ReadSet::amplification_p50() const {
  std::vector<double> r;
  for (std::size_t i = 0; i < disk_bytes.size(); ++i) {
    if (payload_bytes[i] > 0) r.push_back(disk_bytes[i] / payload_bytes[i]);
  }
  return r.empty() ? std::numeric_limits<double>::quiet_NaN() : median(r);
}
double ReadSet::page_amplification() const {
  const double p = sum(payload_bytes);
  return p > 0 ? sum(page_bytes) / p : std::numeric_limits<double>::quiet_NaN();
}

const ReadSet* BrickReadBench::find(const std::string& name) const {
  for (const auto& s : sets) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

std::vector<ReadSample> pick_data_nodes(const Store& store, LevelFilter filter, std::size_t count,
                                        std::uint64_t seed) {
  const NodeId level0_end =
      static_cast<NodeId>(store.octree().level(0).first_node + store.octree().level(0).node_count());
  std::vector<ReadSample> all;
  for (std::uint32_t v = 0; v < store.variable_count(); ++v) {
    const auto entries = store.index(0, v);
    for (NodeId n = 0; n < entries.size(); ++n) {
      if (entries[n].kind != format::BrickKind::kData) continue;
      const bool fine = n < level0_end;
      if ((filter == LevelFilter::kLevel0 && !fine) || (filter == LevelFilter::kCoarse && fine)) continue;
      if (filter == LevelFilter::kFpzip && entries[n].coding != format::ChunkCoding::kFpzip) continue;
      all.push_back({v, n});
    }
  }
  std::mt19937_64 rng(seed);
  std::vector<ReadSample> out;
  if (all.empty() || count == 0) return out;
  if (all.size() >= count) {
    std::shuffle(all.begin(), all.end(), rng);
    all.resize(count);
    return all;
  }
  std::uniform_int_distribution<std::size_t> pick(0, all.size() - 1);
  for (std::size_t i = 0; i < count; ++i) out.push_back(all[pick(rng)]);
  return out;
}

BrickReadBench run_brick_read_bench(const BrickReadOptions& o) {
  BrickReadBench bench;
  bench.method = proc_io_counts_disk_reads(o.scratch.c_str()) ? DiskByteMethod::kProcSelfIo
                                                               : DiskByteMethod::kMincore;
  const auto store = Store::open(o.store);
  const auto step_file = store->step_path(0);
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) store->index(0, v);

  EvictableFile evictable(step_file);
  const auto evict = [&] { evictable.evict(); };
  ::sync();
  evict();
  bench.resident_after_evict = page_cache_residency(step_file).fraction();
  DiskMeter store_meter(bench.method, step_file);

  const auto level0 = pick_data_nodes(*store, LevelFilter::kLevel0, o.reads, o.seed);
  if (level0.empty()) {
    throw make_error(ErrorCode::kInvalidInput, "{}: no data bricks at level 0 to read",
                     o.store.string());
  }
  const std::string one_read = "Store::read_brick: pread of the chunk + XXH3 + Blosc decompress";
  bench.sets.push_back(store_pass(*store, level0, "store cold, level 0",
                                  one_read + ", step file evicted before each read", evict,
                                  store_meter));
  if (o.coarse_set) {
    const auto coarse = pick_data_nodes(*store, LevelFilter::kCoarse, o.reads, o.seed + 1);
    if (!coarse.empty()) {
      bench.sets.push_back(store_pass(*store, coarse, "store cold, levels >= 1",
                                      one_read + ", step file evicted before each read", evict,
                                      store_meter));
    }
  }
  // A store converted with --fpzip: its fpzip chunks alone, whose decoding costs most.
  if (const auto fpzip = pick_data_nodes(*store, LevelFilter::kFpzip, o.reads, o.seed + 2);
      !fpzip.empty()) {
    bench.sets.push_back(store_pass(*store, fpzip, "store cold, fpzip chunks",
                                    "Store::read_brick of fpzip-coded bricks (any level): pread "
                                    "of the chunk + XXH3 + fpzip decode + XXH3 of the samples, "
                                    "step file evicted before each read",
                                    evict, store_meter));
  }
  // The same bricks with direct reads (StoreOpenOptions::direct_reads): whole device
  // blocks instead of whole pages, and no page cache to evict.
  if (DirectReadFile::open(step_file)) {
    const auto direct = Store::open(o.store, StoreOpenOptions{.direct_reads = true});
    for (std::uint32_t v = 0; v < direct->variable_count(); ++v) direct->index(0, v);
    bench.sets.push_back(store_pass(*direct, level0, "store direct, level 0",
                                    "Store::read_brick with direct_reads: O_DIRECT pread of the "
                                    "512-byte blocks the chunk spans + XXH3 + Blosc decompress, "
                                    "no page cache",
                                    evict, store_meter));
  }
  store_pass(*store, level0, "warm-up", "", {}, store_meter);
  bench.sets.push_back(store_pass(*store, level0, "store warm, level 0",
                                  one_read + ", after a warm-up pass over the same bricks", {},
                                  store_meter));

  if (o.first_brick_reads > 0) bench.sets.push_back(first_brick_set(o, level0, evict));
  if (!o.netcdf.empty()) netcdf_sets(o, store->octree(), level0, bench);
  if (!o.vdb_files.empty()) bench.sets.push_back(vdb_pass(o, *store, level0, bench.method));
  return bench;
}

}  // namespace strielad::bench
