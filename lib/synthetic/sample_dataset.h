// SPDX-License-Identifier: Apache-2.0
// The sample-data generator: writes a deterministic CF-NetCDF-4 (or GRIB2) dataset shaped like the
// SciVis 2017 ICON-LEM output (see /work/shared/docs/data.md) at any size up to the
// full 1429 x 1556 x 150 grid. Levels are computed in parallel (oneTBB) and written one
// at a time while the next ones are computed; memory stays bounded by a few levels.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "synthetic/sample_spec.h"

namespace strielad::synthetic {

// Called after each level written, from one thread at a time (not necessarily the
// caller's): done and total count (variable, step, level) triples.
using SampleProgress = std::function<void(std::uint64_t done, std::uint64_t total)>;

// Creates `dir` if missing. kInvalidArgument for an empty path; kIo when it cannot be
// created or is not a directory.
void prepare_sample_directory(const std::filesystem::path& dir);

// Writes one file per name into `out_dir`: file f holds time steps [f n, (f + 1) n) (n = 1
// with spec.file_per_step, else every step), at 0, spec.step_seconds, ... seconds, through
// `write_file`, which calls level_done after each (variable, step, level) written;
// `progress` counts them against `levels_per_step` per step.
using StepFileWriter = std::function<SampleFile(const std::filesystem::path& path,
                                                std::span<const double> times,
                                                const std::function<void()>& level_done)>;
SampleResult write_step_files(const SampleSpec& spec, const std::filesystem::path& out_dir,
                              const std::vector<std::string>& names,
                              std::uint64_t levels_per_step, const StepFileWriter& write_file,
                              const SampleProgress& progress);

// Validates `spec` (kInvalidArgument), creates `out_dir` if missing (kIo when it cannot
// be created or is not a directory) and writes sample_t000.nc ... (file_per_step) or
// sample.nc (.grib2 with SampleFormat::kGrib2), each atomically. Existing files of those
// names are replaced.
SampleResult write_sample_dataset(const SampleSpec& spec, const std::filesystem::path& out_dir,
                                  SampleProgress progress = {});

}  // namespace strielad::synthetic
