// SPDX-License-Identifier: Apache-2.0
// SlabReader: one nc_get_vara per slab under netcdf_mutex(), conversion outside it; or,
// for raw netCDF-4 planes, the planes' byte ranges looked up under the mutex and read
// with O_DIRECT outside it. Files stay open between calls (at most kMaxOpenFiles, least
// recently used closed).
#include <netcdf.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <system_error>

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "core/direct_read_file.h"
#include "core/error.h"
#include "ingest/hdf5_plane_layout.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "ingest/term_reader.h"
#include "ingest/vertical_columns.h"
#include "ingest/vertical_geometry.h"

#include "ingest/grib_catalog.h"
#include "ingest/grib_vertical_reader.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"
#include "ingest/sample_conversion.h"
#include "ingest/variable_meta.h"
#include "ingest/wrf_destagger.h"

namespace strielad::ingest {
namespace {

constexpr std::size_t kMaxOpenFiles = 64;

// Misaligned direct-read samples are copied into an aligned block of this many
// samples (of at most 8 bytes) before conversion.
constexpr std::size_t kAlignedBlockSamples = std::size_t{1} << 15;
constexpr std::size_t kCacheLine = 64;

std::byte* aligned_block() {
  struct Block {
    alignas(kCacheLine) std::byte bytes[kAlignedBlockSamples * 8];
  };
  static thread_local std::unique_ptr<Block> block = std::make_unique<Block>();
  return block->bytes;
}

struct VariableHandle {
  int grpid = -1;
  int varid = -1;
  bool has_time = false;
  std::size_t time_length = 0;
  CfValueAttributes attrs;
  std::shared_ptr<const Hdf5PlaneLayout> planes;  // null: read through netCDF
  StaggeredAxis stagger = StaggeredAxis::kNone;   // WRF's U, V, W: read destaggered
};

struct OpenFile {
  NcFile file;
  std::uint64_t last_use = 0;
  std::map<std::size_t, VariableHandle> variables;
  // The file opened with O_DIRECT, when it is netCDF-4 and its file system allows it.
  std::shared_ptr<const DirectReadFile> direct;
};

// A slab once netcdf_mutex() is released: its samples, raw, already read through
// netCDF, or the byte ranges to read with O_DIRECT.
struct SlabSource {
  CfValueAttributes attrs;
  std::byte* raw = nullptr;
  std::shared_ptr<const DirectReadFile> direct;
  std::optional<std::vector<FileRange>> ranges;
  StaggeredAxis stagger = StaggeredAxis::kNone;  // raw holds the staggered samples
};

}  // namespace

struct SlabReader::Impl {
  InputCatalog catalog;
  ScanOptions options;
  // Guarded by netcdf_mutex(), like the netCDF calls that use them.
  std::map<std::size_t, OpenFile> open;
  std::uint64_t clock = 0;
  std::atomic<std::uint64_t> direct_bytes{0};
  std::set<std::size_t> direct_failed{};  // files whose direct reads failed: netCDF only
  // Reads the sources of the vertical geometry and surface (created on first use).
  std::unique_ptr<NcTermReader> terms{};
  std::once_flag terms_once{};

  NcTermReader& term_reader() {
    std::call_once(terms_once, [this] { terms = std::make_unique<NcTermReader>(catalog); });
    return *terms;
  }

  OpenFile& open_file(std::size_t index);
  const VariableHandle& variable(OpenFile& of, std::size_t file, std::size_t v);

  template <typename Out>
  void read(std::size_t v, std::size_t t, std::size_t z0, std::size_t z1, std::span<Out> out);

  // The number of samples levels [z0, z1) of variable v at step t hold, checked against
  // the catalog and the output's size.
  std::size_t checked_slab_size(std::size_t v, std::size_t t, std::size_t z0, std::size_t z1,
                                std::size_t out_size) const;

  // Under netcdf_mutex(): the slab read through netCDF, or the byte ranges to read directly.
  template <typename Out>
  SlabSource fetch_slab(std::size_t v, const VariableLocation& loc, std::size_t z0,
                        std::size_t z1, std::span<Out> out, const std::string& context);

