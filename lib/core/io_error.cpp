// SPDX-License-Identifier: Apache-2.0
#include "core/io_error.h"

#include <cerrno>
#include <cstring>

namespace strielad {

Error io_error(std::string_view action, const std::filesystem::path& path, int err) {
  return make_error(err == ENOENT ? ErrorCode::kNotFound : ErrorCode::kIo, "{}: cannot {}: {}",
                    path.string(), action, std::strerror(err));
}

}  // namespace strielad
