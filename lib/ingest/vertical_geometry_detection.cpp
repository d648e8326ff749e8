// SPDX-License-Identifier: Apache-2.0
#include "ingest/vertical_geometry_detection.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <cctype>
#include <functional>
#include <mutex>

#include "core/error.h"
#include "ingest/cf_attributes.h"
#include "ingest/formula_terms.h"
#include "ingest/ln_pressure_axis.h"
#include "ingest/netcdf_call.h"
#include "ingest/term_reader.h"
#include "ingest/wrf_grid_reader.h"

namespace strielad::ingest {
namespace {

std::string attribute(const TermVariable& t, std::string_view name) {
  std::lock_guard lock(netcdf_mutex());
  return text_attribute_or_empty(t.grpid, t.varid, name);
}

std::string short_name(const std::string& store_name) {
  const auto slash = store_name.rfind('/');
  return slash == std::string::npos ? store_name : store_name.substr(slash + 1);
}

// The file's name of a catalog variable (a derived one names its source).
std::string file_name(const VariableMeta& v) {
  return short_name(v.source_variable.empty() ? v.name : v.source_variable);
}

class Detector {
 public:
  Detector(const InputCatalog& catalog, const ScanOptions& options)
      : reader_(catalog.as_in_files()), options_(options), dims_(reader_.catalog().dims()) {
    if (!catalog.variables.empty()) {
      if (auto v = reader_.find(file_name(catalog.variables[0]));
          v && v->dimensions.size() >= 3) {
        z_dimension_ = v->dimensions[v->dimensions.size() - 3];
      }
    }
  }

  VerticalDetection run();

 private:
  const std::string& path(const TermVariable& t) const {
    return reader_.catalog().files[t.file].path;
  }
  std::string dims_text(const TermVariable& t) const {
    return fmt::format("({})", fmt::join(t.dimensions, ", "));
  }
  std::optional<VerticalGeometrySource> explicit_height();
  VerticalGeometrySource height_source(std::vector<TermVariable> sources);
  std::optional<VerticalGeometrySource> cf_formula();
  std::optional<VerticalGeometrySource> ccm_formula();
  // The formula's source from terms -> variables; `origin` says where each term was
  // named ("formula_terms of 'lev'", "attribute P0_var").
  VerticalGeometrySource formula_source(
      const FormulaDefinition& formula, const std::map<std::string, std::string>& named,
      const std::function<std::string(const std::string&)>& origin, const std::string& context);
  void check_term_shape(const TermVariable& t, const FormulaTermSpec& spec,
                        std::string_view formula);
  void check_every_step(const VerticalGeometrySource& g);
  std::optional<SurfaceSource> surface(const std::optional<VerticalGeometrySource>& g);
  bool is_plane(const TermVariable& t) const {
    return t.shape == std::vector<std::size_t>{dims_.y, dims_.x};
  }

  NcTermReader reader_;
  const ScanOptions& options_;
  Dims3 dims_;
  std::string z_dimension_;  // the data variables' vertical dimension
};

VerticalGeometrySource Detector::height_source(std::vector<TermVariable> sources) {
  VerticalGeometrySource g;
  g.quantity = VerticalGeometrySource::Quantity::kHeight;
  g.formula = "variable";
  for (const TermVariable& t : sources) {
    const bool levels_fit =
        !t.shape.empty() && (t.shape[0] == dims_.z || t.shape[0] == dims_.z + 1);
    if (t.shape.size() != 3 || !levels_fit || t.shape[1] != dims_.y || t.shape[2] != dims_.x) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: height variable '{}' has dimensions {} of lengths ({}); a height "
                       "source needs (z, y, x) or (time, z, y, x) with {} or {} (half) levels "
                       "on the {} x {} grid",
                       path(t), t.name, dims_text(t), fmt::join(t.shape, ", "), dims_.z,
                       dims_.z + 1, dims_.x, dims_.y);
    }
    if (!metres_per_height_unit(t.units)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: height variable '{}' has units '{}'; a height needs m, km or gpm, a "
                       "geopotential m2 s-2",
                       path(t), t.name, t.units);
    }
    g.sources.push_back(t.name);
    g.varies_in_time = g.varies_in_time || t.has_time;
  }
  return g;
}

