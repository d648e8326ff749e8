// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_dataset.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_pipeline.h>

#include <array>
#include <chrono>
#include <optional>
#include <vector>

#include "core/error.h"
#include "synthetic/grib_sample_writer.h"
#include "synthetic/sample_atmosphere.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_writer.h"

namespace strielad::synthetic {
namespace {

// Levels in flight: one being written while the others are computed.
constexpr std::size_t kLevelsInFlight = 3;

struct LevelJob {
  std::size_t variable_index = 0;
  std::size_t level = 0;
  std::vector<float>* buffer = nullptr;
};

// Computes and writes every (variable, level) of one step, overlapping the serial
// netCDF writes with the parallel computation of the following levels.
using LevelWrite = std::function<void(std::size_t variable_index, std::size_t t_in_file,
                                      std::size_t level, std::span<const float> values)>;

void write_step(const SampleAtmosphere& atmosphere, std::span<const SampleVariable> variables,
                std::size_t nz, const LevelWrite& write_level, std::size_t t_in_file,
                const std::function<void()>& level_done,
                std::array<std::vector<float>, kLevelsInFlight>& buffers) {
  std::size_t next = 0;
  const std::size_t total = variables.size() * nz;
  tbb::parallel_pipeline(
      kLevelsInFlight,
      tbb::make_filter<void, LevelJob>(
          tbb::filter_mode::serial_in_order,
          [&](tbb::flow_control& fc) {
            if (next == total) {
              fc.stop();
              return LevelJob{};
            }
            // At most kLevelsInFlight jobs live and the last filter is serial in order,
            // so job n reuses the buffer of job n - kLevelsInFlight, which is written.
            LevelJob job{next / nz, next % nz, &buffers[next % kLevelsInFlight]};
            ++next;
            return job;
          }) &
          tbb::make_filter<LevelJob, LevelJob>(tbb::filter_mode::parallel,
                                               [&](LevelJob job) {
                                                 atmosphere.fill_level(
                                                     variables[job.variable_index], job.level,
                                                     *job.buffer);
                                                 return job;
                                               }) &
          tbb::make_filter<LevelJob, void>(tbb::filter_mode::serial_in_order,
                                           [&](LevelJob job) {
                                             write_level(job.variable_index, t_in_file,
                                                         job.level, *job.buffer);
                                             level_done();
                                           }));
}

}  // namespace

void prepare_sample_directory(const std::filesystem::path& dir) {
  if (dir.empty()) throw make_error(ErrorCode::kInvalidArgument, "sample: empty output directory");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    throw make_error(ErrorCode::kIo, "{}: cannot create output directory: {}", dir.string(),
                     ec.message());
  }
  if (!std::filesystem::is_directory(dir, ec)) {
    throw make_error(ErrorCode::kIo, "{}: output path exists and is not a directory",
                     dir.string());
  }
}

SampleResult write_step_files(const SampleSpec& spec, const std::filesystem::path& out_dir,
                              const std::vector<std::string>& names,
                              std::uint64_t levels_per_step, const StepFileWriter& write_file,
                              const SampleProgress& progress) {
  const std::uint64_t total = static_cast<std::uint64_t>(spec.steps) * levels_per_step;
  std::uint64_t done = 0;
  const std::function<void()> level_done = [&] {
    ++done;
    if (progress) progress(done, total);
  };
  const std::size_t steps_per_file = spec.file_per_step ? 1 : spec.steps;
  SampleResult result;
  for (std::size_t f = 0; f < names.size(); ++f) {
    std::vector<double> times(steps_per_file);
    for (std::size_t s = 0; s < steps_per_file; ++s) {
      times[s] = static_cast<double>(f * steps_per_file + s) * spec.step_seconds;
    }
    result.files.push_back(write_file(out_dir / names[f], times, level_done));
    result.bytes += result.files.back().bytes;
  }
  return result;
}

SampleResult write_sample_dataset(const SampleSpec& spec, const std::filesystem::path& out_dir,
                                  SampleProgress progress) {
  const std::vector<SampleVariable> variables = validate_sample_spec(spec);
  prepare_sample_directory(out_dir);

  const SampleGrid grid(spec.dims);
  std::array<std::vector<float>, kLevelsInFlight> buffers;
  for (auto& b : buffers) b.resize(grid.level_size());
  const auto write_file = [&](const std::filesystem::path& path, std::span<const double> times,
                              const std::function<void()>& level_done) {
    SampleFileLayout layout;
    layout.variables = variables;
    layout.seed = spec.seed;
    layout.deflate = spec.deflate;
    layout.times.assign(times.begin(), times.end());
    const auto start = std::chrono::steady_clock::now();
    std::optional<SampleFileWriter> netcdf;
    std::optional<GribSampleFileWriter> grib;
    if (spec.format == SampleFormat::kGrib2) {
      grib.emplace(path, grid,
                   GribSampleLayout{variables, layout.times, spec.grib_bits, spec.grib_levels});
    } else {
      netcdf.emplace(path, grid, layout);
    }
    const LevelWrite write_level = [&](std::size_t v, std::size_t t, std::size_t k,
                                       std::span<const float> values) {
      if (grib) {
        grib->write_level(v, t, k, values);
      } else {
        netcdf->write_level(v, t, k, values);
      }
    };
    for (std::size_t s = 0; s < layout.times.size(); ++s) {
      const SampleAtmosphere atmosphere(grid, spec.seed, layout.times[s]);
      write_step(atmosphere, variables, spec.dims.z, write_level, s, level_done, buffers);
    }
    const auto written = std::chrono::steady_clock::now();
    const std::uint64_t bytes = grib ? grib->commit() : netcdf->commit();
    const auto committed = std::chrono::steady_clock::now();
    spdlog::debug("sample: {}: {} bytes, computed and written in {:.2f} s, committed in {:.2f} s",
                  path.string(), bytes,
                  std::chrono::duration<double>(written - start).count(),
                  std::chrono::duration<double>(committed - written).count());
    return SampleFile{path, bytes};
  };
  return write_step_files(spec, out_dir, sample_file_names(spec),
                          static_cast<std::uint64_t>(variables.size()) * spec.dims.z, write_file,
                          progress);
}

}  // namespace strielad::synthetic
