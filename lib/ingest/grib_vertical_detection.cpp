// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_vertical_detection.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>

#include "core/error.h"

namespace strielad::ingest {
namespace {

// A field among the inputs: its parts (one per file that has it).
struct Field {
  std::string short_name, type_of_level;
  std::vector<GribVariablePart> parts;
};

// The field `short_name` (on `type_of_level`, or any when empty), as a plane
// (`planes`) or as a 3-D variable; nullopt when no input has it.
std::optional<Field> find_field(const std::vector<GribScan>& scans, std::string_view short_name,
                                std::string_view type_of_level, bool planes) {
  std::optional<Field> out;
  for (std::size_t f = 0; f < scans.size(); ++f) {
    for (const GribVariable& v : planes ? scans[f].planes : scans[f].variables) {
      if (v.short_name != short_name) continue;
      if (!type_of_level.empty() && v.type_of_level != type_of_level) continue;
      if (out && out->type_of_level != v.type_of_level) continue;
      if (!out) out = Field{v.short_name, v.type_of_level, {}};
      out->parts.push_back({f, &v});
    }
  }
  return out;
}

std::string message_text(const std::vector<GribScan>& scans, const GribVariablePart& part,
                         const GribMessageSummary& m) {
  return fmt::format("{}: GRIB message at byte {} ('{}' on {} {})", scans[part.file].path.string(),
                     m.offset, part.variable->short_name, part.variable->type_of_level,
                     m.level_value);
}

// The field's messages at every catalog time step (its time-invariant single time when
// `invariant`): one location per step, listing the messages of `levels` (indices into
// the field's z values).
std::vector<VariableLocation> locate(const std::vector<GribScan>& scans, const Field& field,
                                     const InputCatalog& c, bool invariant,
                                     const std::vector<std::size_t>& levels) {
  auto location = [&](const GribVariablePart& part, std::size_t t) {
    VariableLocation loc{part.file, t, {}};
    for (const std::size_t k : levels) {
      const GribMessageSummary& m = part.variable->messages[t][k];
      loc.grib_levels.push_back({m.offset, m.size});
    }
    return loc;
  };
  if (invariant) return {location(field.parts.front(), 0)};
  std::vector<VariableLocation> out;
  for (std::size_t step = 0; step < c.time.size(); ++step) {
    const auto t = static_cast<std::int64_t>(c.time.values[step]);
    std::optional<VariableLocation> found;
    for (const GribVariablePart& part : field.parts) {
      const auto& times = part.variable->times;
      const auto it = std::find(times.begin(), times.end(), t);
      if (it != times.end()) {
        found = location(part, static_cast<std::size_t>(it - times.begin()));
        break;
      }
    }
    if (!found) {
      std::vector<std::string> files;
      for (const auto& s : scans) files.push_back(s.path.string());
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: GRIB field '{}' on {}, which places the levels, has no message at "
                       "time step {} ({} s since 1970-01-01); every step of the variables needs "
                       "one",
                       fmt::join(files, ", "), field.short_name, field.type_of_level, step, t);
    }
    out.push_back(std::move(*found));
  }
  return out;
}

void check_grid(const std::vector<GribScan>& scans, const Field& field,
                const GribVariablePart& ref) {
  for (const GribVariablePart& part : field.parts) {
    if (part.variable->grid_md5 != ref.variable->grid_md5) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: GRIB field '{}' on {}, which places the levels, lies on another grid "
                       "than '{}' ({})",
                       scans[part.file].path.string(), field.short_name, field.type_of_level,
                       ref.variable->short_name, scans[ref.file].path.string());
    }
  }
}

// Hybrid levels: pressure from pv (half-level a in Pa, then b) and the surface pressure.
void detect_hybrid(const std::vector<GribScan>& scans, const std::vector<GribVariablePart>& chosen,
                   InputCatalog& c) {
  const GribVariablePart* first_part = nullptr;
  const GribMessageSummary* first = nullptr;
  for (const GribVariablePart& part : chosen) {
    for (const auto& step : part.variable->messages) {
      for (const GribMessageSummary& m : step) {
        if (first == nullptr) {
          first_part = &part;
          first = &m;
        } else if (m.pv_size != first->pv_size || m.pv_checksum != first->pv_checksum) {
          throw make_error(ErrorCode::kInvalidInput,
                           "{} and {} have different hybrid level coefficients (pv: {} and {} "
                           "values); levels of different models cannot share a grid",
                           message_text(scans, *first_part, *first), message_text(scans, part, m),
                           first->pv_size, m.pv_size);
        }
      }
    }
  }
  const std::string where = message_text(scans, *first_part, *first);
  if (first->pv_size == 0) {
    spdlog::info("{}: hybrid levels without pv coefficients: placed by their numbers only", where);
    return;
  }
  if (first->pv_size < 4 || first->pv_size % 2 != 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: pv holds {} values; hybrid levels need 2 (N + 1) (a, then b, of N + 1 "
                     "half levels)",
                     where, first->pv_size);
  }
  const std::size_t n = first->pv_size / 2 - 1;
  for (const double level : c.z.values) {
    if (level != std::round(level) || level < 1 || level > static_cast<double>(n)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: hybrid level {} is not a level number of its pv (1 .. {})", where,
                       level, n);
    }
  }
  std::optional<Field> ps = find_field(scans, "lnsp", "", true);
  if (!ps) ps = find_field(scans, "sp", "", true);
  if (!ps) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: hybrid levels are placed by pressure from pv and the surface pressure, "
                     "but no input has 'lnsp' (its logarithm, on hybrid level 1) or 'sp' (on the "
                     "surface); add the file that holds it",
                     where);
  }
  check_grid(scans, *ps, chosen.front());
  c.grib_fields[ps->short_name] = locate(scans, *ps, c, false, {0});
  VerticalGeometrySource g;
  g.quantity = VerticalGeometrySource::Quantity::kPressure;
  g.formula = "atmosphere_hybrid_sigma_pressure_coordinate";
  g.terms = {{"a", "pv"}, {"b", "pv"}, {"ps", ps->short_name}};
  g.sources = {ps->short_name};
  g.varies_in_time = true;
  c.vertical_geometry = std::move(g);
}

