// SPDX-License-Identifier: Apache-2.0
#include "ingest/netcdf_call.h"

#include <H5Epublic.h>
#include <netcdf.h>

#include "core/error.h"

namespace strielad::ingest {

std::mutex& netcdf_mutex() {
  static std::mutex mutex;
  // netCDF turns HDF5's automatic error printing off only on the thread that first
  // initialises it, and HDF5 keeps that setting per thread: without this, netCDF-4
  // reads on pipeline threads print "HDF5-DIAG" noise for attributes netCDF probes.
  static thread_local const bool quiet = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)quiet;
  return mutex;
}

void nc_check(int status, std::string_view context) {
  if (status == NC_NOERR) return;
  ErrorCode code = ErrorCode::kIo;
  switch (status) {
    case NC_ENOTNC:
    case NC_EHDFERR:
    case NC_EBADDIM:
    case NC_EBADTYPE:
    case NC_ENOTVAR:
    case NC_ENOTATT:
    case NC_EINVALCOORDS:
    case NC_EEDGE:
      code = ErrorCode::kInvalidInput;
      break;
    case ENOENT:
      code = ErrorCode::kNotFound;
      break;
    default:
      break;
  }
  throw make_error(code, "{}: {}", context, nc_strerror(status));
}

}  // namespace strielad::ingest
