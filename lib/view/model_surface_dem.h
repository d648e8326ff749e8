// SPDX-License-Identifier: Apache-2.0
// The surface of a terrain-following store (the manifest geometry's `surface`, m above
// mean sea level on the store's level-0 x/y grid: Store::horizontal_coordinates) as a
// digital elevation model, so that the viewer's terrain (view/terrain_tiles.h) shows the
// model's own orography when no --terrain is given. Sample (col, row) is grid sample
// (i, j); its longitude/latitude come from the store's axes through the world frame
// (longitude/latitude axes, or a grid mapping through PROJ), on the plane or the globe
// (where the terrain tiles place it as the meshes are placed: ECEF at the exaggeration).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "format/geometry_file_format.h"
#include "format/manifest.h"
#include "lod/world_frame.h"
#include "scenery/dem_source.h"

namespace strielad::view {

class ModelSurfaceDem final : public geo::DemSource {
 public:
  // \error kInvalidArgument when `coordinates` has no surface or its size is not the
  // manifest's x/y grid; kUnsupported when `frame` has no place on the Earth.
  ModelSurfaceDem(const format::Manifest& manifest, const lod::WorldFrame& frame,
                  std::shared_ptr<const format::HorizontalCoordinates> coordinates,
                  std::string store_name);

  std::size_t width() const override { return nx_; }
  std::size_t height() const override { return ny_; }
  using geo::DemSource::georeference;
  void georeference(std::span<const double> cols, std::span<const double> rows,
                    std::span<geo::LonLat> out) const override;
  std::vector<float> read(const geo::DemWindow& window) const override;
  std::string describe() const override;
  std::string georeferencing() const override;

 private:
  lod::WorldFrame frame_;
  std::shared_ptr<const format::HorizontalCoordinates> coordinates_;
  std::vector<double> x_, y_;
  double z0_ = 0;
  std::size_t nx_ = 0, ny_ = 0;
  std::string name_;
};

}  // namespace strielad::view