  void stop_direct_reads(std::size_t file, const Error& e);

  // The samples in `ranges` (raw, of attrs.type), read piece by piece with O_DIRECT and
  // converted into `out`.
  template <typename Out>
  ConversionResult read_direct(const DirectReadFile& file, const std::vector<FileRange>& ranges,
                               const CfValueAttributes& attrs, std::span<Out> out);
};

OpenFile& SlabReader::Impl::open_file(std::size_t index) {
  if (auto it = open.find(index); it != open.end()) {
    it->second.last_use = ++clock;
    return it->second;
  }
  if (open.size() >= kMaxOpenFiles) {
    auto oldest = open.begin();
    for (auto it = open.begin(); it != open.end(); ++it) {
      if (it->second.last_use < oldest->second.last_use) oldest = it;
    }
    open.erase(oldest);
  }
  const SourceFile& source = catalog.files[index];
  std::error_code ec;
  const auto size = std::filesystem::file_size(source.path, ec);
  if (ec) {
    throw make_error(ec == std::errc::no_such_file_or_directory ? ErrorCode::kNotFound
                                                                  : ErrorCode::kIo,
                     "{}: cannot read: {}", source.path, ec.message());
  }
  if (size != source.size) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: file changed since it was scanned (now {} bytes, was {})", source.path,
                     size, source.size);
  }
  OpenFile of;
  of.file = NcFile(source.path);
  of.last_use = ++clock;
  if (options.direct_input && !direct_failed.contains(index) &&
      of.file.format() == NC_FORMAT_NETCDF4) {
    of.direct = DirectReadFile::open(source.path);
    if (!of.direct) {
      spdlog::debug("{}: the file system refuses O_DIRECT; reading through netCDF", source.path);
    }
  }
  return open.emplace(index, std::move(of)).first->second;
}

const VariableHandle& SlabReader::Impl::variable(OpenFile& of, std::size_t file, std::size_t v) {
  if (auto it = of.variables.find(v); it != of.variables.end()) return it->second;
  const std::string& path = catalog.files[file].path;
  const VariableMeta& meta = catalog.variables[v];
  // A derived variable (WRF's theta) reads its source variable.
  const std::string& name = meta.source_variable.empty() ? meta.name : meta.source_variable;
  VariableHandle h;
  h.grpid = of.file.id();
  std::string short_name = name;
  if (const auto slash = name.rfind('/'); slash != std::string::npos) {
    std::string group = "/";  // not "/" + substr: GCC 12 -O3 warns falsely (PR 105651)
    group.append(name, 0, slash);
    short_name = name.substr(slash + 1);
    if (nc_inq_grp_full_ncid(of.file.id(), group.c_str(), &h.grpid) != NC_NOERR) {
      throw make_error(ErrorCode::kInvalidInput, "{}: group '{}' not found (file changed since "
                       "it was scanned?)", path, group);
    }
  }
  if (nc_inq_varid(h.grpid, short_name.c_str(), &h.varid) != NC_NOERR) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable '{}' not found (file changed since it was scanned?)", path,
                     name);
  }
  const auto dimids = variable_dimids(h.grpid, h.varid);
  const Dims3 dims = catalog.dims();
  bool ok = dimids.size() == 3 || dimids.size() == 4;
  if (ok) {
    h.has_time = dimids.size() == 4;
    const std::size_t s = dimids.size() - 3;
    const auto stagger = staggered_axis(
        {dimension_name(h.grpid, dimids[s]), dimension_name(h.grpid, dimids[s + 1]),
         dimension_name(h.grpid, dimids[s + 2])},
        {dimension_length(h.grpid, dimids[s]), dimension_length(h.grpid, dimids[s + 1]),
         dimension_length(h.grpid, dimids[s + 2])},
        dims);
    ok = stagger.has_value();
    if (ok) h.stagger = *stagger;
    if (h.has_time) h.time_length = dimension_length(h.grpid, dimids[0]);
  }
  if (!ok) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable '{}' no longer has the shape it had when scanned", path, name);
  }
  h.attrs = read_value_attributes(h.grpid, h.varid);
  add_value_offset(h.attrs, meta.value_offset);
  if (!is_numeric_type(h.attrs.type)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: variable '{}' has non-numeric type {}", path,
                     name, nc_type_name(h.attrs.type));
  }
  check_usable(h.attrs);  // before any read: scale_factor 0, an empty valid range...
  if (of.direct && h.stagger == StaggeredAxis::kNone) {
    std::string why_not;
    h.planes = Hdf5PlaneLayout::open(path, name, h.attrs.type, h.has_time, dims, &why_not);
    if (!h.planes) {
      spdlog::debug("{}: variable '{}' read through netCDF: {}", path, name, why_not);
    }
  }
  return of.variables.emplace(v, std::move(h)).first->second;
}

