// SPDX-License-Identifier: Apache-2.0
#include "bench/deflate_sizes.h"

#include <netcdf.h>

#include <mutex>

#include "bench/conversion_bench.h"
#include "bench/process_runner.h"
#include "core/error.h"
#include "ingest/netcdf_call.h"

namespace strielad::bench {
namespace {

// Size of a NetCDF-4 file with the input's dimensions and no variables.
std::uint64_t empty_file_size(const std::filesystem::path& input, const std::filesystem::path& out) {
  std::lock_guard lock(ingest::netcdf_mutex());
  int in = -1, o = -1;
  ingest::nc_check(nc_open(input.c_str(), NC_NOWRITE, &in), input.string() + ": open");
  int ndims = 0, unlimited = -1;
  nc_inq_ndims(in, &ndims);
  nc_inq_unlimdim(in, &unlimited);
  const int rc = nc_create(out.c_str(), NC_NETCDF4 | NC_CLOBBER, &o);
  if (rc != NC_NOERR) {
    nc_close(in);
    ingest::nc_check(rc, out.string() + ": create");
  }
  for (int d = 0; d < ndims; ++d) {
    char name[NC_MAX_NAME + 1] = {};
    std::size_t len = 0;
    nc_inq_dim(in, d, name, &len);
    int id = -1;
    nc_def_dim(o, name, d == unlimited ? NC_UNLIMITED : len, &id);
  }
  nc_close(in);
  ingest::nc_check(nc_close(o), out.string() + ": close");
  return std::filesystem::file_size(out);
}

}  // namespace

const DeflateSize* DeflateSizes::find(const std::string& name) const {
  for (const auto& v : variables) {
    if (v.variable == name) return &v;
  }
  return nullptr;
}

DeflateSizes measure_deflate_sizes(const std::filesystem::path& input,
                                   const std::vector<std::string>& variables,
                                   const std::filesystem::path& work, std::uint32_t brick,
                                   const std::vector<std::string>& nccopy_extra) {
  std::filesystem::create_directories(work);
  DeflateSizes sizes;
  const auto empty = work / "empty-dims.nc";
  sizes.empty_file_bytes = empty_file_size(input, empty);
  std::filesystem::remove(empty);
  sizes.command = shell_command(nccopy_argv(input, work / "VAR.nc", brick, nccopy_extra, {"VAR"}));
  for (const auto& var : variables) {
    const auto out = work / (var + ".nc");
    const auto argv = nccopy_argv(input, out, brick, nccopy_extra, {var});
    const ProcessResult p = run_process(argv, work / (var + ".log"));
    if (p.exit_status != 0) {
      throw make_error(ErrorCode::kIo, "'{}' failed with status {}: {}", shell_command(argv),
                       p.exit_status, p.output_tail);
    }
    DeflateSize d;
    d.variable = var;
    d.file_bytes = std::filesystem::file_size(out);
    d.bytes = d.file_bytes > sizes.empty_file_bytes ? d.file_bytes - sizes.empty_file_bytes : 0;
    d.seconds = p.seconds;
    sizes.variables.push_back(d);
    std::filesystem::remove(out);
    std::filesystem::remove(work / (var + ".log"));
  }
  return sizes;
}

}  // namespace strielad::bench
