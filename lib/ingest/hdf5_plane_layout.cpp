// SPDX-License-Identifier: Apache-2.0
#include "ingest/hdf5_plane_layout.h"

#include <hdf5.h>
#include <netcdf.h>

#include <array>
#include <bit>
#include <utility>

#include <fmt/format.h>

namespace strielad::ingest {
namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is 64 bits since HDF5 1.10");

// The little-endian HDF5 file type whose bytes are the netCDF type's native ones on a
// little-endian host; negative for types without one (strings, compound).
hid_t little_endian_type(int nc_type) {
  switch (nc_type) {
    case NC_BYTE: return H5T_STD_I8LE;
    case NC_UBYTE: return H5T_STD_U8LE;
    case NC_SHORT: return H5T_STD_I16LE;
    case NC_USHORT: return H5T_STD_U16LE;
    case NC_INT: return H5T_STD_I32LE;
    case NC_UINT: return H5T_STD_U32LE;
    case NC_INT64: return H5T_STD_I64LE;
    case NC_UINT64: return H5T_STD_U64LE;
    case NC_FLOAT: return H5T_IEEE_F32LE;
    case NC_DOUBLE: return H5T_IEEE_F64LE;
    default: return -1;
  }
}

// Closes an HDF5 object id of the kind `close` takes when it goes out of scope.
template <herr_t (*Close)(hid_t)>
struct Id {
  hid_t id = -1;
  explicit Id(hid_t i) : id(i) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  ~Id() {
    if (id >= 0) Close(id);
  }
  hid_t release() { return std::exchange(id, -1); }
};

}  // namespace

std::unique_ptr<Hdf5PlaneLayout> Hdf5PlaneLayout::open(const std::string& path,
                                                       const std::string& variable,
                                                       int nc_type, bool has_time,
                                                       const Dims3& dims, std::string* why_not) {
  auto refuse = [&](std::string reason) -> std::unique_ptr<Hdf5PlaneLayout> {
    if (why_not) *why_not = std::move(reason);
    return nullptr;
  };
  if constexpr (std::endian::native != std::endian::little) return refuse("big-endian host");
  const hid_t wanted_type = little_endian_type(nc_type);
  if (wanted_type < 0) return refuse("not a numeric netCDF type");

  std::unique_ptr<Hdf5PlaneLayout> layout(new Hdf5PlaneLayout);
  auto inspect = [&]() -> std::unique_ptr<Hdf5PlaneLayout> {
    Id<H5Fclose> file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (file.id < 0) return refuse("HDF5 cannot open the file");
    Id<H5Dclose> dataset(H5Dopen2(file.id, ("/" + variable).c_str(), H5P_DEFAULT));
    if (dataset.id < 0) return refuse("no HDF5 dataset of that name");

    Id<H5Tclose> type(H5Dget_type(dataset.id));
    if (type.id < 0 || H5Tequal(type.id, wanted_type) <= 0) {
      return refuse("samples are not little-endian in the variable's own type");
    }
    const std::size_t sample_bytes = H5Tget_size(type.id);

    const int rank = has_time ? 4 : 3;
    Id<H5Sclose> space(H5Dget_space(dataset.id));
    std::array<hsize_t, 4> extent{};
    if (space.id < 0 || H5Sget_simple_extent_ndims(space.id) != rank ||
        H5Sget_simple_extent_dims(space.id, extent.data(), nullptr) != rank) {
      return refuse("HDF5 dataset rank differs from the netCDF variable's");
    }
    const std::size_t s = has_time ? 1 : 0;
    if (extent[s] != dims.z || extent[s + 1] != dims.y || extent[s + 2] != dims.x) {
      return refuse("HDF5 dataset shape differs from the netCDF variable's");
    }

    Id<H5Pclose> dcpl(H5Dget_create_plist(dataset.id));
    if (dcpl.id < 0) return refuse("HDF5 dataset has no creation properties");
    if (H5Pget_nfilters(dcpl.id) != 0) return refuse("stored through filters (compressed)");
    const H5D_layout_t kind = H5Pget_layout(dcpl.id);
    if (kind == H5D_CHUNKED) {
      std::array<hsize_t, 4> chunk{};
      if (H5Pget_chunk(dcpl.id, rank, chunk.data()) != rank) return refuse("unreadable chunk shape");
      if (chunk[s + 1] != dims.y || chunk[s + 2] != dims.x) {
        return refuse("chunks smaller than a lat x lon plane");
      }
      layout->chunked_ = true;
      layout->chunk_time_ = has_time ? chunk[0] : 1;
      layout->chunk_z_ = chunk[s];
    } else if (kind == H5D_CONTIGUOUS) {
      const haddr_t offset = H5Dget_offset(dataset.id);
      if (offset == HADDR_UNDEF) return refuse("never written (fill values only)");
      layout->contiguous_offset_ = offset;
    } else {
      return refuse("compact or virtual HDF5 layout");
    }
    layout->file_ = file.release();
    layout->dataset_ = dataset.release();
    layout->has_time_ = has_time;
    layout->nz_ = dims.z;
    layout->plane_bytes_ = std::uint64_t{dims.x} * dims.y * sample_bytes;
    return std::move(layout);
  };
  // HDF5 reports failures (e.g. a dataset stored under another name) on its error stack,
  // printed by default: silenced here (the caller falls back to netCDF). The macros save
  // and restore the error handler, so nothing may leave the block but its end.
  std::unique_ptr<Hdf5PlaneLayout> result;
  H5E_BEGIN_TRY { result = inspect(); }
  H5E_END_TRY;
  return result;
}