namespace {

template <typename Raw, typename Out>
ConversionResult convert_buffer(const std::byte* buffer, std::size_t count,
                                const CfValueAttributes& attrs, bool nan_as_fill,
                                std::span<Out> out) {
  const auto* data = reinterpret_cast<const Raw*>(buffer);
  return convert_samples<Raw, Out>(std::span<const Raw>(data, count), attrs, nan_as_fill, out);
}

template <typename Out>
ConversionResult convert_any(int type, const std::byte* buffer, std::size_t count,
                             const CfValueAttributes& attrs, bool nan_as_fill,
                             std::span<Out> out) {
  switch (type) {
    case NC_BYTE: return convert_buffer<signed char>(buffer, count, attrs, nan_as_fill, out);
    case NC_UBYTE: return convert_buffer<unsigned char>(buffer, count, attrs, nan_as_fill, out);
    case NC_SHORT: return convert_buffer<short>(buffer, count, attrs, nan_as_fill, out);
    case NC_USHORT: return convert_buffer<unsigned short>(buffer, count, attrs, nan_as_fill, out);
    case NC_INT: return convert_buffer<int>(buffer, count, attrs, nan_as_fill, out);
    case NC_UINT: return convert_buffer<unsigned int>(buffer, count, attrs, nan_as_fill, out);
    case NC_INT64: return convert_buffer<long long>(buffer, count, attrs, nan_as_fill, out);
    case NC_UINT64:
      return convert_buffer<unsigned long long>(buffer, count, attrs, nan_as_fill, out);
    case NC_FLOAT: return convert_buffer<float>(buffer, count, attrs, nan_as_fill, out);
    case NC_DOUBLE: return convert_buffer<double>(buffer, count, attrs, nan_as_fill, out);
    default:
      throw make_error(ErrorCode::kInternal, "unexpected netCDF type {}", type);
  }
}

}  // namespace

template <typename Out>
ConversionResult SlabReader::Impl::read_direct(const DirectReadFile& file,
                                              const std::vector<FileRange>& ranges,
                                              const CfValueAttributes& attrs, std::span<Out> out) {
  const std::size_t sample = nc_type_size(attrs.type);
  const std::size_t piece_samples = kDirectPieceBytes / sample;
  ConversionResult result;
  std::size_t done = 0;  // samples of `out` filled
  for (const FileRange& range : ranges) {
    const std::size_t samples = static_cast<std::size_t>(range.bytes / sample);
    for (std::size_t i = 0; i < samples; i += piece_samples) {
      const std::size_t n = std::min(piece_samples, samples - i);
      if (done + n > out.size()) {
        throw make_error(ErrorCode::kInternal, "{}: direct read ranges exceed the slab",
                         file.path().string());
      }
      const std::byte* bytes = file.read_view(range.offset + i * sample, n * sample).data();
      // HDF5 places data at any byte offset, so the samples may be misaligned for
      // their type: they are then converted from an aligned copy, block by block while
      // the block is in cache.
      const bool aligned = reinterpret_cast<std::uintptr_t>(bytes) % kCacheLine == 0;
      for (std::size_t j = 0; j < n; j += kAlignedBlockSamples) {
        const std::size_t m = std::min(kAlignedBlockSamples, n - j);
        const std::byte* raw = bytes + j * sample;
        if (!aligned) raw = static_cast<const std::byte*>(std::memcpy(aligned_block(), raw, m * sample));
        const ConversionResult r = convert_any<Out>(attrs.type, raw, m, attrs, options.nan_as_fill,
                                                    out.subspan(done, m));
        if (r.first_non_finite && !result.first_non_finite) {
          result.first_non_finite = done + *r.first_non_finite;
          result.non_finite_value = r.non_finite_value;
        }
        if (r.first_overflow && !result.first_overflow) {
          result.first_overflow = done + *r.first_overflow;
          result.overflow_raw = r.overflow_raw;
          result.overflow_value = r.overflow_value;
        }
        if (r.first_inexact && !result.first_inexact) {
          result.first_inexact = done + *r.first_inexact;
          result.inexact_raw = r.inexact_raw;
        }
        done += m;
      }
    }
  }
  if (done != out.size()) {
    throw make_error(ErrorCode::kInternal, "{}: direct read ranges cover {} of {} samples",
                     file.path().string(), done, out.size());
  }
  direct_bytes.fetch_add(done * sample, std::memory_order_relaxed);
  return result;
}

