// SPDX-License-Identifier: Apache-2.0
// strielad-sample -o DIR [--dims XxYxZ] [--steps N] [--seed S] [--vars a,b,...]
//                 [--single-file] [--step-seconds S] [--deflate L] [--tracks N] [--terrain N]
//                 [--model sample|icon|icon-cf|sigma-pressure|wrf|curvilinear] [--z-mc]
//                 [--format netcdf|grib2] [--grib-bits N] [--grib-levels height|model] [--json]
// Writes the built-in sample: a deterministic synthetic CF-NetCDF-4 dataset (lib/synthetic)
// that strielad-convert converts like model output, with optional flight tracks and a DEM.
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "cli/progress_bar.h"
#include "cli/tool_main.h"
#include "core/error.h"
#include "synthetic/grib_sample_writer.h"
#include "synthetic/model_like_files.h"
#include "synthetic/sample_args.h"
#include "synthetic/sample_dataset.h"
#include "synthetic/sample_terrain.h"
#include "synthetic/sample_tracks.h"

namespace strielad {
namespace {

struct SampleOptions {
  std::string output;
  std::string dims = "1429x1556x150";
  std::string steps = "4";  // parsed by synthetic::parse_unsigned: "-1" must not wrap
  std::string seed = "1";
  std::string vars;  // empty: all variables
  bool single_file = false;
  double step_seconds = 300;
  int deflate = 0;
  std::size_t tracks = 0;  // flight tracks written to sample_tracks.csv (0: none)
  std::size_t terrain = 0;  // samples per axis of sample_terrain.nc (0: none)
  bool json = false;
  std::string model = "sample";  // synthetic::parse_sample_model
  bool z_mc = false;             // --model icon: also z_mc
  std::string format = "netcdf";  // synthetic::parse_sample_format
  int grib_bits = 16;
  std::string grib_levels = "height";  // synthetic::parse_grib_level_kind
};

int run_sample(const SampleOptions& opt) {
  synthetic::SampleSpec spec;
  spec.dims = synthetic::parse_dims(opt.dims);
  spec.steps = static_cast<std::size_t>(synthetic::parse_unsigned(opt.steps, "--steps"));
  spec.seed = synthetic::parse_unsigned(opt.seed, "--seed");
  if (!opt.vars.empty()) spec.variables = synthetic::parse_variable_list(opt.vars);
  spec.file_per_step = !opt.single_file;
  spec.step_seconds = opt.step_seconds;
  spec.deflate = opt.deflate;
  spec.format = synthetic::parse_sample_format(opt.format);
  spec.grib_bits = opt.grib_bits;
  spec.grib_levels = synthetic::parse_grib_level_kind(opt.grib_levels);
  const synthetic::SampleModel model = synthetic::parse_sample_model(opt.model);
  const bool model_like = model != synthetic::SampleModel::kSample;
  if (model_like && spec.format != synthetic::SampleFormat::kNetcdf) {
    throw make_error(ErrorCode::kInvalidArgument, "--format {}: --model {} writes NetCDF only",
                     opt.format, synthetic::sample_model_name(model));
  }
  if (model_like && !opt.vars.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--vars: --model {} writes its own variables ({})",
                     synthetic::sample_model_name(model),
                     fmt::join(synthetic::model_sample_variable_names(model), ","));
  }
  if (opt.z_mc && model != synthetic::SampleModel::kIcon) {
    throw make_error(ErrorCode::kInvalidArgument, "--z-mc: only with --model icon");
  }
  synthetic::validate_sample_spec(spec);  // report bad arguments before touching the disk

