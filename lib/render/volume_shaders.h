// SPDX-License-Identifier: Apache-2.0
// The GLSL of the A-buffer renderer (render/volume_renderer.h): the built-in parts of
// its programs. The user's colour and transparency functions (docs/view.md, "User
// shaders") are appended to the geometry pass's fragment stage and to the resolve stage.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace strielad::render {

// Fragments a pixel's resolve keeps (the nearest ones) and sorts.
inline constexpr int kMaxLayersPerPixel = 32;
// The colour function's alpha output is an opacity multiplier in [0, kMaxOpacityScale].
inline constexpr float kMaxOpacityScale = 4.0f;

// Definitions both user stages see: MAX_ATTRIBUTES, ATTR_<name> per attribute (names
// made GLSL-safe), height_m(), missing(), subvolume_color(), and the prototypes of
// color() and alpha(). Both stages declare u_slot_ids[32] before it.
std::string user_prelude(const std::vector<std::string>& attribute_names);

std::string geometry_vertex_source();
std::string geometry_fragment_source(const std::string& prelude);
std::string resolve_vertex_source();
// Sorts each pixel's list by depth, keeps the K nearest and relinks them in order.
std::string sort_fragment_source();
std::string resolve_fragment_source(const std::string& prelude);
std::string background_fragment_source();
std::string line_vertex_source();
std::string line_fragment_source();

// The built-in default user shader (examples/shaders/clouds.glsl).
const std::string& default_user_shader();

}  // namespace strielad::render