std::size_t SlabReader::Impl::checked_slab_size(std::size_t v, std::size_t t, std::size_t z0,
                                                std::size_t z1, std::size_t out_size) const {
  if (v >= catalog.variables.size()) {
    throw make_error(ErrorCode::kInvalidArgument, "variable index {} out of range ({} variables)",
                     v, catalog.variables.size());
  }
  if (t >= catalog.time.size()) {
    throw make_error(ErrorCode::kInvalidArgument, "time step {} out of range ({} steps)", t,
                     catalog.time.size());
  }
  const Dims3 dims = catalog.dims();
  if (z0 > z1 || z1 > dims.z) {
    throw make_error(ErrorCode::kInvalidArgument, "level range [{}, {}) outside [0, {})", z0, z1,
                     dims.z);
  }
  const std::size_t count = (z1 - z0) * dims.y * dims.x;
  if (out_size != count) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "output holds {} samples but levels [{}, {}) of {} x {} need {}", out_size,
                     z0, z1, dims.x, dims.y, count);
  }
  return count;
}

namespace {

// A per-thread buffer that is never zero-filled (netCDF fills it), so a slab costs no
// page faults beyond its first use.
std::byte* reusable_buffer(std::size_t bytes) {
  static thread_local std::unique_ptr<std::byte[]> buffer;
  static thread_local std::size_t buffer_size = 0;
  if (buffer_size < bytes) {
    buffer.reset(new std::byte[bytes]);
    buffer_size = bytes;
  }
  return buffer.get();
}

// Levels [z0, z0 + dims.z) of time index `time_in_file` of a variable, dims.y x dims.x
// samples each, read through netCDF into `raw`.
void get_slab(const VariableHandle& h, std::size_t time_in_file, std::size_t z0,
              const Dims3& dims, std::byte* raw, const std::string& context) {
  std::array<std::size_t, 4> start{}, edge{};
  std::size_t d = 0;
  if (h.has_time) {
    start[d] = time_in_file;
    edge[d++] = 1;
  }
  start[d] = z0;
  edge[d++] = dims.z;
  start[d] = 0;
  edge[d++] = dims.y;
  start[d] = 0;
  edge[d++] = dims.x;
  nc_check(nc_get_vara(h.grpid, h.varid, start.data(), edge.data(), raw), context);
}

// A conversion problem reported for the sample where it was found.
template <typename Out>
void check_converted(const ConversionResult& r, const CfValueAttributes& attrs, const Dims3& dims,
                     std::size_t z0, const std::string& context) {
  const std::size_t plane = dims.x * dims.y;
  if (r.first_non_finite) {
    const std::size_t i = *r.first_non_finite;
    const double bad = r.non_finite_value;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: sample (lon {}, lat {}, level {}) is {}; pass --nan-as-fill to treat "
                     "NaN/Inf as missing",
                     context, i % dims.x, (i % plane) / dims.x, z0 + i / plane,
                     std::isnan(bad) ? "NaN" : (bad > 0 ? "+Inf" : "-Inf"));
  }
  if (r.first_overflow) {
    const std::size_t i = *r.first_overflow;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: sample (lon {}, lat {}, level {}) unpacks to {} ({} x scale_factor {} + "
                     "add_offset {}), beyond the range of {}; check the variable's scale_factor "
                     "and add_offset",
                     context, i % dims.x, (i % plane) / dims.x, z0 + i / plane, r.overflow_value,
                     r.overflow_raw, attrs.scale_factor.value_or(1.0), attrs.add_offset.value_or(0.0),
                     sizeof(Out) == 4 ? "float32" : "float64");
  }
  if (r.first_inexact) {
    const std::size_t i = *r.first_inexact;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: sample (lon {}, lat {}, level {}) is {} ({}), which a float64 cannot hold "
                     "exactly (integers beyond 2^53 would be rounded); the store keeps values "
                     "exactly, so the variable cannot be converted",
                     context, i % dims.x, (i % plane) / dims.x, z0 + i / plane, r.inexact_raw,
                     nc_type_name(attrs.type));
  }
}

}  // namespace

