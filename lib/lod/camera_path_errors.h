// SPDX-License-Identifier: Apache-2.0
// Internal to lib/lod's camera paths: errors "what: path: message" naming the file and
// the JSON path of the offending value, and path building: those of core/strict_json.h,
// which reads camera-path JSON.
#pragma once

#include "core/strict_json.h"

namespace strielad::lod::path_detail {

using strict_json::fail;
using strict_json::index_path;
using strict_json::key_path;
using strict_json::shown;

}  // namespace strielad::lod::path_detail
