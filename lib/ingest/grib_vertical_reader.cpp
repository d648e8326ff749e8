// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_vertical_reader.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/eccodes_call.h"
#include "ingest/grib_messages.h"
#include "ingest/vertical_geometry.h"

namespace strielad::ingest {
namespace {

struct DecodedField {
  std::vector<double> values;  // bitmap points NaN
  std::string units;
  std::vector<double> pv;  // empty when the message has none
};

DecodedField decode(const InputCatalog& c, const VariableLocation& loc, std::size_t level,
                    std::size_t plane, std::string_view field) {
  const std::string& path = c.files[loc.file].path;
  const GribMessageRef& m = loc.grib_levels.at(level);
  const std::string where = fmt::format(
      "{}: GRIB message at byte {} ('{}', which places the levels)", path, m.offset, field);
  std::vector<std::byte> bytes(static_cast<std::size_t>(m.size));
  ReadOnlyFile(path).read_at(m.offset, bytes);
  DecodedField out;
  std::lock_guard lock(eccodes_mutex());
  const GribHandle h = decode_grib_message(bytes, where);
  out.values = h.double_array_key("values", where);
  if (plane != 0 && out.values.size() != plane) {
    throw make_error(ErrorCode::kInvalidInput, "{}: {} values, the grid has {}", where,
                     out.values.size(), plane);
  }
  if (h.long_key("bitmapPresent") != 0) {
    const std::vector<double> bitmap = h.double_array_key("bitmap", where);
    for (std::size_t i = 0; i < out.values.size() && i < bitmap.size(); ++i) {
      if (bitmap[i] == 0) out.values[i] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  out.units = h.string_key("units");
  if (h.long_key("PVPresent") != 0) out.pv = h.double_array_key("pv", where);
  take_eccodes_log();
  return out;
}

const std::vector<VariableLocation>& field_locations(const InputCatalog& c,
                                                     const std::string& field) {
  const auto it = c.grib_fields.find(field);
  if (it == c.grib_fields.end() || it->second.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "the GRIB catalog does not say where field '{}' lies", field);
  }
  return it->second;
}

const VariableLocation& at_step(const std::vector<VariableLocation>& locations, std::size_t step) {
  return locations.size() == 1 ? locations.front() : locations.at(step);
}

double metres_per_unit(const std::string& units, const std::string& where) {
  const std::optional<double> f = units.empty() ? 1.0 : metres_per_height_unit(units);
  if (!f) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: units '{}' are not those of a height (m) or geopotential (m2 s-2)", where,
                     units);
  }
  return *f;
}

void evaluate_hybrid_pressure(const InputCatalog& c, const VerticalGeometrySource& g,
                              std::size_t step, std::size_t z0, std::size_t z1, std::size_t plane,
                              std::span<double> out) {
  const std::string& ps_name = g.terms.at("ps");
  const VariableLocation& data = c.locations.at(0).at(step);
  const std::vector<double> pv = decode(c, data, 0, 0, c.variables.at(0).name).pv;
  const std::string data_file = c.files[data.file].path;
  if (pv.size() < 4 || pv.size() % 2 != 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: GRIB message at byte {}: pv holds {} values; hybrid levels need "
                     "2 (N + 1)",
                     data_file, data.grib_levels.front().offset, pv.size());
  }
  const std::size_t n = pv.size() / 2 - 1;
  const VariableLocation& ps_loc = at_step(field_locations(c, ps_name), step);
  DecodedField ps = decode(c, ps_loc, 0, plane, ps_name);
  if (ps_name == "lnsp") {
    for (double& v : ps.values) v = std::exp(v);
  }
  for (std::size_t k = z0; k < z1; ++k) {
    const double level = c.z.values.at(k);
    if (level != std::round(level) || level < 1 || level > static_cast<double>(n)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: hybrid level {} is not a level number of its pv (1 .. {})", data_file,
                       level, n);
    }
    const auto upper = static_cast<std::size_t>(level) - 1;  // half level above
    const double a0 = pv[upper], a1 = pv[upper + 1];
    const double b0 = pv[n + 1 + upper], b1 = pv[n + 1 + upper + 1];
    double* dst = out.data() + (k - z0) * plane;
    for (std::size_t s = 0; s < plane; ++s) {
      const double p = ps.values[s];
      dst[s] = 0.5 * ((a0 + b0 * p) + (a1 + b1 * p));
    }
  }
}

