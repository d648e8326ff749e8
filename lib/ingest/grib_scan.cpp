// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_scan.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "core/error.h"
#include "geo/cf_calendar.h"

namespace strielad::ingest {
namespace {

struct VerticalType {
  AxisKind kind;
  const char* units;
  const char* positive;
};

std::optional<VerticalType> vertical_type(const std::string& type_of_level) {
  if (type_of_level == "isobaricInhPa") return VerticalType{AxisKind::kPressure, "hPa", "down"};
  if (type_of_level == "isobaricInPa") return VerticalType{AxisKind::kPressure, "Pa", "down"};
  if (type_of_level == "heightAboveGround" || type_of_level == "heightAboveSea") {
    return VerticalType{AxisKind::kHeight, "m", "up"};
  }
  if (type_of_level == "hybrid" || type_of_level == "generalVertical" ||
      type_of_level == "generalVerticalLayer") {
    return VerticalType{AxisKind::kModelLevel, "1", "down"};
  }
  return std::nullopt;
}

using Key = std::pair<std::string, std::string>;  // (shortName, typeOfLevel)

struct Group {
  std::vector<GribMessageSummary> messages;
};

GribVariable build_variable(const Key& key, const Group& group, const VerticalType& vertical,
                            const std::string& file) {
  GribVariable v;
  v.short_name = key.first;
  v.type_of_level = key.second;
  const GribMessageSummary& first = group.messages.front();
  v.name = first.name;
  v.units = first.units;
  v.grid_md5 = first.grid_md5;
  const std::string what = fmt::format("{}: GRIB variable '{}' on {}", file, key.first, key.second);
  std::set<double> levels;
  std::set<std::int64_t> times;
  std::map<std::pair<std::int64_t, double>, const GribMessageSummary*> at;
  for (const auto& m : group.messages) {
    if (m.grid_md5 != v.grid_md5) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: its messages lie on different grids (at bytes {} and {})", what,
                       first.offset, m.offset);
    }
    std::int64_t t = 0;
    try {
      t = grib_validity_seconds(m.validity_date, m.validity_time);
    } catch (const Error& e) {
      throw e.with_context(fmt::format("{} (message at byte {})", what, m.offset));
    }
    const auto [it, inserted] = at.emplace(std::pair{t, m.level_value}, &m);
    if (!inserted) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: level {} at validity {} {:04d} is in two messages (at bytes {} and {})",
                       what, m.level_value, m.validity_date, m.validity_time, it->second->offset,
                       m.offset);
    }
    levels.insert(m.level_value);
    times.insert(t);
  }
  v.times.assign(times.begin(), times.end());
  v.z.name = key.second;
  v.z.kind = vertical.kind;
  v.z.units = vertical.units;
  v.z.positive = vertical.positive;
  v.z.long_name = key.second;
  v.z.values.assign(levels.begin(), levels.end());
  v.messages.resize(v.times.size());
  for (std::size_t ti = 0; ti < v.times.size(); ++ti) {
    for (const double l : levels) {
      const auto it = at.find({v.times[ti], l});
      if (it == at.end()) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: level {} is missing at validity time {} s since 1970 (it is "
                         "there at other times)",
                         what, l, v.times[ti]);
      }
      v.messages[ti].push_back(*it->second);
    }
  }
  return v;
}

}  // namespace

std::int64_t grib_validity_seconds(long date, long time) {
  const geo::CfDate day{date / 10000, static_cast<unsigned>(date / 100 % 100),
                        static_cast<unsigned>(date % 100)};
  if (!geo::cf_date_exists(geo::CfCalendar::kProlepticGregorian, day) || time < 0 ||
      time / 100 > 23 || time % 100 > 59) {
    throw make_error(ErrorCode::kInvalidInput, "GRIB validity {} {:04d} is not a date and time",
                     date, time);
  }
  return geo::cf_day_number(geo::CfCalendar::kProlepticGregorian, day) * 86400 +
         (time / 100) * 3600 + (time % 100) * 60;
}

GribScan scan_grib_file(const std::filesystem::path& path) {
  GribScan scan;
  scan.path = path;
  std::vector<Key> order;
  std::map<Key, Group> groups;
  for (auto& m : list_grib_messages(path)) {
    Key key{m.short_name, m.type_of_level};
    auto [it, inserted] = groups.try_emplace(key);
    if (inserted) order.push_back(key);
    it->second.messages.push_back(std::move(m));
  }
  for (const Key& key : order) {
    const Group& group = groups.at(key);
    const auto vertical = vertical_type(key.second);
    std::set<double> levels;
    for (const auto& m : group.messages) levels.insert(m.level_value);
    if (levels.size() == 1) {
      try {
        scan.planes.push_back(build_variable(
            key, group, vertical.value_or(VerticalType{AxisKind::kOther, "1", ""}),
            path.string()));
      } catch (const Error&) {
        // Not usable as a plane either; listed as skipped below.
      }
    }
    if (!vertical) {
      scan.skipped.push_back({key.first, key.second, "not a vertical level type of a 3-D field"});
      continue;
    }
    if (levels.size() < 2) {
      scan.skipped.push_back({key.first, key.second, "on one level only"});
      continue;
    }
    scan.variables.push_back(build_variable(key, group, *vertical, path.string()));
  }
  return scan;
}

}  // namespace strielad::ingest
