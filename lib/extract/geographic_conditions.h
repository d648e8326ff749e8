// SPDX-License-Identifier: Apache-2.0
// A geographic box (longitude and latitude ranges) on a grid placed by a grid mapping or
// by 2-D coordinates (curvilinear),
// as per-sample conditions of the extraction kernel (formats/scene.md, "Geographic
// boxes"): the region ends where the conditions' trilinear interpolants cross zero,
// exactly at the samples and within the interpolation's error between them, and its mesh
// keeps every guarantee of a domain box (closed, outward, crack-free).
//
// The conditions, in degrees of latitude or in radians scaled as noted:
// - latitude: lat - lo and hi - lat;
// - a longitude range up to half a turn wide: cos(lat) sin(lon - lo) and
//   cos(lat) sin(hi - lon), the half-spaces of the two meridian planes: continuous
//   across the antimeridian and through the poles;
// - a range from half a turn to a full turn: cos(lon - c) - cos(w / 2), c its centre
//   and w its width (continuous everywhere but at the poles).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "format/manifest.h"
#include "store/store.h"
#include "scene/scene.h"

namespace strielad {

// True longitude and latitude (degrees) of every level-0 horizontal sample of a store
// whose grid is placed by a grid mapping, computed once per store and kept while used.
class GeoLocation {
 public:
  // \error kUnsupported when the store's grid has no grid mapping with a pipeline.
  static std::shared_ptr<const GeoLocation> of(const format::Manifest& manifest);
  // Either grid: a curvilinear store's columns from its GEOMETRY file, as stored; else as
  // of(manifest).
  // \error kUnsupported as of(manifest); kCorrupt and others as Store::horizontal_coordinates.
  static std::shared_ptr<const GeoLocation> of(const Store& store);

  const std::array<double, 2>& at(std::size_t i, std::size_t j) const { return lonlat_[j * nx_ + i]; }
  std::size_t nx() const { return nx_; }

 private:
  std::size_t nx_ = 0;
  std::vector<std::array<double, 2>> lonlat_;
};

// The conditions of `box` at the horizontal samples (fine indices `xi` x `yi`, x fastest):
// one vector of xi.size() * yi.size() values per condition, inside where >= 0.
std::vector<std::vector<double>> geographic_conditions(const GeographicBox& box,
                                                       const GeoLocation& geo,
                                                       const std::vector<std::size_t>& xi,
                                                       const std::vector<std::size_t>& yi);

}  // namespace strielad
