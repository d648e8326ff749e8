// SPDX-License-Identifier: Apache-2.0
// The shared secret of formats/protocol.md read from a file (never from the command
// line, where other users see it): trailing newlines removed, at most kMaxTokenBytes.
#pragma once

#include <string>

namespace strielad::net {

// Like ssh with a private key, refuses a file that group or others have any permission
// on: a secret others can read protects nothing.
// \error kNotFound when the file cannot be opened; kInvalidInput naming the file and its
// mode when group or others have permissions on it (chmod 600 fixes it), and when it is
// empty or too long; kIo when reading it fails.
std::string read_token_file(const std::string& path);

}  // namespace strielad::net
