// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_catalog.h"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/grib_grid.h"
#include "ingest/grib_vertical_detection.h"
#include "ingest/requested_steps.h"
#include "ingest/source_file.h"

namespace strielad::ingest {
namespace {

struct Found {
  std::size_t file;
  const GribVariable* variable;
};

// Every 3-D variable of the scans by store name, in the order first seen.
std::vector<std::pair<std::string, std::vector<Found>>> variables_by_name(
    const std::vector<GribScan>& scans) {
  std::vector<std::pair<std::string, std::vector<Found>>> out;
  for (std::size_t f = 0; f < scans.size(); ++f) {
    for (const auto& v : scans[f].variables) {
      const std::string name = grib_variable_name(scans[f], v);
      auto it =
          std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == name; });
      if (it == out.end()) it = out.insert(out.end(), {name, {}});
      it->second.push_back({f, &v});
    }
  }
  return out;
}

bool same_levels_and_grid(const GribVariable& a, const GribVariable& b) {
  return a.type_of_level == b.type_of_level && a.z.values == b.z.values && a.grid_md5 == b.grid_md5;
}

std::string levels_text(const GribVariable& v) {
  return fmt::format("{} levels of {} ({} .. {})", v.z.size(), v.type_of_level, v.z.values.front(),
                     v.z.values.back());
}

GribGrid grid_of(const std::filesystem::path& path, const GribVariable& v) {
  const std::string what = fmt::format("{}: GRIB variable '{}'", path.string(), v.short_name);
  GribGridKeys keys;
  {
    std::lock_guard lock(eccodes_mutex());
    const GribHandle h = read_grib_message(path, v.messages.front().front());
    keys = read_grib_grid_keys(h, what);
  }
  return grib_grid(keys, what);
}

}  // namespace

std::string grib_variable_name(const GribScan& scan, const GribVariable& v) {
  const auto same =
      std::count_if(scan.variables.begin(), scan.variables.end(),
                    [&](const GribVariable& w) { return w.short_name == v.short_name; });
  return same > 1 ? v.short_name + "_" + v.type_of_level : v.short_name;
}

std::vector<std::string> grib_variable_names(const std::vector<GribScan>& scans) {
  std::vector<std::string> names;
  for (const auto& [name, found] : variables_by_name(scans)) names.push_back(name);
  return names;
}

InputCatalog grib_catalog(const std::vector<std::filesystem::path>& inputs,
                          const ScanOptions& options) {
  std::vector<GribScan> scans;
  for (const auto& path : inputs) scans.push_back(scan_grib_file(path));
  return grib_catalog(scans, options);
}