void evaluate_half_level_heights(const InputCatalog& c, const VerticalGeometrySource& g,
                                 std::size_t step, std::size_t z0, std::size_t z1,
                                 std::size_t plane, std::span<double> out) {
  const std::string& name = g.sources.at(0);
  const VariableLocation& loc = at_step(field_locations(c, name), step);
  const std::size_t per_level = loc.grib_levels.size() / c.z.size();
  if (per_level * c.z.size() != loc.grib_levels.size() || per_level == 0 || per_level > 2) {
    throw make_error(ErrorCode::kInternal, "'{}' lists {} messages for {} levels", name,
                     loc.grib_levels.size(), c.z.size());
  }
  std::map<std::uint64_t, DecodedField> decoded;  // by offset: shared half levels once
  auto half = [&](std::size_t index) -> const DecodedField& {
    const std::uint64_t offset = loc.grib_levels[index].offset;
    auto it = decoded.find(offset);
    if (it == decoded.end()) it = decoded.emplace(offset, decode(c, loc, index, plane, name)).first;
    return it->second;
  };
  for (std::size_t k = z0; k < z1; ++k) {
    double* dst = out.data() + (k - z0) * plane;
    const DecodedField& a = half(k * per_level);
    const std::string where = fmt::format("{}: GRIB '{}' at byte {}", c.files[loc.file].path, name,
                                          loc.grib_levels[k * per_level].offset);
    const double f = metres_per_unit(a.units, where);
    if (per_level == 1) {
      for (std::size_t s = 0; s < plane; ++s) dst[s] = a.values[s] * f;
    } else {
      const DecodedField& b = half(k * per_level + 1);
      for (std::size_t s = 0; s < plane; ++s) dst[s] = 0.5 * (a.values[s] + b.values[s]) * f;
    }
    decoded.erase(loc.grib_levels[k * per_level].offset);  // the next layer's is kept
  }
}

}  // namespace

void evaluate_grib_vertical_geometry(const InputCatalog& c, std::size_t step, std::size_t z0,
                                     std::size_t z1, const Dims3& dims, std::span<double> out) {
  if (!c.vertical_geometry) {
    throw make_error(ErrorCode::kInvalidArgument, "the GRIB catalog has no vertical geometry");
  }
  if (z0 > z1 || z1 > dims.z) {
    throw make_error(ErrorCode::kInvalidArgument, "level range [{}, {}) outside [0, {})", z0, z1,
                     dims.z);
  }
  const std::size_t plane = dims.x * dims.y;
  if (out.size() != (z1 - z0) * plane) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "output holds {} values but levels [{}, {}) of {} x {} need {}", out.size(),
                     z0, z1, dims.x, dims.y, (z1 - z0) * plane);
  }
  if (z0 == z1) return;
  const VerticalGeometrySource& g = *c.vertical_geometry;
  if (g.formula == "atmosphere_hybrid_sigma_pressure_coordinate" && g.terms.count("ps") != 0) {
    evaluate_hybrid_pressure(c, g, step, z0, z1, plane, out);
  } else if (g.formula == "variable" && !g.sources.empty()) {
    evaluate_half_level_heights(c, g, step, z0, z1, plane, out);
  } else {
    throw make_error(ErrorCode::kUnsupported, "GRIB vertical geometry '{}' is not evaluated here",
                     g.formula);
  }
}

void evaluate_grib_surface(const InputCatalog& c, const Dims3& dims, std::span<double> out) {
  if (!c.surface) throw make_error(ErrorCode::kInvalidArgument, "the catalog has no surface");
  const std::size_t plane = dims.x * dims.y;
  if (out.size() != plane) {
    throw make_error(ErrorCode::kInvalidArgument, "output holds {} values but {} x {} need {}",
                     out.size(), dims.x, dims.y, plane);
  }
  const std::string& name = c.surface->variable;
  const VariableLocation& loc = field_locations(c, name).front();
  const DecodedField s = decode(c, loc, 0, plane, name);
  const double f = metres_per_unit(
      s.units, fmt::format("{}: GRIB surface height '{}' at byte {}", c.files[loc.file].path, name,
                           loc.grib_levels.front().offset));
  for (std::size_t i = 0; i < plane; ++i) out[i] = s.values[i] * f;
}

}  // namespace strielad::ingest
