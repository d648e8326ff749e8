// SPDX-License-Identifier: Apache-2.0
// Header grammar: https://docs.unidata.ucar.edu/netcdf-c/current/file_format_specifications.html
#include "ingest/classic_layout.h"

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/input_kind.h"

namespace strielad::ingest {
namespace {

enum class Parse { kOk, kNeedMore, kInvalid };

struct NeedMore {};
struct Invalid {};

constexpr std::uint64_t kMax = ~std::uint64_t{0};
constexpr std::uint64_t kMaxHeaderBytes = 64ull << 20;

std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > kMax / a) throw Invalid{};
  return a * b;
}
std::uint64_t add(std::uint64_t a, std::uint64_t b) {
  if (b > kMax - a) throw Invalid{};
  return a + b;
}
std::uint64_t pad4(std::uint64_t n) { return add(n, (4 - n % 4) % 4); }

// Big-endian cursor over the header bytes.
class Cursor {
 public:
  Cursor(std::span<const std::byte> bytes, int version) : bytes_(bytes), version_(version) {}

  std::uint64_t u32() { return be(4); }
  std::uint64_t u64() { return be(8); }
  // NON_NEG: 8 bytes in CDF-5, else 4.
  std::uint64_t non_neg() { return version_ == 5 ? u64() : u32(); }
  std::uint64_t offset() { return version_ == 1 ? u32() : u64(); }
  void skip(std::uint64_t n) {
    if (n > bytes_.size() - pos_) throw NeedMore{};
    pos_ += static_cast<std::size_t>(n);
  }
  void skip_name() { skip(pad4(non_neg())); }

 private:
  std::uint64_t be(std::size_t n) {
    if (n > bytes_.size() - pos_) throw NeedMore{};
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v = (v << 8) | std::to_integer<std::uint64_t>(bytes_[pos_ + i]);
    pos_ += n;
    return v;
  }

  std::span<const std::byte> bytes_;
  std::size_t pos_ = 0;
  int version_;
};

std::uint64_t external_type_size(std::uint64_t type, int version) {
  switch (type) {
    case 1: case 2: return 1;           // byte, char
    case 3: return 2;                   // short
    case 4: case 5: return 4;           // int, float
    case 6: return 8;                   // double
    default: break;
  }
  if (version == 5) {
    switch (type) {
      case 7: return 1;                 // ubyte
      case 8: return 2;                 // ushort
      case 9: return 4;                 // uint
      case 10: case 11: return 8;       // int64, uint64
      default: break;
    }
  }
  throw Invalid{};
}

void skip_attributes(Cursor& c, int version) {
  const std::uint64_t tag = c.u32();
  const std::uint64_t count = c.non_neg();
  if (tag == 0 && count == 0) return;
  if (tag != 0x0C) throw Invalid{};
  for (std::uint64_t i = 0; i < count; ++i) {
    c.skip_name();
    const std::uint64_t type = c.u32();
    const std::uint64_t n = c.non_neg();
    c.skip(pad4(mul(n, external_type_size(type, version))));
  }
}

// The dimension list: each dimension's length (0 for the record dimension).
std::vector<std::uint64_t> read_dimensions(Cursor& c) {
  std::vector<std::uint64_t> dims;
  const std::uint64_t tag = c.u32();
  const std::uint64_t count = c.non_neg();
  if (tag == 0 && count == 0) return dims;
  if (tag != 0x0A) throw Invalid{};
  for (std::uint64_t i = 0; i < count; ++i) {
    c.skip_name();
    dims.push_back(c.non_neg());
  }
  return dims;
}

struct Var {
  std::uint64_t begin = 0, len = 0;  // len: one record for record variables
  bool record = false;
};

// The variable list: where each variable's data begins and how long it is.
std::vector<Var> read_variables(Cursor& c, const std::vector<std::uint64_t>& dims, int version) {
  std::vector<Var> vars;
  const std::uint64_t tag = c.u32();
  const std::uint64_t count = c.non_neg();
  if (tag == 0 && count == 0) return vars;
  if (tag != 0x0B) throw Invalid{};
  for (std::uint64_t i = 0; i < count; ++i) {
    c.skip_name();
    const std::uint64_t ndims = c.non_neg();
    Var v;
    std::uint64_t product = 1;
    for (std::uint64_t d = 0; d < ndims; ++d) {
      const std::uint64_t dimid = c.non_neg();
      if (dimid >= dims.size()) throw Invalid{};
      if (dims[dimid] == 0) {
        if (d != 0) throw Invalid{};
        v.record = true;
      } else {
        product = mul(product, dims[dimid]);
      }
    }
    skip_attributes(c, version);
    const std::uint64_t type = c.u32();
    c.non_neg();  // vsize: recomputed below (it saturates for huge variables)
    v.begin = c.offset();
    v.len = mul(product, external_type_size(type, version));
    vars.push_back(v);
  }
  return vars;
}

