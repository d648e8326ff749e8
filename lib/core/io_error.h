// SPDX-License-Identifier: Apache-2.0
// The error of a failed system call on a file: "PATH: cannot ACTION: strerror(err)",
// kNotFound for ENOENT and kIo otherwise.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/error.h"

namespace strielad {

Error io_error(std::string_view action, const std::filesystem::path& path, int err);

}  // namespace strielad
