// SPDX-License-Identifier: Apache-2.0
#include "core/checksum.h"

#include <xxhash.h>

namespace strielad {

std::uint64_t checksum64(std::span<const std::byte> bytes) noexcept {
  return XXH3_64bits(bytes.data(), bytes.size());
}

}  // namespace strielad