// The end of the last variable's data: the bytes a complete file holds.
std::uint64_t data_end(const std::vector<Var>& vars, std::uint64_t numrecs, bool streaming) {
  std::uint64_t recsize = 0;
  std::size_t nrec = 0;
  for (const Var& v : vars) {
    if (!v.record) continue;
    recsize = add(recsize, pad4(v.len));
    ++nrec;
  }
  if (nrec == 1) {
    for (const Var& v : vars) {
      if (v.record) recsize = v.len;  // a lone record variable is not padded
    }
  }
  std::uint64_t required = 0;
  for (const Var& v : vars) {
    std::uint64_t end = v.begin;
    if (!v.record) {
      end = add(end, v.len);
    } else if (!streaming && numrecs > 0) {
      end = add(add(end, mul(numrecs - 1, recsize)), v.len);
    }
    required = std::max(required, end);
  }
  return required;
}

Parse parse(std::span<const std::byte> bytes, std::uint64_t& required) {
  if (bytes.size() < 4) return Parse::kNeedMore;
  if (bytes[0] != std::byte{'C'} || bytes[1] != std::byte{'D'} || bytes[2] != std::byte{'F'}) {
    return Parse::kInvalid;
  }
  const int version = std::to_integer<int>(bytes[3]);
  if (version != 1 && version != 2 && version != 5) return Parse::kInvalid;
  try {
    Cursor c(bytes.subspan(4), version);
    const std::uint64_t numrecs = c.non_neg();
    const bool streaming = version == 5 ? numrecs == kMax : numrecs == 0xFFFFFFFFu;
    const std::vector<std::uint64_t> dims = read_dimensions(c);
    skip_attributes(c, version);
    const std::vector<Var> vars = read_variables(c, dims, version);
    required = data_end(vars, numrecs, streaming);
    return Parse::kOk;
  } catch (const NeedMore&) {
    return Parse::kNeedMore;
  } catch (const Invalid&) {
    return Parse::kInvalid;
  }
}

}  // namespace

std::optional<std::uint64_t> classic_required_size(std::span<const std::byte> header) {
  std::uint64_t required = 0;
  if (parse(header, required) != Parse::kOk) return std::nullopt;
  return required;
}

void check_classic_header(const std::filesystem::path& path) {
  ReadOnlyFile file(path);
  const std::uint64_t size = file.size();
  std::uint64_t want = std::min<std::uint64_t>(size, 64 * 1024);
  for (;;) {
    std::vector<std::byte> bytes(static_cast<std::size_t>(want));
    file.read_at(0, bytes);
    std::uint64_t required = 0;
    const Parse result = parse(bytes, required);
    if (result == Parse::kInvalid) {
      if (!has_classic_magic(bytes)) return;  // not classic: netCDF/HDF5 checks the rest
      // netCDF-C's own parser of classic headers trusts what it reads (a mutated count
      // made it crash in NC_hashmapadd or free_NC_vararrayV): a header that does not
      // follow the grammar never reaches it.
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable netCDF file: its classic-format header is damaged "
                       "(a tag, type, count or dimension id that the format does not allow)",
                       path.string());
    }
    if (result == Parse::kOk) {
      if (size < required) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: file is truncated: its header describes {} bytes of data but "
                         "the file has only {} bytes",
                         path.string(), required, size);
      }
      return;
    }
    if (want >= size) {
      if (size >= 4) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: file is truncated: it ends inside its netCDF header ({} bytes)",
                         path.string(), size);
      }
      return;  // too short to tell; nc_open reports it
    }
    // Real headers are a few MiB at most: beyond that, leave the file to netCDF.
    if (want >= kMaxHeaderBytes) return;
    want = std::min<std::uint64_t>({size, want * 4, kMaxHeaderBytes});
  }
}

}  // namespace strielad::ingest
