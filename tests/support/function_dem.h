// SPDX-License-Identifier: Apache-2.0
// An in-memory DEM for the terrain tests: a regular longitude/latitude grid (row 0 in
// the north, like most rasters) whose heights come from a function of lon/lat.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "scenery/dem_source.h"

namespace strielad::testing {

class FunctionDem final : public geo::DemSource {
 public:
  using Height = std::function<float(double lon, double lat)>;
  FunctionDem(std::size_t width, std::size_t height, double lon0, double lon1, double lat0,
              double lat1, Height f)
      : w_(width), h_(height), lon0_(lon0), lon1_(lon1), lat0_(lat0), lat1_(lat1), f_(std::move(f)) {}

  std::size_t width() const override { return w_; }
  std::size_t height() const override { return h_; }
  double lon(double col) const { return lon0_ + (lon1_ - lon0_) * col / double(w_ - 1); }
  double lat(double row) const { return lat1_ - (lat1_ - lat0_) * row / double(h_ - 1); }
  void georeference(std::span<const double> cols, std::span<const double> rows,
                    std::span<geo::LonLat> out) const override {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {lon(cols[i]), lat(rows[i])};
  }
  std::vector<float> read(const geo::DemWindow& w) const override {
    geo::check_dem_window(w, w_, h_, "function DEM");
    ++reads;
    std::vector<float> out(w.cols * w.rows);
    for (std::size_t r = 0; r < w.rows; ++r) {
      for (std::size_t c = 0; c < w.cols; ++c) {
        out[r * w.cols + c] = f_(lon(double(w.col0 + c * w.stride)), lat(double(w.row0 + r * w.stride)));
      }
    }
    return out;
  }
  std::string describe() const override { return "function DEM"; }
  std::string georeferencing() const override { return "longitude/latitude axes"; }
  mutable std::size_t reads = 0;

 private:
  std::size_t w_, h_;
  double lon0_, lon1_, lat0_, lat1_;
  Height f_;
};

}  // namespace strielad::testing
