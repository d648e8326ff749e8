// SPDX-License-Identifier: Apache-2.0
// The built-in look chosen by --look (docs/view.md "Looks"): the default clouds, or the
// "scalar on surface" shader (render/surface_scalar_look.h) with its legend.
#pragma once

#include <optional>

#include "render/colour_bar_legend.h"
#include "viewer_args.h"
#include "viewer_session.h"

namespace strielad::view_cmd {

// With --look scalar: puts the --color-by variables among the session's scene
// attributes (when missing), its shader in the session, and returns the legend to draw.
// With --look clouds: the session unchanged, no legend. \error kInvalidArgument for
// --look scalar without --color-by or with --shader, a variable the store lacks, more
// attributes than the viewer carries, a malformed --color-range, an unknown --colormap,
// or no range (the store records none and --color-range is missing).
std::optional<render::ColourBarLegend> apply_look(const ViewerArgs& args, ViewerSession& session);

}  // namespace strielad::view_cmd
