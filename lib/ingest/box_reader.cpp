// SPDX-License-Identifier: Apache-2.0
#include "ingest/box_reader.h"

#include <fcntl.h>
#include <netcdf.h>
#include <netcdf_filter.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "ingest/grib_catalog.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"
#include "ingest/sample_conversion.h"
#include "ingest/variable_meta.h"
#include "ingest/wrf_destagger.h"

namespace strielad::build {

struct BoxReader::Impl {
  std::string path, name;
  // The file's variable read: `name`, or the source of a derived variable (WRF's theta
  // reads T, adding value_offset to every value).
  std::string source_name;
  double value_offset = 0;
  std::string context;  // "file: variable 'x' time step t"
  ingest::NcFile file;
  int grpid = -1, varid = -1;
  bool has_time = false;
  // WRF's U, V, W: the box is read one sample longer along this axis and destaggered.
  ingest::StaggeredAxis stagger = ingest::StaggeredAxis::kNone;
  std::size_t time_index = 0;
  bool filtered = false;
  bool nan_as_fill = false;
  ingest::CfValueAttributes attrs;
  // The planes' file offsets and a descriptor for prefetching (unfiltered netCDF-4 only).
  std::unique_ptr<ingest::Hdf5PlaneLayout> planes;
  int prefetch_fd = -1;
  Dims3 dims{};
  // Samples per row in the file when the catalog repeats the first meridian at the end
  // (column source_nx of a box is column 0 of the file); 0 otherwise.
  std::size_t repeated_from = 0;
  // GRIB input: each level's message (every read decodes whole levels); empty for netCDF.
  std::vector<ingest::GribMessageRef> grib_levels;
  // Raw samples of the last read; grown on demand, never zero-filled (netCDF fills it).
  std::unique_ptr<std::byte[]> buffer;
  std::size_t buffer_size = 0;

  template <typename Out>
  void read(const IndexBox& box, std::span<Out> out);
  template <typename Out>
  void read_grib(const IndexBox& box, std::span<Out> out);

