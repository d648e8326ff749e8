// SPDX-License-Identifier: Apache-2.0
// A sample shaped like WRF ARW history output (wrfout_d01_<date>), for the tests of a
// WRF reader: the Lambert conformal C grid of wrf_grid.h over the sample terrain, eta
// levels counted from the ground, and the atmosphere of model_atmosphere.h.
//   dims Time (unlimited), DateStrLen (19), west_east, south_north, bottom_top (nx, ny,
//     nz) and west_east_stag, south_north_stag, bottom_top_stag (one more each);
//   Times(Time, DateStrLen) "2013-04-26_12:00:00"; XTIME(Time) minutes since the start;
//   XLAT, XLONG (mass points), XLAT_U, XLONG_U, XLAT_V, XLONG_V (staggered) from PROJ;
//   ZNU, ZNW (eta of the mass and w levels, 1 at the ground to 0 at the top), P_TOP;
//   HGT, COSALPHA, SINALPHA; PHB, PH (base and perturbation geopotential on w levels:
//   (PH + PHB) / 9.81 is the w levels' height, HGT at the bottom); PB, P (base and
//   perturbation pressure), T (potential temperature - 300 K), QVAPOR, QCLOUD on mass
//   levels; U, V (grid-relative, on the staggered points), W (on w levels).
// All data NC_FLOAT with WRF's attributes (FieldType 104, MemoryOrder, description,
// units, stagger, coordinates) and global attributes (MAP_PROJ 1, TRUELAT1/2, DX, DY,
// CEN_LAT, grid dimensions, ...). Classic 64-bit-offset files as WRF writes by default;
// NetCDF-4 chunked by planes when SampleSpec::deflate > 0 (WRF's compressed output).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "synthetic/sample_dataset.h"
#include "synthetic/sample_spec.h"

namespace strielad::synthetic {

inline constexpr double kWrfGravity = 9.81;       // m s-2, WRF's g
inline constexpr double kWrfThetaBase = 300.0;    // K, T = theta - 300
inline constexpr const char* kWrfStartDate = "2013-04-26_12:00:00";

// "YYYY-MM-DD_HH:MM:SS" of `seconds` (rounded to whole seconds) after kWrfStartDate.
std::string wrf_date_string(double seconds);

// The 3-D variables, in file order: U V W PH PHB T P PB QVAPOR QCLOUD.
std::vector<std::string> wrf_sample_variable_names();

// "wrfout_d01_<date of the file's first step>": one file with every step, or one a step
// when spec.file_per_step.
std::vector<std::string> wrf_sample_file_names(const SampleSpec& spec);

// Validates `spec`, creates `out_dir` if missing and writes the files atomically.
// Progress counts (variable, step, mass level) triples.
SampleResult write_wrf_like_dataset(const SampleSpec& spec, const std::filesystem::path& out_dir,
                                    SampleProgress progress = {});

}  // namespace strielad::synthetic