template <typename Out>
SlabSource SlabReader::Impl::fetch_slab(std::size_t v, const VariableLocation& loc,
                                        std::size_t z0, std::size_t z1, std::span<Out> out,
                                        const std::string& context) {
  std::lock_guard lock(netcdf_mutex());
  OpenFile& of = open_file(loc.file);
  const VariableHandle& h = variable(of, loc.file, v);
  if (h.has_time ? loc.time_in_file >= h.time_length : loc.time_in_file != 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: time index {} not in the file (file changed since it was scanned?)",
                     context, loc.time_in_file);
  }
  SlabSource s;
  s.attrs = h.attrs;
  if (h.stagger != StaggeredAxis::kNone) {
    const Dims3 slab{catalog.dims().x, catalog.dims().y, z1 - z0};
    const Dims3 extent = staggered_extent(slab, h.stagger);
    s.stagger = h.stagger;
    s.raw = reusable_buffer(extent.count() * nc_type_size(s.attrs.type));
    get_slab(h, loc.time_in_file, z0, extent, s.raw, context);
    return s;
  }
  if (h.planes && of.direct) s.ranges = h.planes->planes(loc.time_in_file, z0, z1);
  if (s.ranges) {
    s.direct = of.direct;  // kept alive should another thread close the file
    return s;
  }
  // Samples already in the output type are read straight into `out` and converted in
  // place; others go through a reusable buffer.
  if (s.attrs.type == (sizeof(Out) == 4 ? NC_FLOAT : NC_DOUBLE)) {
    s.raw = reinterpret_cast<std::byte*>(out.data());
  } else {
    s.raw = reusable_buffer(out.size() * nc_type_size(s.attrs.type));
  }
  get_slab(h, loc.time_in_file, z0, Dims3{catalog.dims().x, catalog.dims().y, z1 - z0}, s.raw,
           context);
  return s;
}

// A file system that opens files with O_DIRECT but refuses the reads (alignment beyond
// 4 KiB, a device error): this file is read through netCDF from now on, and netCDF
// reports what is really wrong with it, if anything.
void SlabReader::Impl::stop_direct_reads(std::size_t file, const Error& e) {
  spdlog::warn("{}: direct read failed ({}); reading the file through netCDF",
               catalog.files[file].path, e.what());
  std::lock_guard lock(netcdf_mutex());
  direct_failed.insert(file);
  if (auto it = open.find(file); it != open.end()) it->second.direct.reset();
}

