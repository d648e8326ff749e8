// SPDX-License-Identifier: Apache-2.0
// The representative level heights of a terrain-following store (formats/store.md,
// "Grid geometry (version 5)"): the world frame's vertical map of such a store
// (lod::WorldFrameOptions::level_heights_m) is one height per level, taken from the
// geometry field's column at the domain's centre at the first time step (a pressure
// through the ICAO standard atmosphere). Camera, boxes, slices and advection place z by
// it; vertices of sub-volumes are placed exactly by the field itself
// (view/height_placement.h).
#pragma once

#include <vector>

namespace strielad {
class Store;
}

namespace strielad::view {

// The level-0 column of the geometry field at the centre sample (nx / 2, ny / 2), in
// metres, one per z sample; empty for a store without a geometry field (a `levels`
// geometry is the frame's own table).
// \error kInvalidInput naming the store when the column has a missing value or is not
// strictly monotonic; kCorrupt as Store::read_brick.
std::vector<double> representative_level_heights_m(const Store& store);

}  // namespace strielad::view