std::optional<VerticalGeometrySource> Detector::explicit_height() {
  if (options_.height_var) {
    auto t = reader_.find(*options_.height_var);
    if (!t) {
      throw make_error(ErrorCode::kNotFound,
                       "height variable '{}' (--height-var) is in none of "
                       "the {} input files",
                       *options_.height_var, reader_.catalog().files.size());
    }
    return height_source({*t});
  }
  std::vector<std::pair<std::string, std::vector<TermVariable>>> candidates;
  // ICON writes z_mc as the mean of z_ifc's half levels: one candidate, z_mc preferred.
  if (auto t = reader_.find("z_mc")) {
    candidates.push_back({"z_mc", {*t}});
  } else if (auto half = reader_.find("z_ifc")) {
    candidates.push_back({"z_ifc", {*half}});
  }
  if (auto t = reader_.find("HHL")) candidates.push_back({"HHL", {*t}});
  auto ph = reader_.find("PH");
  auto phb = reader_.find("PHB");
  if (ph && phb) candidates.push_back({"PH + PHB", {*ph, *phb}});
  if (candidates.empty()) return std::nullopt;
  if (candidates.size() == 1 && candidates[0].first == "PH + PHB") {
    VerticalGeometrySource g = height_source(candidates[0].second);
    g.geopotential_gravity = kWrfGravity;
    return g;
  }
  if (candidates.size() > 1) {
    std::vector<std::string> named;
    for (const auto& [name, vars] : candidates) {
      named.push_back(fmt::format("'{}' ({})", name, path(vars[0])));
    }
    throw make_error(ErrorCode::kInvalidInput,
                     "the inputs hold {} height variables that could place the levels: {}; "
                     "choose one with --height-var",
                     candidates.size(), fmt::join(named, " and "));
  }
  return height_source(candidates[0].second);
}

void Detector::check_term_shape(const TermVariable& t, const FormulaTermSpec& spec,
                                std::string_view formula) {
  bool ok = false;
  std::string expected;
  switch (spec.shape) {
    case TermShape::kLevels:
      ok = !t.has_time && t.shape == std::vector<std::size_t>{dims_.z} &&
           (z_dimension_.empty() || t.dimensions.back() == z_dimension_);
      expected = fmt::format("({}) of {} levels", z_dimension_, dims_.z);
      break;
    case TermShape::kPlane:
      ok = is_plane(t);
      expected = fmt::format("(y, x) or (time, y, x) on the {} x {} grid", dims_.x, dims_.y);
      break;
    case TermShape::kScalar:
      ok = !t.has_time && (t.shape.empty() || t.shape == std::vector<std::size_t>{1});
      expected = "a scalar";
      break;
  }
  if (!ok) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable '{}' (term '{}' of {}) has dimensions {} of lengths ({}); "
                     "expected {}",
                     path(t), t.name, spec.term, formula, dims_text(t), fmt::join(t.shape, ", "),
                     expected);
  }
}

VerticalGeometrySource Detector::formula_source(
    const FormulaDefinition& formula, const std::map<std::string, std::string>& named,
    const std::function<std::string(const std::string&)>& origin, const std::string& context) {
  auto constant = [&](const std::string& term,
                      const std::string& variable) -> std::optional<double> {
    for (const std::string& key : {variable, term}) {
      if (auto it = options_.formula_constants.find(key); it != options_.formula_constants.end()) {
        return it->second;
      }
    }
    return std::nullopt;
  };
  std::vector<std::string> given;
  for (const auto& [term, variable] : named) given.push_back(term);
  for (const auto& set : formula.term_sets) {
    for (const FormulaTermSpec& spec : set) {
      const std::string term(spec.term);
      std::string upper = term;
      for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (!named.count(term) && constant(term, upper)) given.push_back(term);
    }
  }
  const auto set = complete_term_set(formula, given);
  if (!set) {
    throw make_error(
        ErrorCode::kInvalidInput, "{}: {} needs the terms {}; given: {}", context,
        formula.standard_name, describe_term_sets(formula),
        given.empty() ? std::string("none") : fmt::format("{}", fmt::join(given, ", ")));
  }
  VerticalGeometrySource g;
  g.quantity = formula.quantity;
  g.formula = std::string(formula.standard_name);
  for (const FormulaTermSpec& spec : *set) {
    const std::string term(spec.term);
    const auto it = named.find(term);
    std::string upper = term;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const std::string variable = it == named.end() ? upper : it->second;
    std::optional<TermVariable> t;
    if (it != named.end()) t = reader_.find(variable);
    if (!t) {
      if (auto c = constant(term, variable)) {
        g.constants[term] = *c;
        continue;
      }
      const std::string example = term == "p0" ? "100000" : "VALUE";
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: {} names variable '{}', which none of the {} input files holds; "
                       "give its value (in {}) with --formula-term {}={}",
                       context, origin(term), variable, reader_.catalog().files.size(),
                       spec.units == TermUnits::kPressure ? "Pa"
                       : spec.units == TermUnits::kLength ? "m"
                                                          : "its units",
                       variable, example);
    }
    check_term_shape(*t, spec, formula.standard_name);
    g.terms[term] = variable;
    g.sources.push_back(variable);
    g.varies_in_time = g.varies_in_time || t->has_time;
  }
  return g;
}

