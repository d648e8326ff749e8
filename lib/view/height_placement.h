// SPDX-License-Identifier: Apache-2.0
// How the viewer places its meshes' heights. The world frame's
// vertical map (lod/world_frame.h) places a height axis as it is and a pressure axis by
// the ICAO standard atmosphere; a pressure-level store that also holds geopotential or
// geopotential height (zg, gh, z, phi ...: choose_vertical_placement in
// extract/output_frame.h) is placed by that field instead: the viewer asks the server for
// it as one more per-vertex attribute of the scene it sends (view/view_link.h) and sets
// each vertex's height from its value (view/node_geometry.h). The frame's own map stays
// the standard atmosphere for what has no field value: camera positions, the advection
// lattice, slices (the server sends no attribute with them) and vertices where the field
// is missing.
//
// Node boxes stay conservative: each node's vertical extent is widened to the field's
// exact range in the node over every time step, read from the store's index (the
// per-node minimum and maximum the converter wrote), so every placed vertex is inside
// its node's box. That needs the store on this machine; through --connect the viewer
// keeps the standard atmosphere and says why.
//
// A terrain-following store (formats/store.md, "Grid geometry (version 5)") with a
// per-sample geometry field is placed the same way by the field (geometry_height, or
// geometry_pressure through the ICAO standard atmosphere), and its frame maps z by the
// field's column at the domain's centre (view/level_heights.h): vertices of sub-volumes
// are exact, camera, slices and advection approximate. It needs the store on this
// machine (refused otherwise). A geometry of `levels` is the frame's own table.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "format/manifest.h"
#include "lod/geometry.h"

namespace strielad {
class Store;
}

namespace strielad::view {

struct HeightPlacement {
  enum class Kind {
    kFrame,     // the world frame's vertical map: a height axis, or the standard atmosphere
    kVariable,  // a store variable per vertex
  };
  Kind kind = Kind::kFrame;
  std::string variable;        // kVariable: carried as an extra attribute of the scene
  double metres_per_unit = 1;  // kVariable: the variable's units to metres
  // kVariable: > 0 when the variable is a pressure (its pascals per unit), placed at the
  // ICAO standard atmosphere's height of the pressure.
  double pascals_per_unit = 0;
  // The frame's representative height (m) per z sample of a terrain-following store
  // (lod::WorldFrameOptions::level_heights_m); empty otherwise.
  std::vector<double> level_heights_m;
  // kVariable: per node (NodeId), the lowest and highest height in metres a vertex of the
  // node can be given: the field's range over the node and every step, joined with the
  // standard atmosphere's range of the node's pressures (the fallback where the field is
  // missing).
  std::vector<std::array<double, 2>> node_heights_m;
  std::string description;  // one line for the log and the panel

  // The vertical extent of every box (world km at `exaggeration`) widened to
  // node_heights_m; nothing for kFrame. On the globe, where up is not z, given
  // `globe_frame_height_km` (the frame's largest |world height| of a level), every side
  // moves out by the node's largest |height| plus that: a vertex moves along its
  // ellipsoid normal from its frame height to its own by at most so much.
  void widen_boxes(std::vector<lod::WorldBox>& boxes, double exaggeration,
                   std::optional<double> globe_frame_height_km = std::nullopt) const;
  // The height in metres of a value of the variable (kVariable).
  double metres(double value) const;
};

// The placement of store `manifest`: kVariable when its vertical axis is a pressure axis,
// choose_vertical_placement finds a geopotential or height variable and `store` (the
// same store, opened on this machine) is given to bound the node boxes; kFrame otherwise,
// with the reason in the description. A store with a geometry field: kVariable by the
// field, with level_heights_m.
// \error kCorrupt naming the file when the store's index cannot be read; kUnsupported for
// a geometry field without `store` (through --connect); as representative_level_heights_m.
HeightPlacement choose_height_placement(const format::Manifest& manifest, const Store* store);

}  // namespace strielad::view