  const std::size_t variable_count =
      model_like ? synthetic::model_sample_variable_names(model).size() : spec.variables.size();
  const std::uint64_t levels = static_cast<std::uint64_t>(spec.steps) * variable_count *
                               spec.dims.z;
  spdlog::info("sample: writing {} step(s) of {}x{}x{} ({} variables, seed {}{}) to {}",
               spec.steps, spec.dims.x, spec.dims.y, spec.dims.z, variable_count, spec.seed,
               model_like ? fmt::format(", model {}", synthetic::sample_model_name(model)) : "",
               opt.output);
  const auto start = std::chrono::steady_clock::now();
  synthetic::SampleResult result;
  {
    cli::ProgressBar bar("sample", levels, "levels");
    const auto advance = [&bar](std::uint64_t, std::uint64_t) { bar.advance(); };
    result = model_like ? synthetic::write_model_like_dataset(spec, model, opt.output,
                                                              {.write_z_mc = opt.z_mc}, advance)
                        : synthetic::write_sample_dataset(spec, opt.output, advance);
    bar.finish();
  }
  synthetic::SampleTracksResult tracks;
  if (opt.tracks > 0) {
    synthetic::SampleTrackSpec track_spec;
    track_spec.tracks = opt.tracks;
    track_spec.span_seconds = std::max(1.0, static_cast<double>(spec.steps) * spec.step_seconds);
    track_spec.seed = spec.seed;
    const auto track_path = std::filesystem::path(opt.output) / "sample_tracks.csv";
    tracks = synthetic::write_sample_tracks(track_spec, track_path);
    spdlog::info("sample: wrote {} flight tracks ({} reports) to {}", tracks.tracks,
                 tracks.reports, track_path.string());
  }
  synthetic::SampleTerrainResult terrain;
  if (opt.terrain > 0) {
    const auto terrain_path = std::filesystem::path(opt.output) / "sample_terrain.nc";
    terrain = synthetic::write_sample_terrain({.samples = opt.terrain, .seed = spec.seed}, terrain_path);
    spdlog::info("sample: wrote a {} x {} rotated-pole DEM (up to {:.0f} m) to {}", terrain.width,
                 terrain.height, terrain.max_height_m, terrain_path.string());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double values = static_cast<double>(levels) * static_cast<double>(spec.dims.x) *
                        static_cast<double>(spec.dims.y);
  spdlog::info("sample: wrote {} file(s), {:.3f} GiB in {:.2f} s ({:.1f} Mvalues/s, {:.0f} MiB/s)",
               result.files.size(), static_cast<double>(result.bytes) / (1024.0 * 1024 * 1024),
               seconds, values / seconds / 1e6,
               static_cast<double>(result.bytes) / (1024.0 * 1024) / seconds);

  if (opt.json) {
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : result.files) files.push_back(f.path.string());
    const nlohmann::json out = {
        {"files", files},
        {"bytes", result.bytes},
        {"dims", {spec.dims.x, spec.dims.y, spec.dims.z}},
        {"steps", spec.steps},
        {"model", synthetic::sample_model_name(model)},
        {"seconds", seconds},
        {"tracks", tracks.tracks},
        {"terrain_samples", terrain.width * terrain.height},
    };
    std::cout << out.dump() << std::endl;
  }
  return 0;
}

void register_sample(CLI::App& app, cli::Action& action) {
  auto opt = std::make_shared<SampleOptions>();
  auto* sub = &app;
  sub->add_option("-o,--output", opt->output, "Output directory (created if missing)")
      ->required();
  sub->add_option("--dims", opt->dims, "Grid size XxYxZ (lon x lat x height)")
      ->type_name("XxYxZ")
      ->capture_default_str();
  sub->add_option("--steps", opt->steps, "Number of time steps")
      ->type_name("UINT")
      ->capture_default_str();
  sub->add_option("--seed", opt->seed, "Seed of the synthetic weather (0 .. 2^64-1)")
      ->type_name("UINT")
      ->capture_default_str();
  sub->add_option("--vars", opt->vars,
                  "Comma-separated variables (default all: clw,cli,qr,ta,pres,ua,va,wa)");
  sub->add_flag("--single-file", opt->single_file,
                "Write all steps into sample.nc instead of one file per step");
  sub->add_option("--step-seconds", opt->step_seconds, "Seconds between time steps")
      ->capture_default_str();
  sub->add_option("--deflate", opt->deflate, "Deflate level 0-9 (with shuffle; 0: none)")
      ->capture_default_str();
  sub->add_option("--tracks", opt->tracks,
                  "Also write N synthetic flight tracks over the domain to sample_tracks.csv "
                  "(strielad-view --tracks)")
      ->capture_default_str();
  sub->add_option("--terrain", opt->terrain,
                  "Also write an N x N rotated-pole DEM under the domain to sample_terrain.nc "
                  "(strielad-view --terrain; 0: none)")
      ->capture_default_str();
  sub->add_option("--model", opt->model,
                  "What the files look like: sample (constant-height levels), icon (ICON-LEM "
                  "remapped: z_ifc, topography_c), icon-cf (CF hybrid height), sigma-pressure "
                  "(IFS/CAM hybrid sigma-pressure), wrf (WRF ARW wrfout_d01_<date>: Lambert conformal "
                  "C grid, eta levels, PH/PHB, U/V/W, T, P/PB, QVAPOR, QCLOUD), curvilinear "
                  "(a rotated-pole grid written only as 2-D lat/lon, on height levels)")
      ->capture_default_str();
  sub->add_flag("--z-mc", opt->z_mc,
                "With --model icon: also write z_mc, the full levels' heights");
  sub->add_option("--format", opt->format,
                  "File format: netcdf (CF-NetCDF-4) or grib2 (one message per variable and "
                  "level on a regular_ll grid, heightAboveSea levels)")
      ->capture_default_str();
  sub->add_option("--grib-bits", opt->grib_bits,
                  "GRIB2: bits per value of grid_simple packing (1..32); 0: IEEE float32")
      ->capture_default_str();
  sub->add_option("--grib-levels", opt->grib_levels,
                  "GRIB2: height (heightAboveSea, m) or model (hybrid level numbers, 1 = top; "
                  "what grib_to_netcdf can convert)")
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "Print a JSON summary on stdout");
  sub->callback([&action, opt] { action = [opt] { return run_sample(*opt); }; });
}

}  // namespace
}  // namespace strielad

int main(int argc, char** argv) {
  using namespace strielad;
  const cli::ToolSpec spec{
      "strielad-sample",
      "Write the built-in sample: a deterministic synthetic CF-NetCDF-4 dataset (clouds, "
      "rain, temperature, pressure, wind), optionally with flight tracks and a DEM",
      register_sample};
  return cli::run_tool(spec, argc, argv);
}