std::optional<VerticalGeometrySource> Detector::cf_formula() {
  const auto z = reader_.find(reader_.catalog().z.name);
  if (!z) return std::nullopt;
  const std::string formula_terms = attribute(*z, "formula_terms");
  if (formula_terms.empty()) return std::nullopt;
  const std::string standard_name = attribute(*z, "standard_name");
  const std::string context = fmt::format("{}: z coordinate '{}'", path(*z), z->name);
  // Levels that the scan turned into a pressure axis (ln_pressure_axis.h): nothing to place.
  if (standard_name == kLnPressureCoordinate) return std::nullopt;
  const FormulaDefinition* formula = find_formula(standard_name);
  if (formula == nullptr) {
    throw make_error(ErrorCode::kUnsupported,
                     "{} has formula_terms with standard_name '{}', a formula that is not "
                     "supported (supported: {}, and {} as a pressure axis)",
                     context, standard_name, supported_formulas(), kLnPressureCoordinate);
  }
  std::map<std::string, std::string> named;
  for (const FormulaTerm& t : parse_formula_terms(formula_terms, context))
    named[t.term] = t.variable;
  return formula_source(
      *formula, named,
      [&](const std::string& term) {
        return fmt::format("formula_terms term '{}' of '{}'", term, z->name);
      },
      context);
}

std::optional<VerticalGeometrySource> Detector::ccm_formula() {
  std::vector<TermVariable> holders;
  if (auto z = reader_.find(reader_.catalog().z.name)) holders.push_back(*z);
  if (!reader_.catalog().variables.empty()) {
    if (auto v = reader_.find(file_name(reader_.catalog().variables[0])))
      holders.push_back(*v);
  }
  static const std::map<std::string, std::string> kTermOf{
      {"A_var", "a"}, {"B_var", "b"}, {"P0_var", "p0"}, {"PS_var", "ps"}};
  for (const TermVariable& holder : holders) {
    std::map<std::string, std::string> named, attribute_of;
    for (const auto& [attr, term] : kTermOf) {
      const std::string value = attribute(holder, attr);
      if (value.empty()) continue;
      named[term] = value;
      attribute_of[term] = attr;
    }
    if (named.empty()) continue;
    const std::string context = fmt::format(
        "{}: variable '{}' (CCM hybrid attributes A_var, "
        "B_var, P0_var, PS_var)",
        path(holder), holder.name);
    const FormulaDefinition* formula = find_formula("atmosphere_hybrid_sigma_pressure_coordinate");
    return formula_source(
        *formula, named,
        [&](const std::string& term) {
          auto it = attribute_of.find(term);
          return it == attribute_of.end() ? fmt::format("term '{}'", term)
                                          : fmt::format("attribute {}", it->second);
        },
        context);
  }
  return std::nullopt;
}

void Detector::check_every_step(const VerticalGeometrySource& g) {
  if (!g.varies_in_time) return;
  for (const std::string& source : g.sources) {
    for (std::size_t step = 0; step < reader_.catalog().time.size(); ++step) {
      reader_.locate(source, step);  // throws for a step the source lacks
    }
  }
}

std::optional<SurfaceSource> Detector::surface(const std::optional<VerticalGeometrySource>& g) {
  if (g && g->formula == "atmosphere_hybrid_height_coordinate" && g->terms.count("orog")) {
    return SurfaceSource{g->terms.at("orog")};
  }
  for (const char* name : {"HSURF", "HGT", "topography_c", "orog"}) {
    const auto t = reader_.find(name);
    if (!t) continue;
    if (!is_plane(*t) || !metres_per_height_unit(t->units)) {
      spdlog::info(
          "{}: '{}' is not taken as the surface height: it is not a height (m, km, "
          "gpm) on the {} x {} grid (dimensions {}, units '{}')",
          path(*t), name, dims_.x, dims_.y, dims_text(*t), t->units);
      continue;
    }
    return SurfaceSource{name};
  }
  return std::nullopt;
}

VerticalDetection Detector::run() {
  VerticalDetection out;
  out.geometry = explicit_height();
  if (!out.geometry) out.geometry = cf_formula();
  if (!out.geometry) out.geometry = ccm_formula();
  if (out.geometry) check_every_step(*out.geometry);
  out.surface = surface(out.geometry);
  return out;
}

}  // namespace

std::vector<std::string> height_field_names(const ScanOptions& options) {
  std::vector<std::string> names{"z_mc", "z_ifc", "HHL", "PH", "PHB"};
  if (options.height_var) names.push_back(*options.height_var);
  return names;
}

VerticalDetection detect_vertical_geometry(const InputCatalog& catalog,
                                           const ScanOptions& options) {
  return Detector(catalog, options).run();
}

}  // namespace strielad::ingest
