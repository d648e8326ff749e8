// SPDX-License-Identifier: Apache-2.0
// Internal to lib/scene: errors that name the scene and the path of the offending value
// ("scene.json: subvolumes[1].limits[0].min: ..."), and path building: those of
// core/strict_json.h, which reads scene JSON.
#pragma once

#include "core/strict_json.h"

namespace strielad::scene_detail {

using strict_json::fail;
using strict_json::index_path;
using strict_json::key_path;
using strict_json::shown;

}  // namespace strielad::scene_detail
