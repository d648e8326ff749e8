// SPDX-License-Identifier: Apache-2.0
// load_flight_tracks_netcdf (flight_tracks.h): CF discrete sampling geometry files of
// featureType "trajectory" (CF 1.6+, section 9), in the two layouts flight data comes
// in: the multidimensional array (variables over (trajectory, obs), shorter tracks
// padded with _FillValue) and the contiguous ragged array (variables over one sample
// dimension, a `row_size` variable with sample_dimension giving each track's length).
#include <netcdf.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>

#include "core/error.h"
#include "geo/cf_time.h"
#include "scenery/flight_tracks.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"

namespace strielad::geo {
namespace {

struct Found {
  int varid = -1;
  std::string name;
};

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A variable by standard_name, else by one of `names`.
Found find_variable(int ncid, const std::string& standard_name,
                    std::initializer_list<const char*> names) {
  const int n = ingest::variable_count(ncid);
  for (int v = 0; v < n; ++v) {
    if (lower(ingest::text_attribute_or_empty(ncid, v, "standard_name")) == standard_name) {
      return {v, ingest::variable_name(ncid, v)};
    }
  }
  for (int v = 0; v < n; ++v) {
    const std::string name = lower(ingest::variable_name(ncid, v));
    for (const char* candidate : names) {
      if (name == candidate) return {v, ingest::variable_name(ncid, v)};
    }
  }
  return {};
}

// Values as double with _FillValue / missing_value as NaN.
std::vector<double> read_values(int ncid, int varid, const std::string& context) {
  std::vector<double> values = ingest::read_all_as_double(ncid, varid, context);
  for (const char* fill_name : {"_FillValue", "missing_value"}) {
    const auto fill = ingest::numeric_attribute(ncid, varid, fill_name);
    if (fill.empty()) continue;
    const double f = static_cast<double>(fill[0]);
    for (auto& v : values) {
      if (v == f || (std::isfinite(f) && std::fabs(f) > 1e30 && std::fabs(v - f) <= 1e-6 * std::fabs(f))) {
        v = NAN;
      }
    }
  }
  return values;
}

// Metres per unit of an altitude variable.
double metres_per_unit(const std::string& units, const std::string& context) {
  const std::string u = lower(units);
  if (u == "m" || u == "meter" || u == "meters" || u == "metre" || u == "metres" || u.empty()) return 1.0;
  if (u == "km" || u == "kilometer" || u == "kilometers" || u == "kilometre") return 1000.0;
  if (u == "ft" || u == "feet" || u == "foot") return 0.3048;
  throw make_error(ErrorCode::kUnsupported, "{}: altitude units '{}': expected m, km or ft", context, units);
}

// Track ids: a variable with cf_role trajectory_id (numbers or text), else the index.
std::vector<std::string> track_ids(int ncid, std::size_t count, const std::string& path) {
  std::vector<std::string> ids(count);
  for (std::size_t t = 0; t < count; ++t) ids[t] = std::to_string(t);
  const int n = ingest::variable_count(ncid);
  for (int v = 0; v < n; ++v) {
    if (ingest::text_attribute_or_empty(ncid, v, "cf_role") != "trajectory_id") continue;
    const int type = ingest::variable_type(ncid, v);
    const auto dims = ingest::variable_dimids(ncid, v);
    if (ingest::is_numeric_type(type) && dims.size() == 1 && ingest::dimension_length(ncid, dims[0]) == count) {
      const auto values = ingest::read_all_as_double(ncid, v, path);
      for (std::size_t t = 0; t < count; ++t) ids[t] = fmt::format("{}", values[t]);
    } else if (type == NC_CHAR && dims.size() == 2 && ingest::dimension_length(ncid, dims[0]) == count) {
      const std::size_t width = ingest::dimension_length(ncid, dims[1]);
      std::string text(count * width, '\0');
      ingest::nc_check(nc_get_var_text(ncid, v, text.data()), path);
      for (std::size_t t = 0; t < count; ++t) {
        std::string id = text.substr(t * width, width);
        id.erase(std::find(id.begin(), id.end(), '\0'), id.end());
        while (!id.empty() && id.back() == ' ') id.pop_back();
        ids[t] = id;
      }
    } else if (type == NC_STRING && dims.size() == 1 && ingest::dimension_length(ncid, dims[0]) == count) {
      std::vector<char*> strings(count, nullptr);
      ingest::nc_check(nc_get_var_string(ncid, v, strings.data()), path);
      for (std::size_t t = 0; t < count; ++t) ids[t] = strings[t] ? strings[t] : "";
      nc_free_string(count, strings.data());
    }
    break;
  }
  return ids;
}

struct TrajectoryVariables {
  Found time, lon, lat, alt;
};

TrajectoryVariables find_trajectory_variables(int ncid, const std::string& p) {
  const TrajectoryVariables v{find_variable(ncid, "time", {"time"}),
                              find_variable(ncid, "longitude", {"lon", "longitude"}),
                              find_variable(ncid, "latitude", {"lat", "latitude"}),
                              find_variable(ncid, "altitude", {"alt", "altitude", "height"})};
  for (const auto& [found, what] : {std::pair{v.time, "time"}, std::pair{v.lon, "longitude"},
                                    std::pair{v.lat, "latitude"}, std::pair{v.alt, "altitude"}}) {
    if (found.varid < 0) {
      throw make_error(ErrorCode::kInvalidInput, "{}: no {} variable (by standard_name or name)", p, what);
    }
  }
  return v;
}

// Where each track's reports are (first, count): rows of a (trajectory, obs) array, or
// runs given by a row_size variable (contiguous ragged array).
std::vector<std::pair<std::size_t, std::size_t>> track_runs(int ncid, const Found& time,
                                                            std::size_t samples,
                                                            const std::string& p) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  const auto dims = ingest::variable_dimids(ncid, time.varid);
  if (dims.size() == 2) {
    const std::size_t tracks = ingest::dimension_length(ncid, dims[0]);
    const std::size_t obs = ingest::dimension_length(ncid, dims[1]);
    for (std::size_t i = 0; i < tracks; ++i) runs.emplace_back(i * obs, obs);
  } else if (dims.size() == 1) {
    int row_size = -1;
    const int n = ingest::variable_count(ncid);
    for (int v = 0; v < n && row_size < 0; ++v) {
      if (ingest::has_attribute(ncid, v, "sample_dimension")) row_size = v;
    }
    if (row_size < 0) {
      runs.emplace_back(0, samples);  // a single trajectory
    } else {
      const auto sizes = ingest::read_all_as_double(ncid, row_size, p + ": row_size");
      std::size_t first = 0;
      for (const double s : sizes) {
        if (!(s >= 0) || first + static_cast<std::size_t>(s) > samples) {
          throw make_error(ErrorCode::kInvalidInput,
                           "{}: {}: row sizes add up to more than the {} samples", p,
                           ingest::variable_name(ncid, row_size), samples);
        }
        runs.emplace_back(first, static_cast<std::size_t>(s));
        first += static_cast<std::size_t>(s);
      }
    }
  } else {
    throw make_error(ErrorCode::kInvalidInput, "{}: {} has {} dimensions: expected (trajectory, obs) "
                     "or one sample dimension", p, time.name, dims.size());
  }
  return runs;
}

// Every position report: time (in the file's units), longitude, latitude, altitude (in
// the file's units), NaN where missing.
struct Reports {
  std::vector<double> t, x, y, z;
};

// Track `id`: the complete reports of one run, sorted by time, in seconds since
// `earliest` (a Julian day) and metres (`to_m` per altitude unit); nothing when the run
// has no complete report.
std::optional<FlightTrack> track_of_run(const Reports& r, std::pair<std::size_t, std::size_t> run,
                                        const std::string& id, const CfTimeUnits& units,
                                        double earliest, double to_m, const std::string& lat_name,
                                        const std::string& p) {
  std::vector<std::size_t> order;
  for (std::size_t i = run.first; i < run.first + run.second; ++i) {
    if (std::isfinite(r.t[i]) && std::isfinite(r.x[i]) && std::isfinite(r.y[i]) && std::isfinite(r.z[i])) {
      if (r.y[i] < -90 || r.y[i] > 90) {
        throw make_error(ErrorCode::kInvalidInput, "{}: {}[{}]: latitude {} outside [-90, 90]", p, lat_name, i, r.y[i]);
      }
      order.push_back(i);
    }
  }
  if (order.empty()) return std::nullopt;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return r.t[a] < r.t[b]; });
  FlightTrack track;
  track.id = id;
  for (const std::size_t i : order) {
    const double s = (units.julian_day(r.t[i]) - earliest) * 86400.0;
    if (!track.seconds.empty() && !(s > track.seconds.back())) {
      throw make_error(ErrorCode::kInvalidInput, "{}: track '{}' has two reports at the same time", p, track.id);
    }
    track.seconds.push_back(s);
    track.lon.push_back(r.x[i]);
    track.lat.push_back(r.y[i]);
    track.altitude_m.push_back(r.z[i] * to_m);
  }
  return track;
}

}  // namespace

