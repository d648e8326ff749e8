// SPDX-License-Identifier: Apache-2.0
// The shared secret of formats/protocol.md read from a file (never from the command
// line, where other users see it): trailing newlines removed, at most kMaxTokenBytes.
#pragma once

#include <string>

namespace strielad::net {

// Warns (spdlog) when the file is readable by group or others.
// \error kNotFound when the file cannot be read; kInvalidInput when it is empty or too long.
std::string read_token_file(const std::string& path);

}  // namespace strielad::net
