// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_tracks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "core/file_io.h"
#include "synthetic/hash_noise.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

constexpr double kEarthRadiusM = 6371008.8;
constexpr double kDeg = std::numbers::pi / 180.0;

// "2013-04-26T12:00:00Z" plus `seconds` (the sample's reference time, sample_writer.h).
std::string iso_time(double seconds) {
  const long total = std::lround(seconds) + 12 * 3600;  // within 2013-04-25 .. 04-27
  const long day = 26 + (total >= 0 ? total / 86400 : (total - 86399) / 86400);
  const long in_day = total - (day - 26) * 86400;
  return fmt::format("2013-04-{:02}T{:02}:{:02}:{:02}Z", day, in_day / 3600, in_day / 60 % 60,
                     in_day % 60);
}

}  // namespace

SampleTracksResult write_sample_tracks(const SampleTrackSpec& spec, const std::filesystem::path& path) {
  if (spec.tracks == 0 || spec.tracks > 10'000'000) {
    throw make_error(ErrorCode::kInvalidArgument, "--tracks {}: need 1 .. 10000000", spec.tracks);
  }
  if (!(spec.span_seconds > 0) || !std::isfinite(spec.span_seconds) ||
      !(spec.report_seconds > 0) || !std::isfinite(spec.report_seconds)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample tracks: span {} s and report interval {} s must be finite and > 0",
                     spec.span_seconds, spec.report_seconds);
  }
  std::string csv = "id,time,lon,lat,altitude\n";
  SampleTracksResult result;
  const double lat_mid = 0.5 * (kLatMin + kLatMax);
  for (std::size_t t = 0; t < spec.tracks; ++t) {
    const auto u = [&](int k) { return unit_hash(spec.seed * 7919 + static_cast<std::uint64_t>(k), t); };
    // A line through a point of the domain, in a random direction, long enough to cross it.
    const double lon0 = kLonMin + (kLonMax - kLonMin) * u(1);
    const double lat0 = kLatMin + (kLatMax - kLatMin) * u(2);
    const double heading = 2 * std::numbers::pi * u(3);
    const double speed = 200 + 50 * u(4);
    // Every aircraft is in the air during the whole span (the benchmarked scene: 27,000
    // tracks on screen at once), taking off up to its duration before the span ends.
    const double duration = std::max(1200 + 1800 * u(6), spec.span_seconds + 600);
    const double start = (spec.span_seconds - duration) * u(5);  // take-off, <= 0
    const int kind = static_cast<int>(u(7) * 10);  // 0-1 climbing, 2-3 descending, else cruise
    const double cruise = 9000 + 3500 * u(8);
    const double east = std::sin(heading) * speed, north = std::cos(heading) * speed;
    const std::string id = fmt::format("S{:05}", t);
    for (double s = 0; s <= duration; s += spec.report_seconds) {
      const double d = s - duration / 2;  // the track is centred on (lon0, lat0)
      const double lat = lat0 + north * d / kEarthRadiusM / kDeg;
      const double lon = lon0 + east * d / (kEarthRadiusM * std::cos(lat_mid * kDeg)) / kDeg;
      const double f = s / duration;
      const double altitude = kind < 2 ? cruise * std::min(1.0, 2.5 * f)
                              : kind < 4 ? cruise * std::min(1.0, 2.5 * (1 - f))
                                         : cruise;
      csv += fmt::format("{},{},{:.5f},{:.5f},{:.0f}\n", id, iso_time(start + s), lon, lat, altitude);
      ++result.reports;
    }
    ++result.tracks;
  }
  write_file_atomically(path, std::as_bytes(std::span(csv.data(), csv.size())));
  result.bytes = csv.size();
  return result;
}

}  // namespace strielad::synthetic
