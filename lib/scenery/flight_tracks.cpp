// SPDX-License-Identifier: Apache-2.0
#include "scenery/flight_tracks.h"

#include <algorithm>
#include <array>
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

constexpr std::array<const char*, 5> kColumnNames = {"id", "time", "lon", "lat", "altitude"};
using Columns = std::array<std::size_t, 5>;  // the field index of each of kColumnNames

Error field_error(const std::filesystem::path& path, std::size_t line, std::size_t column,
                  const std::string& what) {
  return make_error(ErrorCode::kInvalidInput, "{}:{}: column {}: {}", path.string(), line,
                    column, what);
}

Columns header_columns(const std::vector<std::string_view>& header,
                       const std::filesystem::path& path) {
  Columns column{};
  for (std::size_t c = 0; c < kColumnNames.size(); ++c) {
    const auto it = std::find(header.begin(), header.end(), kColumnNames[c]);
    if (it == header.end()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}:1: no column '{}' (the header must name id, time, lon, lat, altitude)",
                       path.string(), kColumnNames[c]);
    }
    column[c] = static_cast<std::size_t>(it - header.begin());
  }
  return column;
}

// The position report in the fields of line `line`.
Report parse_report(const std::vector<std::string_view>& fields, const Columns& column,
                    std::size_t line, const std::filesystem::path& path) {
  Report r{};
  const auto number = [&](std::size_t c) {
    const auto f = fields[column[c]];
    double v = 0;
    const auto res = std::from_chars(f.data(), f.data() + f.size(), v);
    if (res.ec != std::errc() || res.ptr != f.data() + f.size() || !std::isfinite(v)) {
      throw field_error(path, line, column[c] + 1,
                        fmt::format("{} '{}' is not a finite number", kColumnNames[c], f));
    }
    return v;
  };
  r.lon = number(2);
  r.lat = number(3);
  r.altitude = number(4);
  if (r.lat < -90 || r.lat > 90) {
    throw field_error(path, line, column[3] + 1, fmt::format("latitude {} outside [-90, 90]", r.lat));
  }
  try {
    r.julian_day = parse_cf_time_units("seconds since " + std::string(fields[column[1]])).reference_julian_day;
  } catch (const Error&) {
    throw field_error(path, line, column[1] + 1,
                      fmt::format("time '{}' is not an ISO 8601 date-time (YYYY-MM-DDThh:mm:ssZ)",
                                  fields[column[1]]));
  }
  return r;
}

// The reports of one track in time order, in seconds since `earliest` (a Julian day).
void fill_track(FlightTrack& track, std::vector<Report>& rs, double earliest,
                const std::filesystem::path& path) {
  std::stable_sort(rs.begin(), rs.end(), [](const Report& a, const Report& b) { return a.julian_day < b.julian_day; });
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

}  // namespace

FlightTracks load_flight_tracks_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw make_error(std::filesystem::exists(path) ? ErrorCode::kIo : ErrorCode::kNotFound,
                     "{}: cannot open the flight track file", path.string());
  }
  std::string text;
  if (!std::getline(in, text)) throw make_error(ErrorCode::kInvalidInput, "{}: empty file", path.string());
  const auto header = split(text);
  const Columns column = header_columns(header, path);
  const std::size_t needed = *std::max_element(column.begin(), column.end()) + 1;

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
      throw field_error(path, line, fields.size() + 1,
                        fmt::format("{} fields, the header has {}", fields.size(), header.size()));
    }
    const Report r = parse_report(fields, column, line, path);
    const std::string id(fields[column[0]]);
    if (id.empty()) throw field_error(path, line, column[0] + 1, "empty id");
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
    out.tracks[t].id = ids[t];
    fill_track(out.tracks[t], reports[t], earliest, path);
  }
  return out;
}

}  // namespace strielad::geo