  ~Impl() {
    if (prefetch_fd >= 0) ::close(prefetch_fd);
  }
};

namespace {

template <typename Raw, typename Out>
void convert(const std::byte* buffer, const ingest::CfValueAttributes& attrs, bool nan_as_fill,
             std::span<Out> out) {
  const std::span<const Raw> raw(reinterpret_cast<const Raw*>(buffer), out.size());
  ingest::convert_samples<Raw, Out>(raw, attrs, nan_as_fill, out);
}

template <typename Out>
void convert_any(const std::byte* buffer, const ingest::CfValueAttributes& attrs,
                 bool nan_as_fill, std::span<Out> out) {
  switch (attrs.type) {
    case NC_BYTE: return convert<signed char>(buffer, attrs, nan_as_fill, out);
    case NC_UBYTE: return convert<unsigned char>(buffer, attrs, nan_as_fill, out);
    case NC_SHORT: return convert<short>(buffer, attrs, nan_as_fill, out);
    case NC_USHORT: return convert<unsigned short>(buffer, attrs, nan_as_fill, out);
    case NC_INT: return convert<int>(buffer, attrs, nan_as_fill, out);
    case NC_UINT: return convert<unsigned int>(buffer, attrs, nan_as_fill, out);
    case NC_INT64: return convert<long long>(buffer, attrs, nan_as_fill, out);
    case NC_UINT64: return convert<unsigned long long>(buffer, attrs, nan_as_fill, out);
    case NC_FLOAT: return convert<float>(buffer, attrs, nan_as_fill, out);
    case NC_DOUBLE: return convert<double>(buffer, attrs, nan_as_fill, out);
    default: throw make_error(ErrorCode::kInternal, "unexpected netCDF type {}", attrs.type);
  }
}

}  // namespace

BoxReader::BoxReader(const ingest::InputCatalog& catalog, const ingest::ScanOptions& scan,
                     std::size_t variable, std::size_t step)
    : impl_(std::make_unique<Impl>()) {
  if (variable >= catalog.variables.size() || variable >= catalog.locations.size() ||
      step >= catalog.locations[variable].size()) {
    throw make_error(ErrorCode::kInvalidArgument, "box reader: no variable {} at time step {}",
                     variable, step);
  }
  const ingest::VariableLocation& loc = catalog.locations[variable][step];
  Impl& m = *impl_;
  m.path = catalog.files.at(loc.file).path;
  m.name = catalog.variables[variable].name;
  m.source_name = catalog.variables[variable].source_variable.empty()
                      ? m.name
                      : catalog.variables[variable].source_variable;
  m.value_offset = catalog.variables[variable].value_offset;
  m.context = fmt::format("{}: variable '{}' time step {}", m.path, m.name, step);
  m.time_index = loc.time_in_file;
  m.nan_as_fill = scan.nan_as_fill;

  if (catalog.repeats_first_column()) m.repeated_from = catalog.source_nx;
  if (!loc.grib_levels.empty()) {
    m.grib_levels = loc.grib_levels;
    m.dims = catalog.as_in_files().dims();
    m.filtered = true;
    return;
  }
  std::lock_guard lock(ingest::netcdf_mutex());
  try {
    open_variable(m, catalog.as_in_files().dims());
  } catch (...) {
    m.file = ingest::NcFile();  // closed under the lock
    throw;
  }
}

void BoxReader::open_variable(Impl& m, Dims3 dims) {
  m.file = ingest::NcFile(m.path);
  m.grpid = m.file.id();
  std::string short_name = m.source_name;
  if (const auto slash = m.source_name.rfind('/'); slash != std::string::npos) {
    std::string group = "/";  // not "/" + substr: GCC 12 -O3 warns falsely (PR 105651)
    group.append(m.source_name, 0, slash);
    short_name = m.source_name.substr(slash + 1);
    ingest::nc_check(nc_inq_grp_full_ncid(m.file.id(), group.c_str(), &m.grpid), m.context);
  }
  ingest::nc_check(nc_inq_varid(m.grpid, short_name.c_str(), &m.varid), m.context);
  const auto dimids = ingest::variable_dimids(m.grpid, m.varid);
  bool ok = dimids.size() == 3 || dimids.size() == 4;
  if (ok) {
    m.has_time = dimids.size() == 4;
    const std::size_t s = dimids.size() - 3;
    const auto stagger = ingest::staggered_axis(
        {ingest::dimension_name(m.grpid, dimids[s]), ingest::dimension_name(m.grpid, dimids[s + 1]),
         ingest::dimension_name(m.grpid, dimids[s + 2])},
        {ingest::dimension_length(m.grpid, dimids[s]),
         ingest::dimension_length(m.grpid, dimids[s + 1]),
         ingest::dimension_length(m.grpid, dimids[s + 2])},
        dims);
    if (stagger) m.stagger = *stagger;
    ok = stagger.has_value() &&
         (m.has_time ? m.time_index < ingest::dimension_length(m.grpid, dimids[0])
                     : m.time_index == 0);
  }
  if (!ok) {
    throw make_error(ErrorCode::kInvalidInput, "{}: no longer has the shape it had when scanned",
                     m.context);
  }
  m.attrs = ingest::read_value_attributes(m.grpid, m.varid);
  ingest::add_value_offset(m.attrs, m.value_offset);
  if (!ingest::is_numeric_type(m.attrs.type)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: non-numeric type {}", m.context,
                     ingest::nc_type_name(m.attrs.type));
  }
  // Classic files have neither filters nor chunk caches: both calls then fail harmlessly.
  std::size_t filters = 0;
  int shuffle = 0, deflate = 0, level = 0;
  const bool has_filters =
      nc_inq_var_filter_ids(m.grpid, m.varid, &filters, nullptr) == NC_NOERR && filters > 0;
  const bool has_shuffle =
      nc_inq_var_deflate(m.grpid, m.varid, &shuffle, &deflate, &level) == NC_NOERR &&
      (shuffle != 0 || deflate != 0);
  m.filtered = has_filters || has_shuffle;
  if (m.filtered || m.stagger != ingest::StaggeredAxis::kNone) return;
  nc_set_var_chunk_cache(m.grpid, m.varid, 0, 0, 0.75f);
  std::string why_not;
  m.planes = ingest::Hdf5PlaneLayout::open(m.path, m.source_name, m.attrs.type, m.has_time, dims,
                                           &why_not);
  if (m.planes) {
    m.dims = dims;
    m.prefetch_fd = ::open(m.path.c_str(), O_RDONLY | O_CLOEXEC);  // -1: no prefetching
  }
}

std::vector<ingest::FileRange> BoxReader::prefetch_ranges(const IndexBox& requested) const {
  const Impl& m = *impl_;
  IndexBox box = requested;  // the repeated meridian is the file's first column: not prefetched
  if (m.repeated_from != 0 && box.hi[0] >= m.repeated_from) {
    if (box.lo[0] >= m.repeated_from) return {};
    box.hi[0] = m.repeated_from - 1;
  }
  std::vector<ingest::FileRange> out;
  if (m.prefetch_fd < 0) return out;
  const std::uint64_t sample = ingest::nc_type_size(m.attrs.type);
  const std::uint64_t nx = m.dims.x;
  const std::uint64_t first = (box.lo[1] * nx + box.lo[0]) * sample;
  const std::uint64_t bytes = ((box.hi[1] - box.lo[1]) * nx + box.extent(0)) * sample;
  std::lock_guard lock(ingest::netcdf_mutex());
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z) {
    const auto plane = m.planes->planes(m.time_index, z, z + 1);
    if (!plane || plane->size() != 1) continue;  // never written: netCDF supplies the fill
    out.push_back({plane->front().offset + first, bytes});
  }
  return out;
}

