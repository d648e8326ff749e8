// SPDX-License-Identifier: Apache-2.0
// What `strielad-convert info` prints: a human summary or JSON of a store's manifest,
// files and octree, written to a stream so it is testable.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "store/store.h"

namespace strielad {

void describe_store(const Store& store, std::ostream& out);
nlohmann::json store_info_json(const Store& store);

}  // namespace strielad
