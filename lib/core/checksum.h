// SPDX-License-Identifier: Apache-2.0
// XXH3-64 (libxxhash) is the checksum of every stored object; see formats/store.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace strielad {

std::uint64_t checksum64(std::span<const std::byte> bytes) noexcept;

}  // namespace strielad
