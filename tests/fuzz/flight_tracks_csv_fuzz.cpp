// SPDX-License-Identifier: Apache-2.0
// Fuzzes the CSV flight-track reader (scenery/flight_tracks.h, load_flight_tracks_csv) on
// the input written to a file: it must reject with strielad::Error or return tracks
// that keep the reader's promises (sorted times, latitudes in range, consistent sizes).
#include <string>

#include "core/error.h"
#include "fuzz/flight_tracks_checks.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;

namespace {

std::vector<std::uint8_t> text(const std::string& s) { return {s.begin(), s.end()}; }

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {text("callsign,altitude,lat,lon,time,id\r\n"
               "x,10000,50.5,8.0,2013-04-26T12:01:00Z,DLH1\r\n"
               "x,11000,51.0,9.0,2013-04-26T12:00:00Z,BAW2\r\n"
               "x,10500,50.0,7.0,2013-04-26T12:00:00Z,DLH1\n"
               "\n"
               "x,11000,51.2,9.5,2013-04-26T13:00:30+01:00,BAW2\n"),
          text("id,time,lon,lat,altitude\n"
               "A,2000-02-29T23:59:59Z,-179.5,-89.9,0\n"
               "A,2000-03-01T00:00:00-05:30,179.5,89.9,12000.25\n"
               "B,1999-12-31T23:00:00Z,0,0,-30\n")};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fuzz::check_flight_tracks(geo::load_flight_tracks_csv(fuzz::input_file(data, size, ".csv")));
  } catch (const Error&) {
  }
  return 0;
}
