// SPDX-License-Identifier: Apache-2.0
#include "ingest/netcdf_call.h"

#include <netcdf.h>

#include "core/error.h"

namespace strielad::ingest {

std::mutex& netcdf_mutex() {
  static std::mutex mutex;
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
