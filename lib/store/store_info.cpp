// SPDX-License-Identifier: Apache-2.0
#include "store/store_info.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "core/text_columns.h"
#include "geo/grid_projection.h"
#include "geo/time_axis_dates.h"

namespace strielad {
namespace {

bool is_uniform(const Axis& a) {
  if (a.size() < 3) return true;
  const double d = a.values[1] - a.values[0];
  for (std::size_t i = 2; i < a.size(); ++i) {
    if (std::abs((a.values[i] - a.values[i - 1]) - d) > 1e-9 * std::abs(d) + 1e-12) return false;
  }
  return true;
}

std::uint64_t step_files_bytes(const Store& store) {
  std::uint64_t total = 0;
  for (std::uint32_t s = 0; s < store.step_count(); ++s) {
    if (store.has_step(s)) total += std::filesystem::file_size(store.step_path(s));
  }
  return total;
}

// The time axis: its units and calendar, then the first and last steps, each raw value
// beside its date, or the one reason the values have no dates.
void describe_time(const Store& store, std::ostream& out) {
  const TimeAxis& t = store.manifest().time;
  std::size_t present = 0;
  for (std::uint32_t s = 0; s < store.step_count(); ++s) present += store.has_step(s);
  fmt::print(out, "time       {} step{} ({} converted): {}, calendar {}\n", t.size(),
             t.size() == 1 ? "" : "s", present, t.units.empty() ? "no units" : t.units,
             t.calendar.empty() ? "not named (standard, the CF default)" : t.calendar);
  const geo::TimeAxisDates dates(t);
  TextColumns steps;
  std::string why_not = dates.why_not();
  std::vector<std::size_t> shown{0};
  if (t.size() > 1) shown.push_back(t.size() - 1);
  for (const std::size_t s : shown) {
    const auto date = dates.date(t.values[s]);
    if (!date.ok() && why_not.empty()) why_not = date.why_not;
    steps.add_row({fmt::format("step {}", s), fmt::format("{}", t.values[s]),
                   dates.has_dates() ? (date.ok() ? date.text : "no date") : ""});
  }
  steps.print(out, "  ");
  if (!why_not.empty()) fmt::print(out, "  no dates: {}\n", why_not);
}

// Where the grid is on the Earth: longitude/latitude axes, a grid mapping (with its PROJ
// pipeline and the true position of the grid's corners), 2-D coordinates (with the
// corners' positions from the GEOMETRY file), or nowhere.
void describe_placement(const Store& store, std::ostream& out) {
  const format::Manifest& m = store.manifest();
  if (format::is_curvilinear(m)) {
    fmt::print(out, "placed     by 2-D longitude '{}' and latitude '{}' (GEOMETRY)\n",
               m.geometry->horizontal.lon_variable, m.geometry->horizontal.lat_variable);
    const auto c = store.horizontal_coordinates();
    TextColumns corners;
    const std::size_t nx = c->nx, ny = c->ny;
    for (const auto& [name, i, j] : {std::tuple{"first x, first y", std::size_t{0}, std::size_t{0}},
                                     std::tuple{"last x, first y", nx - 1, std::size_t{0}},
                                     std::tuple{"first x, last y", std::size_t{0}, ny - 1},
                                     std::tuple{"last x, last y", nx - 1, ny - 1}}) {
      corners.add_row({name, fmt::format("({}, {}) at lon {:.6f}, lat {:.6f}", i, j,
                                         c->lon[j * nx + i], c->lat[j * nx + i])});
    }
    corners.print(out, "  ");
  } else if (m.grid_mapping && !m.grid_mapping->proj.empty()) {
    fmt::print(out, "placed     by grid mapping '{}' ({})\n", m.grid_mapping->variable,
               m.grid_mapping->name);
    fmt::print(out, "  proj     {}\n", m.grid_mapping->proj);
    const geo::GridProjection p(m.grid_mapping->proj);
    TextColumns corners;
    for (const auto& [name, x, y] :
         {std::tuple{"first x, first y", m.x.values.front(), m.y.values.front()},
          std::tuple{"last x, first y", m.x.values.back(), m.y.values.front()},
          std::tuple{"first x, last y", m.x.values.front(), m.y.values.back()},
          std::tuple{"last x, last y", m.x.values.back(), m.y.values.back()}}) {
      const auto ll = p.to_geographic(x, y);
      corners.add_row({name, fmt::format("({}, {}) at lon {:.6f}, lat {:.6f}", x, y, ll[0], ll[1])});
    }
    corners.print(out, "  ");
  } else if (m.x.kind == AxisKind::kLongitude && m.y.kind == AxisKind::kLatitude) {
    fmt::print(out, "placed     longitude and latitude{}\n",
               m.grid_mapping ? fmt::format(" (grid mapping '{}', {})", m.grid_mapping->variable,
                                            m.grid_mapping->name)
                              : std::string());
  } else {
    fmt::print(out, "placed     nowhere on the Earth: axes '{}' and '{}' without a grid mapping\n",
               m.x.name, m.y.name);
  }
}

// One line for the grid geometry: how x and y, then z are placed, the surface, and a
// mirrored index-to-Earth orientation; empty for a store without a geometry.
std::string geometry_summary(const format::Manifest& m) {
  if (!m.geometry) return {};
  const format::GridGeometry& g = *m.geometry;
  std::vector<std::string> parts;
  if (g.horizontal.kind == format::HorizontalGeometry::Kind::kCurvilinear) {
    parts.push_back(fmt::format("curvilinear {} x {} from {}/{}", m.x.size(), m.y.size(),
                                g.horizontal.lon_variable, g.horizontal.lat_variable));
  }
  const format::VerticalGeometry& v = g.vertical;
  const std::string quantity(format::vertical_quantity_name(v.quantity));
  if (v.kind == format::VerticalGeometry::Kind::kLevels) {
    parts.push_back(fmt::format("{} on {} levels ({}) from {}", quantity, v.levels.size(),
                                v.units, v.formula));
  } else if (v.kind == format::VerticalGeometry::Kind::kField) {
    std::vector<std::string> inputs;
    if (v.formula == format::kGeometryFormulaVariable) {
      inputs = v.sources;
    } else {
      for (const auto& [term, source] : v.terms) inputs.push_back(term);
    }
    parts.push_back(fmt::format(
        "{}s ({}) from {}{}, {}, {}", quantity, v.units,
        v.formula == format::kGeometryFormulaVariable ? std::string("variables") : v.formula,
        inputs.empty() ? std::string()
                       : fmt::format(" ({})", fmt::join(inputs, ", ")),
        v.varies_in_time ? "time-varying" : "time-invariant", dtype_name(v.dtype)));
  }
  if (g.surface) parts.push_back(fmt::format("surface from {}", g.surface->variable));
  if (g.orientation < 0) parts.push_back("mirrored (orientation -1)");
  return fmt::format("{}", fmt::join(parts, "; "));
}

// The geometry's files present in the store and their sizes.
nlohmann::json geometry_files(const Store& store) {
  nlohmann::json files = nlohmann::json::object();
  for (const auto& path : {store.geometry_path(), store.geometry_bricks_path()}) {
    if (std::filesystem::exists(path)) {
      files[path.filename().string()] = std::filesystem::file_size(path);
    }
  }
  return files;
}

}  // namespace

void describe_store(const Store& store, std::ostream& out) {
  const auto& m = store.manifest();
  const auto& layout = store.octree();
  fmt::print(out, "store      {}\n", store.path().string());
  fmt::print(out, "state      {} (written by strielad {})\n", m.complete ? "complete" : "converting",
             m.tool_version);
  fmt::print(out, "store id   {:016x}\n", m.store_id);
  fmt::print(out, "grid       {} x {} x {} samples\n", m.x.size(), m.y.size(), m.z.size());
  TextColumns axes;
  for (const Axis* a : {&m.x, &m.y, &m.z}) {
    axes.add_row({a->name,
                  fmt::format("{} ({}, {}): {} .. {}, {}, {}", a->size(), axis_kind_name(a->kind),
                              a->units.empty() ? "no units" : a->units, a->values.front(),
                              a->values.back(), a->descending() ? "descending" : "ascending",
                              is_uniform(*a) ? "uniform" : "non-uniform") +
                      (a->periodic ? ", periodic (round the Earth)" : "")});
  }
  axes.print(out, "  ");
  describe_placement(store, out);
  if (m.geometry) fmt::print(out, "geometry   {}\n", geometry_summary(m));
  describe_time(store, out);
  fmt::print(out, "variables  {}\n", m.variables.size());
  TextColumns variables;
  variables.add_row({"name", "type", "units", "predictor", "long name"});
  for (std::size_t i = 0; i < m.variables.size(); ++i) {
    const auto& v = m.variables[i];
    variables.add_row({v.name, std::string(dtype_name(v.dtype)), v.units.empty() ? "-" : v.units,
                       m.codec_of(i).predictor, v.long_name});
  }
  variables.print(out, "  ");
  fmt::print(out, "octree     brick {}, {} levels, {} nodes per step, {:.1f}% sample overhead\n",
             m.brick, layout.level_count(), layout.node_count(),
             layout.overhead_fraction() * 100);
  TextColumns levels;
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const auto& s = layout.level(l);
    levels.add_row({fmt::format("level {}", l),
                    fmt::format("{} x {} x {} nodes, stride {} x {} x {}", s.nodes[0], s.nodes[1],
                                s.nodes[2], s.stride[0], s.stride[1], s.stride[2])});
  }
  levels.print(out, "  ");
  const auto fpzip_text = [](const format::CodecSpec& c) {
    if (c.zfp) {
      const auto& z = *c.zfp;
      return z.mode == format::LossyMode::kRelative
                 ? fmt::format(", LOSSY zfp within {:g} (rel {:g} of the range)", z.tolerance, z.value)
                 : fmt::format(", LOSSY zfp within {:g} (abs)", z.tolerance);
    }
    return c.fpzip ? std::string(", fpzip where it pays") : std::string();
  };
  fmt::print(out, "codec      blosc {} level {} shuffle {}, predictor {}{} (format version {})\n",
             m.codec.name, m.codec.level, m.codec.shuffle, m.codec.predictor, fpzip_text(m.codec),
             m.format_version);
  TextColumns codecs;
  for (const auto& v : m.variables) {
    if (!v.codec) continue;
    codecs.add_row({v.name, fmt::format("blosc {} level {} shuffle {}, predictor {}{}",
                                        v.codec->name, v.codec->level, v.codec->shuffle,
                                        v.codec->predictor, fpzip_text(*v.codec))});
  }
  codecs.print(out, "  ");
  fmt::print(out, "sources    {} files\n", m.sources.size());
  fmt::print(out, "size       {:.1f} MB of step files\n", step_files_bytes(store) / 1e6);
  if (m.complete && m.summary.contains("ratio")) {
    fmt::print(out, "ratio      {:.2f} (input {:.1f} MB)\n", m.summary["ratio"].get<double>(),
               m.summary["input_bytes"].get<double>() / 1e6);
  }
}