InputCatalog grib_catalog(const std::vector<GribScan>& scans, const ScanOptions& options) {
  std::vector<std::filesystem::path> inputs;
  for (const auto& s : scans) inputs.push_back(s.path);
  const auto all = variables_by_name(scans);
  if (all.empty()) {
    std::vector<std::string> why;
    for (const auto& s : scans) {
      for (const auto& k : s.skipped)
        why.push_back(fmt::format("{} on {}: {}", k.short_name, k.type_of_level, k.why));
    }
    throw make_error(ErrorCode::kInvalidInput, "{}: no 3-D field in the GRIB input ({})",
                     inputs.front().string(), fmt::join(why, "; "));
  }

  // The variables: those asked for, or every one on the first one's levels and grid.
  std::vector<std::size_t> chosen;
  if (options.variables.empty()) {
    // The levels and grid most variables share (the first such set on a tie); fields
    // that place the levels (HHL) are not variables of their own.
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (!grib_field_places_levels(all[i].second.front().variable->short_name)) {
        candidates.push_back(i);
      }
    }
    if (candidates.empty()) {
      for (std::size_t i = 0; i < all.size(); ++i) candidates.push_back(i);
    }
    std::size_t lead = candidates.front(), lead_count = 0;
    for (const std::size_t i : candidates) {
      const auto count = static_cast<std::size_t>(
          std::count_if(candidates.begin(), candidates.end(), [&](std::size_t e) {
            return same_levels_and_grid(*all[e].second.front().variable,
                                        *all[i].second.front().variable);
          }));
      if (count > lead_count) lead = i, lead_count = count;
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (std::find(candidates.begin(), candidates.end(), i) == candidates.end()) {
        spdlog::info("GRIB field '{}' places the levels and is not converted as a variable "
                     "(ask for it with --vars)",
                     all[i].first);
        continue;
      }
      if (same_levels_and_grid(*all[i].second.front().variable,
                               *all[lead].second.front().variable)) {
        chosen.push_back(i);
      } else {
        spdlog::info(
            "GRIB variable '{}' skipped: {}, not the {} most variables are on (ask for "
            "it alone with --vars)",
            all[i].first, levels_text(*all[i].second.front().variable),
            levels_text(*all[lead].second.front().variable));
      }
    }
  } else {
    for (const auto& name : options.variables) {
      const auto it =
          std::find_if(all.begin(), all.end(), [&](const auto& e) { return e.first == name; });
      if (it == all.end()) {
        std::vector<std::string> names;
        for (const auto& e : all) names.push_back(e.first);
        throw make_error(ErrorCode::kNotFound, "{}: no GRIB variable '{}' (3-D variables: {})",
                         inputs.front().string(), name, fmt::join(names, ", "));
      }
      chosen.push_back(static_cast<std::size_t>(it - all.begin()));
    }
  }
  const GribVariable& ref = *all[chosen.front()].second.front().variable;
  for (const std::size_t i : chosen) {
    for (const Found& f : all[i].second) {
      if (!same_levels_and_grid(*f.variable, ref)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: GRIB variable '{}' is on {}{}, '{}' on {}; convert them separately",
                         scans[f.file].path.string(), all[i].first, levels_text(*f.variable),
                         f.variable->grid_md5 == ref.grid_md5 ? "" : " of another grid",
                         all[chosen.front()].first, levels_text(ref));
      }
    }
  }

  InputCatalog c;
  for (const auto& path : inputs) c.files.push_back(describe_source_file(path));
  const GribGrid grid = grid_of(scans[all[chosen.front()].second.front().file].path, ref);
  for (const auto& note : grid.placement.notes) spdlog::info("{}", note);
  c.x = grid.x;
  c.y = grid.y;
  c.z = ref.z;
  c.grid_mapping = grid.placement.mapping;
  c.source_nx = grid.placement.source_nx;

  // Times: every chosen variable at the same validity times, each in one file.
  std::vector<std::map<std::int64_t, VariableLocation>> at(chosen.size());
  for (std::size_t v = 0; v < chosen.size(); ++v) {
    for (const Found& f : all[chosen[v]].second) {
      for (std::size_t t = 0; t < f.variable->times.size(); ++t) {
        VariableLocation loc{f.file, t, {}};
        for (const auto& m : f.variable->messages[t]) loc.grib_levels.push_back({m.offset, m.size});
        const auto [it, inserted] = at[v].emplace(f.variable->times[t], std::move(loc));
        if (!inserted) {
          throw make_error(ErrorCode::kInvalidInput,
                           "GRIB variable '{}' at {} s since 1970 is in two files: {} and {}",
                           all[chosen[v]].first, f.variable->times[t],
                           scans[it->second.file].path.string(), scans[f.file].path.string());
        }
      }
    }
  }
  for (std::size_t v = 1; v < chosen.size(); ++v) {
    for (const auto& [t, loc] : at[0]) {
      if (!at[v].count(t)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "GRIB variable '{}' has no field at {} s since 1970, which '{}' has; "
                         "every variable must have the same time steps",
                         all[chosen[v]].first, t, all[chosen[0]].first);
      }
    }
    if (at[v].size() != at[0].size()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "GRIB variable '{}' has {} time steps, '{}' {}; every variable must have "
                       "the same time steps",
                       all[chosen[v]].first, at[v].size(), all[chosen[0]].first, at[0].size());
    }
  }
  const std::size_t n = at[0].size();
  const StepRange range = requested_steps(options, n);
  c.time.name = "time";
  c.time.units = "seconds since 1970-01-01 00:00:00";
  c.time.calendar = "proleptic_gregorian";
  std::size_t step = 0;
  for (const auto& [t, loc] : at[0]) {
    if (step >= range.first && step <= range.last) c.time.values.push_back(static_cast<double>(t));
    ++step;
  }
  c.locations.resize(chosen.size());
  for (std::size_t v = 0; v < chosen.size(); ++v) {
    const GribVariable& g = *all[chosen[v]].second.front().variable;
    VariableMeta meta;
    meta.name = all[chosen[v]].first;
    meta.units = g.units;
    meta.long_name = g.name;
    meta.store_type = DType::kFloat32;
    meta.source_type = "GRIB";
    meta.fill_value = std::numeric_limits<double>::quiet_NaN();  // bitmap points
    c.variables.push_back(meta);
    for (const double t : c.time.values)
      c.locations[v].push_back(at[v].at(static_cast<std::int64_t>(t)));
  }
  std::vector<GribVariablePart> parts;
  for (const std::size_t i : chosen) {
    for (const Found& f : all[i].second) parts.push_back({f.file, f.variable});
  }
  detect_grib_vertical_geometry(scans, parts, c);
  std::vector<std::string> names;
  for (const auto& m : c.variables) names.push_back(m.name);
  spdlog::info(
      "{} GRIB input file{}: {} variable{} ({}) on a {} x {} x {} grid ({}), {} of {} "
      "time step{}",
      inputs.size(), inputs.size() == 1 ? "" : "s", names.size(), names.size() == 1 ? "" : "s",
      fmt::join(names, ", "), c.x.size(), c.y.size(), c.z.size(), ref.type_of_level, c.time.size(),
      n, n == 1 ? "" : "s");
  return c;
}