template <typename Out>
void SlabReader::Impl::read(std::size_t v, std::size_t t, std::size_t z0, std::size_t z1,
                            std::span<Out> out) {
  const std::size_t count = checked_slab_size(v, t, z0, z1, out.size());
  if (count == 0) return;

  const VariableLocation& loc = catalog.locations[v][t];
  const std::string& path = catalog.files[loc.file].path;
  const std::string& name = catalog.variables[v].name;
  const std::string context = fmt::format("{}: variable '{}' time step {}", path, name, t);
  if (!loc.grib_levels.empty()) {
    read_grib_levels(path, std::span(loc.grib_levels).subspan(z0, z1 - z0), count / (z1 - z0),
                     context, out.first(count));
    return;
  }

  SlabSource s;
  ConversionResult r;
  for (;;) {
    s = fetch_slab(v, loc, z0, z1, out, context);
    if (s.stagger != StaggeredAxis::kNone) {
      // Converted (unpacked, missing values NaN) in double, then destaggered.
      const Dims3 slab{catalog.dims().x, catalog.dims().y, z1 - z0};
      const Dims3 extent = staggered_extent(slab, s.stagger);
      std::vector<double> staggered(extent.count());
      r = convert_any<double>(s.attrs.type, s.raw, staggered.size(), s.attrs,
                              options.nan_as_fill, std::span<double>(staggered));
      check_converted<double>(r, s.attrs, Dims3{extent.x, extent.y, catalog.dims().z}, z0,
                              context + " (staggered)");
      destagger(staggered, slab, s.stagger, out.first(count));
      return;
    }
    if (!s.ranges) {
      r = convert_any<Out>(s.attrs.type, s.raw, count, s.attrs, options.nan_as_fill, out);
      break;
    }
    try {
      r = read_direct(*s.direct, *s.ranges, s.attrs, out);
      break;
    } catch (const Error& e) {
      stop_direct_reads(loc.file, e);
    }
  }
  check_converted<Out>(r, s.attrs, catalog.dims(), z0, context);
}

const InputCatalog& SlabReader::catalog() const { return impl_->catalog; }

SlabReader::SlabReader(const InputCatalog& catalog, const ScanOptions& options)
    : impl_(new Impl{catalog.as_in_files(), options, {}, 0}),
      repeat_first_column_(catalog.repeats_first_column()) {
  for (std::size_t v = 0; v < catalog.variables.size(); ++v) {
    if (v >= catalog.locations.size() || catalog.locations[v].size() != catalog.time.size()) {
      delete impl_;
      throw make_error(ErrorCode::kInvalidArgument,
                       "catalog has no location for every time step of variable '{}'",
                       catalog.variables[v].name);
    }
  }
}

std::uint64_t SlabReader::direct_bytes() const {
  return impl_->direct_bytes.load(std::memory_order_relaxed);
}

SlabReader::~SlabReader() {
  impl_->terms.reset();  // takes netcdf_mutex() itself
  std::lock_guard lock(netcdf_mutex());  // nc_close is a netCDF call too
  delete impl_;
}

namespace {

// Rows of `nx` samples at the start of `out` spread to rows of nx + 1 whose last sample
// repeats their first (a periodic longitude axis's repeated meridian), in place from the
// last row down.
template <typename T>
void repeat_first_column(std::span<T> out, std::size_t nx) {
  const std::size_t rows = out.size() / (nx + 1);
  for (std::size_t r = rows; r-- > 0;) {
    T* row = out.data() + r * (nx + 1);
    std::memmove(row, out.data() + r * nx, nx * sizeof(T));
    row[nx] = row[0];
  }
}

}  // namespace

template <typename T>
void SlabReader::read_any(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
                          std::span<T> out) {
  if (!repeat_first_column_) {
    impl_->read(variable, step, z0, z1, out);
    return;
  }
  const Dims3 dims = impl_->catalog.dims();  // as in the files
  const std::size_t with_repeat = (z1 - z0) * dims.y * (dims.x + 1);
  if (z0 > z1 || out.size() != with_repeat) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "output holds {} samples but levels [{}, {}) of {} x {} need {}", out.size(),
                     z0, z1, dims.x + 1, dims.y, with_repeat);
  }
  impl_->read(variable, step, z0, z1, out.first((z1 - z0) * dims.y * dims.x));
  repeat_first_column(out, dims.x);
}

