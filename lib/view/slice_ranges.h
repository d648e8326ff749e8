// SPDX-License-Identifier: Apache-2.0
// The colour range a slice without a `range` gets (formats/scene.md, "Slices"): the
// smallest and largest value of its colouring variable among the slice vertices shown
// now, so the colour map spans what is on screen, locally and through a remote server
// alike. Missing values (NaN) are ignored.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "view/progressive_meshes.h"

namespace strielad::view {

using SliceRange = std::array<float, 2>;  // lo, hi

// One entry per slice slot 0 .. slice_count - 1; nullopt for a slice with no finite value
// shown.
std::vector<std::optional<SliceRange>> shown_slice_ranges(const ProgressiveMeshes& meshes,
                                                          std::size_t slice_count);

}  // namespace strielad::view
