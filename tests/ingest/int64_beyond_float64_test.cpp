// SPDX-License-Identifier: Apache-2.0
// int64/uint64 samples go into a float64 store: every value a double holds exactly is
// kept bit for bit (far beyond 2^53 when its low bits are zero); one it cannot hold
// (2^53 + 1, which was stored as 2^53) is refused with the file, variable, position and
// value, through netCDF and through direct reads alike. Missing samples are not checked.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

constexpr long long k2p53 = 1LL << 53;

// A (time, lev, lat, lon) variable "N" of `type` (NC_INT64 or NC_UINT64) holding
// `values` exactly: the fixture writes doubles, so the samples are written again here.
template <typename T>
void write_wide(const std::filesystem::path& path, int cmode, int type, const std::vector<T>& values,
                std::vector<NcAttr> attrs = {}) {
  SimpleGrid g;
  g.time_unlimited = false;  // contiguous storage needs fixed dimensions
  VarStorage storage;
  storage.contiguous = cmode == NC_NETCDF4;
  NetcdfFixture(cmode)
      .grid(g)
      .variable("N", type, g.dims(), std::vector<double>(g.samples(), 0.0), std::move(attrs),
                storage)
      .write(path);
  int ncid = -1, varid = -1;
  if (nc_open(path.c_str(), NC_WRITE, &ncid) != NC_NOERR) throw std::runtime_error("nc_open");
  int rc = nc_inq_varid(ncid, "N", &varid);
  if constexpr (std::is_signed_v<T>) {
    if (rc == NC_NOERR) rc = nc_put_var_longlong(ncid, varid, values.data());
  } else {
    if (rc == NC_NOERR) rc = nc_put_var_ulonglong(ncid, varid, values.data());
  }
  nc_close(ncid);
  if (rc != NC_NOERR) throw std::runtime_error(nc_strerror(rc));
}

std::vector<double> read_all(const std::filesystem::path& path, bool direct = true) {
  const InputCatalog c = scan_inputs({path}, {});
  ScanOptions options;
  options.direct_input = direct;
  SlabReader reader(c, options);
  std::vector<double> v(c.dims().count());
  reader.read(0, 0, 0, c.dims().z, v);
  return v;
}

struct Format {
  const char* name;
  int cmode;
  bool direct;
};
// CDF-5 through netCDF; netCDF-4 contiguous (raw planes, read with O_DIRECT where the
// file system allows) and through netCDF.
const Format kFormats[] = {{"cdf5", NC_64BIT_DATA, false},
                           {"netcdf4-direct", NC_NETCDF4, true},
                           {"netcdf4", NC_NETCDF4, false}};

TEST(Int64BeyondFloat64Test, ValuesADoubleHoldsAreKeptExactly) {
  const SimpleGrid g;
  std::vector<long long> values(g.samples(), 7);
  values[0] = k2p53;
  values[1] = -k2p53;
  values[2] = k2p53 + 2;                          // even: exact
  values[3] = (1LL << 62) + (1LL << 10);          // 53 significant bits
  values[4] = std::numeric_limits<long long>::min();  // -2^63: one bit
  values[5] = k2p53 - 1;
  for (const Format& f : kFormats) {
    TempDir dir;
    write_wide(dir / "n.nc", f.cmode, NC_INT64, values);
    const auto v = read_all(dir / "n.nc", f.direct);
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_EQ(v[i], static_cast<double>(values[i])) << f.name << " sample " << i;
      EXPECT_EQ(static_cast<long double>(v[i]), static_cast<long double>(values[i]))
          << f.name << " sample " << i;
    }
  }
}

TEST(Int64BeyondFloat64Test, TwoTo53PlusOneIsRefusedNamingFileVariableAndSample) {
  const SimpleGrid g;
  std::vector<long long> values(g.samples(), 1);
  values[17] = k2p53 + 1;  // lon 1, lat 1, level 1
  values[20] = -k2p53 - 3;
  for (const Format& f : kFormats) {
    TempDir dir;
    write_wide(dir / "n.nc", f.cmode, NC_INT64, values);
    expect_error([&] { read_all(dir / "n.nc", f.direct); }, ErrorCode::kInvalidInput,
                 {(dir / "n.nc").string(), "variable 'N'", "time step 0",
                  "(lon 1, lat 1, level 1)", "9007199254740993", "int64", "2^53"});
  }
}

TEST(Int64BeyondFloat64Test, Uint64MaximumIsRefused) {
  const SimpleGrid g;
  std::vector<unsigned long long> values(g.samples(), 3);
  values[9] = std::numeric_limits<unsigned long long>::max();  // not the default fill (max - 1)
  TempDir dir;
  write_wide(dir / "u.nc", NC_NETCDF4, NC_UINT64, values);
  expect_error([&] { read_all(dir / "u.nc"); }, ErrorCode::kInvalidInput,
               {"variable 'N'", "(lon 1, lat 2, level 0)", "18446744073709551615", "uint64"});
}

TEST(Int64BeyondFloat64Test, MissingSamplesAreNotChecked) {
  const SimpleGrid g;
  std::vector<long long> values(g.samples(), 5);
  values[1] = NC_FILL_INT64;  // the default fill, -9223372036854775806: missing
  values[2] = k2p53 + 1;      // the declared _FillValue: missing
  values[3] = -k2p53 - 1;     // below valid_min: missing
  TempDir dir;
  write_wide(dir / "f.nc", NC_64BIT_DATA, NC_INT64, values,
             {NcAttr::number("missing_value", NC_INT64, {static_cast<double>(k2p53)})});
  // The fixture writes attributes as doubles: put the exact ones here.
  int ncid = -1, varid = -1;
  ASSERT_EQ(nc_open((dir / "f.nc").c_str(), NC_WRITE, &ncid), NC_NOERR);
  ASSERT_EQ(nc_redef(ncid), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(ncid, "N", &varid), NC_NOERR);
  const long long missing = k2p53 + 1, low = -k2p53;
  ASSERT_EQ(nc_put_att_longlong(ncid, varid, "missing_value", NC_INT64, 1, &missing), NC_NOERR);
  ASSERT_EQ(nc_put_att_longlong(ncid, varid, "valid_min", NC_INT64, 1, &low), NC_NOERR);
  ASSERT_EQ(nc_close(ncid), NC_NOERR);
  const auto v = read_all(dir / "f.nc");
  EXPECT_TRUE(std::isnan(v[1]));
  EXPECT_TRUE(std::isnan(v[2]));
  EXPECT_TRUE(std::isnan(v[3]));
  EXPECT_EQ(v[4], 5.0);
}

TEST(Int64BeyondFloat64Test, PackedValuesStartFromTheExactRawValue) {
  const SimpleGrid g;
  std::vector<long long> values(g.samples(), 2);
  values[6] = k2p53 + 1;
  TempDir dir;
  write_wide(dir / "p.nc", NC_64BIT_DATA, NC_INT64, values,
             {NcAttr::number("scale_factor", NC_DOUBLE, {0.5})});
  expect_error([&] { read_all(dir / "p.nc"); }, ErrorCode::kInvalidInput,
               {"variable 'N'", "(lon 2, lat 1, level 0)", "9007199254740993"});
  values[6] = k2p53 + 2;
  write_wide(dir / "p.nc", NC_64BIT_DATA, NC_INT64, values,
             {NcAttr::number("scale_factor", NC_DOUBLE, {0.5})});
  EXPECT_EQ(read_all(dir / "p.nc")[6], static_cast<double>(k2p53 / 2 + 1));
}

}  // namespace
}  // namespace strielad::ingest