namespace {

// Whether float32 keeps a message's packed values apart: its packing step against the
// float32 spacing at its largest magnitude.
void check_float_resolves(const GribHandle& h, const std::string& what) {
  const std::string packing = h.string_key("packingType");
  if (packing.rfind("grid_ieee", 0) == 0) {
    if (h.long_key("precision", 1) != 1) {
      throw make_error(ErrorCode::kUnsupported,
                       "{}: IEEE float64 values would lose precision in "
                       "float32",
                       what);
    }
    return;
  }
  const double e = h.double_key("binaryScaleFactor").value_or(0);
  const double d = h.double_key("decimalScaleFactor").value_or(0);
  const double r = h.double_key("referenceValue").value_or(0);
  const double bits = h.double_key("bitsPerValue").value_or(0);
  if (bits == 0) return;  // a constant field
  const double step = std::ldexp(1.0, static_cast<int>(e)) * std::pow(10.0, -d);
  const double largest =
      std::max(std::abs(r), std::abs(r + (std::ldexp(1.0, static_cast<int>(bits)) - 1) * step));
  const double spacing = largest > 0 ? std::ldexp(1.0, std::ilogb(largest) - 23) : 0;
  if (step < spacing) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: packed in steps of {:g} up to {:g}, finer than float32 resolves ({:g}); "
                     "the store would round them",
                     what, step, largest, spacing);
  }
}

template <typename Out>
void read_levels(const std::filesystem::path& path, std::span<const GribMessageRef> levels,
                 std::size_t plane, std::string_view what, std::span<Out> out) {
  if (out.size() < levels.size() * plane) {
    throw make_error(ErrorCode::kInternal, "{}: {} samples for {} levels of {}", what, out.size(),
                     levels.size(), plane);
  }
  const ReadOnlyFile file(path);
  std::vector<std::byte> bytes;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const GribMessageRef& m = levels[k];
    const std::string where = fmt::format("{}: GRIB message at byte {}", what, m.offset);
    bytes.resize(static_cast<std::size_t>(m.size));
    file.read_at(m.offset, bytes);
    std::lock_guard lock(eccodes_mutex());
    const GribHandle h = decode_grib_message(bytes, where);
    if (sizeof(Out) == 4) check_float_resolves(h, where);
    const std::vector<double> values = h.double_array_key("values", where);
    if (values.size() != plane) {
      throw make_error(ErrorCode::kInvalidInput, "{}: {} values, the grid has {}", where,
                       values.size(), plane);
    }
    std::vector<double> bitmap;
    if (h.long_key("bitmapPresent") != 0) bitmap = h.double_array_key("bitmap", where);
    Out* dst = out.data() + k * plane;
    for (std::size_t i = 0; i < plane; ++i) {
      dst[i] = !bitmap.empty() && bitmap[i] == 0 ? std::numeric_limits<Out>::quiet_NaN()
                                                 : static_cast<Out>(values[i]);
    }
    take_eccodes_log();
  }
}

}  // namespace

void read_grib_levels(const std::filesystem::path& path, std::span<const GribMessageRef> levels,
                      std::size_t plane, std::string_view what, std::span<float> out) {
  read_levels(path, levels, plane, what, out);
}

void read_grib_levels(const std::filesystem::path& path, std::span<const GribMessageRef> levels,
                      std::size_t plane, std::string_view what, std::span<double> out) {
  read_levels(path, levels, plane, what, out);
}

}  // namespace strielad::ingest