// generalVerticalLayer (layer k between half levels k and k + 1) and generalVertical
// (level k is half level k): height from HHL.
void detect_cosmo(const std::vector<GribScan>& scans, const std::vector<GribVariablePart>& chosen,
                  InputCatalog& c) {
  const std::optional<Field> hhl = find_field(scans, "HHL", "generalVertical", false);
  if (!hhl) {
    spdlog::info("{}: no HHL among the inputs: the {} levels are placed by their numbers only",
                 scans[chosen.front().file].path.string(), chosen.front().variable->type_of_level);
    return;
  }
  check_grid(scans, *hhl, chosen.front());
  const GribVariable& h = *hhl->parts.front().variable;
  const bool layers = chosen.front().variable->type_of_level == "generalVerticalLayer";
  std::vector<std::size_t> levels;  // indices into HHL's z values
  auto index_of = [&](double level, double layer) {
    const auto it = std::find(h.z.values.begin(), h.z.values.end(), level);
    if (it == h.z.values.end()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: HHL has no half level {}, which level {} of {} needs (HHL levels {} "
                       "..{})",
                       scans[hhl->parts.front().file].path.string(), level, layer,
                       chosen.front().variable->type_of_level, h.z.values.front(),
                       h.z.values.back());
    }
    return static_cast<std::size_t>(it - h.z.values.begin());
  };
  for (const double level : c.z.values) {
    levels.push_back(index_of(level, level));
    if (layers) levels.push_back(index_of(level + 1, level));
  }
  std::size_t times = 0;
  for (const auto& part : hhl->parts) times += part.variable->times.size();
  for (const auto& part : hhl->parts) {
    if (part.variable->z.values != h.z.values) {
      throw make_error(ErrorCode::kInvalidInput, "{}: HHL has other levels than in {}",
                       scans[part.file].path.string(),
                       scans[hhl->parts.front().file].path.string());
    }
  }
  const bool varies = times > 1;
  c.grib_fields["HHL"] = locate(scans, *hhl, c, !varies, levels);
  VerticalGeometrySource g;
  g.quantity = VerticalGeometrySource::Quantity::kHeight;
  g.formula = "variable";
  g.sources = {"HHL"};
  g.varies_in_time = varies;
  c.vertical_geometry = std::move(g);
}

// The model's surface height: orog, HSURF or h, or the surface geopotential z.
void detect_surface(const std::vector<GribScan>& scans, const GribVariablePart& ref,
                    InputCatalog& c) {
  for (const std::string_view name : {"orog", "HSURF", "h", "z"}) {
    // A geopotential z elsewhere than on the surface (or IFS's hybrid level 1) is not
    // the surface's; DWD's HSURF is on the surface up to mean sea level (a type of
    // level ecCodes calls "unknown").
    std::optional<Field> s = find_field(scans, name, name == "z" ? "surface" : "", true);
    if (!s && name == "z") s = find_field(scans, name, "hybrid", true);
    if (!s) continue;
    if (s->parts.front().variable->grid_md5 != ref.variable->grid_md5) {
      spdlog::info("{}: '{}' is not taken as the surface height: it lies on another grid",
                   scans[s->parts.front().file].path.string(), name);
      continue;
    }
    c.grib_fields[std::string(name)] = locate(scans, *s, c, true, {0});
    c.surface = SurfaceSource{std::string(name)};
    return;
  }
}

}  // namespace

bool grib_field_places_levels(std::string_view short_name) {
  return short_name == "HHL" || short_name == "lnsp" || short_name == "sp";
}

void detect_grib_vertical_geometry(const std::vector<GribScan>& scans,
                                   const std::vector<GribVariablePart>& chosen, InputCatalog& c) {
  if (chosen.empty()) return;
  const std::string& type = chosen.front().variable->type_of_level;
  if (type == "hybrid") {
    detect_hybrid(scans, chosen, c);
  } else if (type == "generalVertical" || type == "generalVerticalLayer") {
    detect_cosmo(scans, chosen, c);
  } else {
    return;
  }
  detect_surface(scans, chosen.front(), c);
}

}  // namespace strielad::ingest