Hdf5PlaneLayout::~Hdf5PlaneLayout() {
  H5E_BEGIN_TRY {
    if (dataset_ >= 0) H5Dclose(dataset_);
    if (file_ >= 0) H5Fclose(file_);
  }
  H5E_END_TRY;
}

std::optional<std::vector<FileRange>> Hdf5PlaneLayout::planes(std::size_t t, std::size_t z0,
                                                             std::size_t z1) const {
  std::vector<FileRange> ranges;
  auto add = [&](std::uint64_t offset, std::uint64_t bytes) {
    if (!ranges.empty() && ranges.back().offset + ranges.back().bytes == offset) {
      ranges.back().bytes += bytes;
    } else {
      ranges.push_back({offset, bytes});
    }
  };
  if (!chunked_) {
    const std::uint64_t first = (std::uint64_t{t} * nz_ + z0) * plane_bytes_;
    if (z1 > z0) add(contiguous_offset_ + first, (z1 - z0) * plane_bytes_);
    return ranges;
  }
  const std::uint64_t chunk_bytes = std::uint64_t{chunk_time_} * chunk_z_ * plane_bytes_;
  const std::size_t t_in_chunk = t % chunk_time_;
  bool written = true;
  H5E_BEGIN_TRY {
    for (std::size_t z = z0; z < z1 && written;) {
      const std::size_t chunk_z0 = z / chunk_z_ * chunk_z_;
      const std::size_t end = std::min(z1, chunk_z0 + chunk_z_);
      std::array<hsize_t, 4> coord{};
      std::size_t d = 0;
      if (has_time_) coord[d++] = t - t_in_chunk;
      coord[d++] = chunk_z0;
      unsigned filter_mask = 0;
      haddr_t address = HADDR_UNDEF;
      hsize_t size = 0;
      written = H5Dget_chunk_info_by_coord(dataset_, coord.data(), &filter_mask, &address,
                                           &size) >= 0 &&
                address != HADDR_UNDEF && size == chunk_bytes;
      if (written) {
        // Planes in a chunk: C order over (time in chunk, z in chunk).
        const std::uint64_t plane = std::uint64_t{t_in_chunk} * chunk_z_ + (z - chunk_z0);
        add(address + plane * plane_bytes_, (end - z) * plane_bytes_);
      }
      z = end;
    }
  }
  H5E_END_TRY;
  if (!written) return std::nullopt;
  return ranges;
}

}  // namespace strielad::ingest