nlohmann::json store_info_json(const Store& store) {
  nlohmann::json j = format::manifest_to_json(store.manifest());
  nlohmann::json present = nlohmann::json::array();
  for (std::uint32_t s = 0; s < store.step_count(); ++s) {
    if (store.has_step(s)) present.push_back(s);
  }
  j["converted_steps"] = present;
  // Beside the manifest's raw time values: their dates, or why there are none.
  const geo::TimeAxisDates dates(store.manifest().time);
  if (dates.has_dates()) {
    nlohmann::json list = nlohmann::json::array();
    for (const double v : store.manifest().time.values) {
      const auto date = dates.date(v);
      list.push_back(date.ok() ? nlohmann::json(date.text) : nlohmann::json());
      if (!date.ok() && !j["time"].contains("date_error")) j["time"]["date_error"] = date.why_not;
    }
    j["time"]["dates"] = std::move(list);
  } else {
    j["time"]["dates"] = nullptr;
    j["time"]["date_error"] = dates.why_not();
  }
  j["step_files_bytes"] = step_files_bytes(store);
  // Beside the manifest's geometry object: the same one-line summary as the text, and the
  // geometry's files.
  if (store.manifest().geometry) {
    j["geometry_info"] = {{"summary", geometry_summary(store.manifest())},
                          {"files", geometry_files(store)}};
  }
  j["octree"]["sample_overhead_percent"] = store.octree().overhead_fraction() * 100;
  return j;
}

}  // namespace strielad
