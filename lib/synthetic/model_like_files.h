// SPDX-License-Identifier: Apache-2.0
// Samples shaped like real model output on terrain-following levels over the sample
// terrain (sample_terrain.h), for the tests and demos of terrain-following input:
//   icon: as ICON-LEM writes after remapping to a regular lon/lat grid: dims time,
//     height (nz full levels), height_2 (nz + 1 half levels), lat, lon; height and
//     height_2 are level indices 1.. counted from the top; z_ifc(height_2, lat, lon) the
//     half levels' heights above sea level (SLEVE-like hybrid height, model_levels.h),
//     topography_c(lat, lon); temp, qc, u, v, w on (time, height, lat, lon); time in
//     ICON's absolute "day as %Y%m%d.%f". z_mc (full levels' heights) only when asked;
//   icon-cf: the same fields with the CF atmosphere_hybrid_height_coordinate lev
//     (a: lev, b: b, orog: orog) and time in seconds;
//   sigma-pressure: IFS/CAM-like hybrid sigma-pressure levels lev (ap: hyam, b: hybm,
//     ps: ps), top to bottom, ps(time, lat, lon), orog, and t, q, u, v;
//   wrf: WRF ARW history files wrfout_d01_<date> on a Lambert conformal C grid
//     (wrf_like_file.h);
//   curvilinear: a rotated-pole grid written only as 2-D lat/lon, on height levels
//     (curvilinear_like_file.h).
// The grid, steps, seed, step length, file split and deflate level come from SampleSpec
// (its variable list is not used: each model writes its own variables).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "synthetic/sample_dataset.h"
#include "synthetic/sample_spec.h"

namespace strielad::synthetic {

enum class SampleModel { kSample, kIcon, kIconCf, kSigmaPressure, kWrf, kCurvilinear };

// "sample" (the default sample_dataset.h writes), "icon", "icon-cf", "sigma-pressure",
// "wrf", "curvilinear".
std::string_view sample_model_name(SampleModel model) noexcept;

// The 3-D variables a model writes, in file order (kInvalidArgument for kSample).
std::vector<std::string> model_sample_variable_names(SampleModel model);

struct ModelSampleOptions {
  bool write_z_mc = false;  // icon: also z_mc(height, lat, lon), the full levels' heights
};

// File names of a model-like sample: "<prefix>_t000.nc", ... or "<prefix>.nc" with
// the prefix icon, icon_cf, sigma_pressure or curvilinear; wrf_sample_file_names for kWrf.
// kInvalidArgument for kSample.
std::vector<std::string> model_sample_file_names(const SampleSpec& spec, SampleModel model);

// Validates `spec` (validate_sample_spec), creates `out_dir` if missing and writes the
// files of `model` atomically, replacing files of those names. kInvalidArgument for
// kSample (write_sample_dataset writes that), kIo when a file cannot be written.
// Progress counts (variable, step, level) triples.
SampleResult write_model_like_dataset(const SampleSpec& spec, SampleModel model,
                                      const std::filesystem::path& out_dir,
                                      const ModelSampleOptions& options = {},
                                      SampleProgress progress = {});

}  // namespace strielad::synthetic