FlightTracks load_flight_tracks_netcdf(const std::filesystem::path& path) {
  std::lock_guard lock(ingest::netcdf_mutex());
  const ingest::NcFile file(path);
  const int ncid = file.id();
  const std::string p = path.string();
  const auto feature = lower(ingest::text_attribute_or_empty(ncid, NC_GLOBAL, "featureType"));
  if (feature != "trajectory") {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: featureType '{}': flight tracks must be a CF trajectory file "
                     "(featureType = \"trajectory\")", p, feature);
  }
  const auto [time, lon, lat, alt] = find_trajectory_variables(ncid, p);
  const auto units = parse_cf_time_units(ingest::text_attribute_or_empty(ncid, time.varid, "units"),
                                         ingest::text_attribute_or_empty(ncid, time.varid, "calendar"));
  const double to_m = metres_per_unit(ingest::text_attribute_or_empty(ncid, alt.varid, "units"),
                                      p + ": " + alt.name);
  Reports r;
  r.t = read_values(ncid, time.varid, p + ": " + time.name);
  r.x = read_values(ncid, lon.varid, p + ": " + lon.name);
  r.y = read_values(ncid, lat.varid, p + ": " + lat.name);
  r.z = read_values(ncid, alt.varid, p + ": " + alt.name);
  if (r.x.size() != r.t.size() || r.y.size() != r.t.size() || r.z.size() != r.t.size()) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: {}, {}, {} and {} do not have the same shape", p, time.name, lon.name,
                     lat.name, alt.name);
  }
  const auto runs = track_runs(ncid, time, r.t.size(), p);
  const auto ids = track_ids(ncid, runs.size(), p);
  FlightTracks out;
  double earliest = INFINITY;
  for (const double v : r.t) {
    if (std::isfinite(v)) earliest = std::min(earliest, units.julian_day(v));
  }
  if (!std::isfinite(earliest)) throw make_error(ErrorCode::kInvalidInput, "{}: no position reports", p);
  out.reference_julian_day = earliest;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    auto track = track_of_run(r, runs[i], ids[i], units, earliest, to_m, lat.name, p);
    if (!track) continue;
    out.reports += track->size();
    out.tracks.push_back(std::move(*track));
  }
  return out;
}

FlightTracks load_flight_tracks(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".nc" || ext == ".nc4" || ext == ".netcdf" || ext == ".cdf") {
    return load_flight_tracks_netcdf(path);
  }
  return load_flight_tracks_csv(path);
}

}  // namespace strielad::geo
