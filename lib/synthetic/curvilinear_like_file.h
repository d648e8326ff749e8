// SPDX-License-Identifier: Apache-2.0
// A sample on a curvilinear grid placed only by 2-D latitude and longitude, as regional
// climate models on a rotated pole (EURO-CORDEX, COSMO-CLM) are often published after
// their rotated axes were dropped: dims time (unlimited), height (nz), y (ny), x (nx) with
// no coordinate variables for y and x; lat(y, x) and lon(y, x) (double, degrees_north /
// degrees_east) from PROJ's ob_tran for the pole at kCurvilinearPoleLat N,
// kCurvilinearPoleLon E (no grid_mapping, no rlon/rlat in the file); height(height) in m
// above sea level, top to bottom (sample_grid.h); temp, qc, u, v, w on (time, height, y,
// x) with `coordinates = "lon lat"`, from the atmosphere of model_atmosphere.h.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "synthetic/sample_dataset.h"
#include "synthetic/sample_spec.h"

namespace strielad::synthetic {

inline constexpr double kCurvilinearPoleLon = -170.0, kCurvilinearPoleLat = 40.0;
// The rotated longitudes and latitudes (degrees) the grid spans, over Germany.
inline constexpr double kCurvilinearRlonMin = -4.5, kCurvilinearRlonMax = 4.5;
inline constexpr double kCurvilinearRlatMin = -3.0, kCurvilinearRlatMax = 4.0;

// "+proj=ob_tran +o_proj=longlat +o_lat_p=40 +o_lon_p=0 +lon_0=10": rotated (rlon, rlat)
// to geographic longitude and latitude, as cs2cs reads it.
std::string curvilinear_sample_proj_string();

struct CurvilinearSampleGrid {
  std::size_t nx = 0, ny = 0;
  std::vector<double> rlon, rlat;  // the rotated coordinates of columns and rows
  std::vector<double> lon, lat;    // ny x nx, x fastest
};

// \error kUnsupported when PROJ rejects the projection.
CurvilinearSampleGrid curvilinear_sample_grid(std::size_t nx, std::size_t ny);

// "curvilinear.nc", or curvilinear_t000.nc ... when spec.file_per_step.
std::vector<std::string> curvilinear_sample_file_names(const SampleSpec& spec);

// Validates `spec`, creates `out_dir` if missing and writes the files atomically.
SampleResult write_curvilinear_like_dataset(const SampleSpec& spec,
                                            const std::filesystem::path& out_dir,
                                            SampleProgress progress = {});

}  // namespace strielad::synthetic
