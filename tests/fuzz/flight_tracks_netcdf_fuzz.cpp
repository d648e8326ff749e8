// SPDX-License-Identifier: Apache-2.0
// Fuzzes the CF trajectory reader (scenery/flight_tracks.h, load_flight_tracks_netcdf) on
// the input written to a file: it must reject with strielad::Error or return tracks
// that keep the reader's promises. Seeds are classic-format (CDF-2) files in both CF
// layouts; netCDF-C parses the container, so this mostly exercises what the reader does
// with the dimensions, attributes and values a damaged file declares.
#include "core/error.h"
#include "fuzz/flight_tracks_checks.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"
#include "support/netcdf_fixture.h"

using namespace strielad;
using strielad::testing::NcAttr;
using strielad::testing::NetcdfFixture;

namespace {

const double kFill = -999;

NetcdfFixture with_variables(NetcdfFixture f, const std::vector<std::string>& dims,
                             std::vector<double> time, std::vector<double> lon,
                             std::vector<double> lat, std::vector<double> alt,
                             const char* alt_units) {
  const auto fill = NcAttr::number("_FillValue", NC_DOUBLE, {kFill});
  return f.global_attribute(NcAttr::text_value("featureType", "trajectory"))
      .variable("time", NC_DOUBLE, dims, std::move(time),
                {NcAttr::text_value("standard_name", "time"),
                 NcAttr::text_value("units", "seconds since 2013-04-26 12:00:00"), fill})
      .variable("lon", NC_DOUBLE, dims, std::move(lon),
                {NcAttr::text_value("standard_name", "longitude"), fill})
      .variable("lat", NC_DOUBLE, dims, std::move(lat),
                {NcAttr::text_value("standard_name", "latitude"), fill})
      .variable("alt", NC_DOUBLE, dims, std::move(alt),
                {NcAttr::text_value("standard_name", "altitude"),
                 NcAttr::text_value("units", alt_units), fill});
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  const auto multidimensional = [](const std::filesystem::path& path) {
    NetcdfFixture f(NC_64BIT_OFFSET);
    f.dimension("trajectory", 2).dimension("obs", 3);
    f.variable("flight", NC_INT, {"trajectory"}, {4711, 815},
               {NcAttr::text_value("cf_role", "trajectory_id")});
    with_variables(f, {"trajectory", "obs"}, {60, 0, 120, 30, 90, kFill}, {6, 5, 7, 10, 11, kFill},
                   {50, 49, 51, 52, 53, kFill}, {10, 9.5, 10.5, 3, 4, kFill}, "km")
        .write(path);
  };
  const auto ragged = [](const std::filesystem::path& path) {
    NetcdfFixture f(NC_64BIT_OFFSET);
    f.dimension("trajectory", 2).dimension("obs", 5);
    f.variable("row_size", NC_INT, {"trajectory"}, {2, 3},
               {NcAttr::text_value("sample_dimension", "obs")});
    with_variables(f, {"obs"}, {0, 60, 10, 20, 30}, {5, 6, 9, 9.1, 9.2}, {48, 49, 50, 50, 50},
                   {1000, 2000, 3000, 3000, 3000}, "ft")
        .write(path);
  };
  return {fuzz::bytes_written_by(".nc", multidimensional), fuzz::bytes_written_by(".nc", ragged)};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fuzz::check_flight_tracks(geo::load_flight_tracks_netcdf(fuzz::input_file(data, size, ".nc")));
  } catch (const Error&) {
  }
  return 0;
}
