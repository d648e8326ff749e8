// SPDX-License-Identifier: Apache-2.0
#include "scenery/flight_tracks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numeric>
#include <unordered_map>

#include <fmt/format.h>

#include "core/error.h"
#include "geo/cf_time.h"

namespace strielad::geo {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    std::string_view f = line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
    while (!f.empty() && (f.back() == ' ' || f.back() == '\t' || f.back() == '\r')) f.remove_suffix(1);
    fields.push_back(f);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

struct Report {
  double julian_day, lon, lat, altitude;
};

}  // namespace

FlightTracks load_flight_tracks_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw make_error(std::filesystem::exists(path) ? ErrorCode::kIo : ErrorCode::kNotFound,
                     "{}: cannot open the flight track file", path.string());
  }
  const auto fail = [&](std::size_t line, std::size_t column, const std::string& what) {
    return make_error(ErrorCode::kInvalidInput, "{}:{}: column {}: {}", path.string(), line,
                      column, what);
  };
  std::string text;
  if (!std::getline(in, text)) throw make_error(ErrorCode::kInvalidInput, "{}: empty file", path.string());
  const auto header = split(text);
  const char* names[5] = {"id", "time", "lon", "lat", "altitude"};
  std::size_t column[5];
  for (int c = 0; c < 5; ++c) {
    const auto it = std::find(header.begin(), header.end(), names[c]);
    if (it == header.end()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}:1: no column '{}' (the header must name id, time, lon, lat, altitude)",
                       path.string(), names[c]);
    }
    column[c] = static_cast<std::size_t>(it - header.begin());
  }
  const std::size_t needed = *std::max_element(column, column + 5) + 1;

  std::unordered_map<std::string, std::size_t> index_of;
  std::vector<std::string> ids;
  std::vector<std::vector<Report>> reports;
  std::size_t line = 1;
  double earliest = INFINITY;
  std::size_t count = 0;
  while (std::getline(in, text)) {
    ++line;
    if (text.empty() || text == "\r") continue;
    const auto fields = split(text);
    if (fields.size() < needed) {
      throw fail(line, fields.size() + 1, fmt::format("{} fields, the header has {}", fields.size(), header.size()));
    }
    Report r{};
    const auto number = [&](int c) {
      const auto f = fields[column[c]];
      double v = 0;
      const auto res = std::from_chars(f.data(), f.data() + f.size(), v);
      if (res.ec != std::errc() || res.ptr != f.data() + f.size() || !std::isfinite(v)) {
        throw fail(line, column[c] + 1, fmt::format("{} '{}' is not a finite number", names[c], f));
      }
      return v;
    };
    r.lon = number(2);
    r.lat = number(3);
    r.altitude = number(4);
    if (r.lat < -90 || r.lat > 90) throw fail(line, column[3] + 1, fmt::format("latitude {} outside [-90, 90]", r.lat));
    try {
      r.julian_day = parse_cf_time_units("seconds since " + std::string(fields[column[1]])).reference_julian_day;
    } catch (const Error&) {
      throw fail(line, column[1] + 1,
                 fmt::format("time '{}' is not an ISO 8601 date-time (YYYY-MM-DDThh:mm:ssZ)", fields[column[1]]));
    }
    const std::string id(fields[column[0]]);
    if (id.empty()) throw fail(line, column[0] + 1, "empty id");
    auto [it, added] = index_of.try_emplace(id, ids.size());
    if (added) {
      ids.push_back(id);
      reports.emplace_back();
    }
    reports[it->second].push_back(r);
    earliest = std::min(earliest, r.julian_day);
    ++count;
  }
  if (count == 0) throw make_error(ErrorCode::kInvalidInput, "{}: no position reports", path.string());

  FlightTracks out;
  out.reference_julian_day = earliest;
  out.reports = count;
  out.tracks.resize(ids.size());
  for (std::size_t t = 0; t < ids.size(); ++t) {
    auto& rs = reports[t];
    std::stable_sort(rs.begin(), rs.end(), [](const Report& a, const Report& b) { return a.julian_day < b.julian_day; });
    FlightTrack& track = out.tracks[t];
    track.id = ids[t];
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const double s = (rs[i].julian_day - earliest) * 86400.0;
      if (i > 0 && !(s > track.seconds.back())) {
        throw make_error(ErrorCode::kInvalidInput, "{}: track '{}' has two reports at the same time",
                         path.string(), track.id);
      }
      track.seconds.push_back(s);
      track.lon.push_back(rs[i].lon);
      track.lat.push_back(rs[i].lat);
      track.altitude_m.push_back(rs[i].altitude);
    }
  }
  return out;
}

}  // namespace strielad::geo