void BoxReader::prefetch(const IndexBox& box) {
  for (const ingest::FileRange& r : prefetch_ranges(box)) {
    ::posix_fadvise(impl_->prefetch_fd, static_cast<off_t>(r.offset), static_cast<off_t>(r.bytes),
                    POSIX_FADV_WILLNEED);
  }
}

BoxReader::~BoxReader() {
  std::lock_guard lock(ingest::netcdf_mutex());  // nc_close is a netCDF call too
  impl_.reset();
}

bool BoxReader::filtered() const { return impl_->filtered; }

template <typename Out>
void BoxReader::Impl::read_grib(const IndexBox& box, std::span<Out> out) {
  const std::size_t plane = dims.x * dims.y;
  std::vector<Out> level(plane);
  Out* dst = out.data();
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z) {
    ingest::read_grib_levels(path, std::span(grib_levels).subspan(z, 1), plane, context,
                             std::span<Out>(level));
    for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y) {
      const Out* row = level.data() + y * dims.x;
      dst = std::copy(row + box.lo[0], row + box.hi[0] + 1, dst);
    }
  }
}

template <typename Out>
void BoxReader::Impl::read(const IndexBox& box, std::span<Out> out) {
  if (out.size() != box.count()) {
    throw make_error(ErrorCode::kInternal, "box reader: {} samples for a box of {}", out.size(),
                     box.count());
  }
  if (!grib_levels.empty()) {
    read_grib(box, out);
    return;
  }
  IndexBox file_box = box;  // one longer along a staggered axis
  if (stagger == ingest::StaggeredAxis::kX) ++file_box.hi[0];
  if (stagger == ingest::StaggeredAxis::kY) ++file_box.hi[1];
  if (stagger == ingest::StaggeredAxis::kZ) ++file_box.hi[2];
  {
    std::lock_guard lock(ingest::netcdf_mutex());
    std::array<std::size_t, 4> start{}, edge{};
    std::size_t d = 0;
    if (has_time) {
      start[d] = time_index;
      edge[d++] = 1;
    }
    for (int a = 2; a >= 0; --a) {
      start[d] = file_box.lo[a];
      edge[d++] = file_box.extent(a);
    }
    const std::size_t bytes = file_box.count() * ingest::nc_type_size(attrs.type);
    if (buffer_size < bytes) {
      buffer.reset(new std::byte[bytes]);
      buffer_size = bytes;
    }
    ingest::nc_check(nc_get_vara(grpid, varid, start.data(), edge.data(), buffer.get()), context);
  }
  if (stagger == ingest::StaggeredAxis::kNone) {
    convert_any<Out>(buffer.get(), attrs, nan_as_fill, out);
    return;
  }
  std::vector<double> staggered(file_box.count());
  convert_any<double>(buffer.get(), attrs, nan_as_fill, std::span<double>(staggered));
  ingest::destagger(staggered, Dims3{box.extent(0), box.extent(1), box.extent(2)}, stagger, out);
}

namespace {

// A box reaching the repeated meridian (column `repeated`, the file's column 0): the part
// before it, and that column read from column 0, interleaved row by row.
template <typename Out, typename ReadFn>
void read_with_repeated_column(const IndexBox& box, std::size_t repeated, std::span<Out> out,
                               ReadFn read) {
  const std::size_t rows = box.extent(1) * box.extent(2);
  IndexBox column = box;
  column.lo[0] = column.hi[0] = 0;
  std::vector<Out> first(rows);
  read(column, std::span<Out>(first));
  const std::size_t width = box.extent(0);
  if (box.lo[0] == repeated) {  // only the repeated column
    std::copy(first.begin(), first.end(), out.begin());
    return;
  }
  IndexBox before = box;
  before.hi[0] = repeated - 1;
  read(before, out.first(rows * (width - 1)));
  for (std::size_t r = rows; r-- > 0;) {
    Out* row = out.data() + r * width;
    std::memmove(row, out.data() + r * (width - 1), (width - 1) * sizeof(Out));
    row[width - 1] = first[r];
  }
}

}  // namespace

template <typename Out>
void BoxReader::read_any(const IndexBox& box, std::span<Out> out) {
  Impl& m = *impl_;
  if (m.repeated_from == 0 || box.hi[0] < m.repeated_from) {
    m.read(box, out);
    return;
  }
  if (out.size() != box.count()) {
    throw make_error(ErrorCode::kInternal, "box reader: {} samples for a box of {}", out.size(),
                     box.count());
  }
  read_with_repeated_column(box, m.repeated_from, out,
                            [&](const IndexBox& b, std::span<Out> o) { m.read(b, o); });
}

void BoxReader::read(const IndexBox& box, std::span<float> out) { read_any(box, out); }
void BoxReader::read(const IndexBox& box, std::span<double> out) { read_any(box, out); }

}  // namespace strielad::build