namespace {

// An error from evaluating a geometry that does not yet name a file is given `context`.
[[noreturn]] void rethrow_with_context(const Error& e, const std::string& path,
                                       const std::string& context) {
  if (std::string_view(e.what()).substr(0, path.size()) == path) throw e;
  throw e.with_context(context);
}

std::size_t checked_output_size(std::size_t z0, std::size_t z1, const Dims3& dims,
                                bool repeat, std::size_t out_size) {
  if (z0 > z1 || z1 > dims.z) {
    throw make_error(ErrorCode::kInvalidArgument, "level range [{}, {}) outside [0, {})", z0, z1,
                     dims.z);
  }
  const std::size_t nx = dims.x + (repeat ? 1 : 0);
  const std::size_t count = (z1 - z0) * dims.y * nx;
  if (out_size != count) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "output holds {} values but levels [{}, {}) of {} x {} need {}", out_size,
                     z0, z1, nx, dims.y, count);
  }
  return (z1 - z0) * dims.y * dims.x;
}

// Whether the catalog's inputs are GRIB: its locations name messages.
bool from_grib(const InputCatalog& c) {
  return !c.locations.empty() && !c.locations.front().empty() &&
         !c.locations.front().front().grib_levels.empty();
}

}  // namespace

void SlabReader::read_vertical_geometry(std::size_t step, std::size_t z0, std::size_t z1,
                                        std::span<double> out) {
  const InputCatalog& c = impl_->catalog;
  if (!c.vertical_geometry) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "the catalog has no vertical geometry: its z axis places every sample");
  }
  if (step >= c.time.size()) {
    throw make_error(ErrorCode::kInvalidArgument, "time step {} out of range ({} steps)", step,
                     c.time.size());
  }
  const Dims3 dims = c.dims();  // as in the files
  const std::size_t count = checked_output_size(z0, z1, dims, repeat_first_column_, out.size());
  const VerticalGeometrySource& g = *c.vertical_geometry;
  const std::string& path = c.files[c.locations[0][step].file].path;
  const std::string context = fmt::format("{}: vertical geometry ({} from {}) time step {}", path,
                                          g.formula, fmt::join(g.sources, ", "), step);
  const std::span<double> in_files = out.first(count);
  try {
    if (from_grib(c)) {
      evaluate_grib_vertical_geometry(c, step, z0, z1, dims, in_files);
    } else {
      evaluate_vertical_geometry(g, impl_->term_reader(), step, z0, z1, dims, in_files);
    }
  } catch (const Error& e) {
    rethrow_with_context(e, path, context);
  }
  ColumnOrderCheck order(dims.x, dims.y, context);
  const std::size_t plane = dims.x * dims.y;
  for (std::size_t k = z0; k < z1; ++k) {
    order.add_level(k, in_files.subspan((k - z0) * plane, plane));
  }
  if (repeat_first_column_) repeat_first_column(out, dims.x);
}

void SlabReader::read_surface(std::span<double> out) {
  const InputCatalog& c = impl_->catalog;
  if (!c.surface) {
    throw make_error(ErrorCode::kInvalidArgument, "the catalog has no surface height");
  }
  const Dims3 dims = c.dims();
  const std::size_t count = checked_output_size(0, 1, Dims3{dims.x, dims.y, 1},
                                                repeat_first_column_, out.size());
  const std::string& path = c.files.front().path;
  try {
    if (from_grib(c)) {
      evaluate_grib_surface(c, dims, out.first(count));
    } else {
      evaluate_surface(*c.surface, impl_->term_reader(), dims, out.first(count));
    }
  } catch (const Error& e) {
    rethrow_with_context(e, path,
                         fmt::format("{}: surface height '{}'", path, c.surface->variable));
  }
  for (std::size_t s = 0; s < count; ++s) {
    if (!std::isfinite(out[s])) {
      throw make_error(ErrorCode::kInvalidInput, "{}: surface height '{}' sample (i {}, j {}) is "
                       "{}", path, c.surface->variable, s % dims.x, s / dims.x, out[s]);
    }
  }
  if (repeat_first_column_) repeat_first_column(out, dims.x);
}

void SlabReader::read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
                      std::span<float> out) {
  read_any(variable, step, z0, z1, out);
}

void SlabReader::read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
                      std::span<double> out) {
  read_any(variable, step, z0, z1, out);
}

}  // namespace strielad::ingest
