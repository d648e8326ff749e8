// SPDX-License-Identifier: Apache-2.0
#include "ingest/wrf_scan.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <netcdf.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <set>

#include "core/error.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_file.h"
#include "ingest/variable_meta.h"
#include "ingest/wrf_destagger.h"
#include "ingest/wrf_grid_reader.h"

namespace strielad::ingest {
namespace {

bool is_wrf_coordinate(const std::string& name) {
  static const std::set<std::string> kNames{"Times", "XTIME",  "XLAT",   "XLONG", "XLAT_U",
                                            "XLONG_U", "XLAT_V", "XLONG_V", "ZNU",   "ZNW"};
  return kNames.count(name) > 0;
}

ScannedVariable scan_one(int ncid, int varid, const WrfLayout& layout, const std::string& file) {
  ScannedVariable sv;
  sv.name = variable_name(ncid, varid);
  const auto dimids = variable_dimids(ncid, varid);
  for (int d : dimids) sv.dimensions.push_back(dimension_name(ncid, d));
  sv.auxiliary = is_wrf_coordinate(sv.name);
  const auto not_gridded = [&](std::string why) {
    sv.klass = VariableClass::kNotGridded;
    sv.problem = make_error(ErrorCode::kUnsupported, "{}: WRF variable '{}' has dimensions ({}); {}",
                            file, sv.name, fmt::join(sv.dimensions, ", "), why);
    return sv;
  };
  if (!is_numeric_type(variable_type(ncid, varid))) return not_gridded("it is not numeric");
  const bool with_time = dimids.size() == 4 && sv.dimensions[0] == "Time";
  if (!with_time || (sv.dimensions[1] != "bottom_top" && sv.dimensions[1] != "bottom_top_stag") ||
      (sv.dimensions[2] != "south_north" && sv.dimensions[2] != "south_north_stag") ||
      (sv.dimensions[3] != "west_east" && sv.dimensions[3] != "west_east_stag")) {
    return not_gridded(
        "only fields on (Time, bottom_top, south_north, west_east), one of them possibly "
        "staggered (*_stag), are converted");
  }
  const std::array<std::string, 3> names{sv.dimensions[1], sv.dimensions[2], sv.dimensions[3]};
  const std::array<std::size_t, 3> lengths{dimension_length(ncid, dimids[1]),
                                           dimension_length(ncid, dimids[2]),
                                           dimension_length(ncid, dimids[3])};
  const Dims3 grid{layout.x.size(), layout.y.size(), layout.z.size()};
  if (!staggered_axis(names, lengths, grid)) {
    return not_gridded(fmt::format("its lengths ({}) do not fit the {} x {} x {} mass grid with "
                                   "at most one staggered dimension",
                                   fmt::join(lengths, ", "), grid.x, grid.y, grid.z));
  }
  sv.klass = VariableClass::kGrid3D;
  sv.x = layout.x;
  sv.y = layout.y;
  sv.z = layout.z;
  sv.grid_mapping = layout.mapping;
  sv.source_nx = layout.x.size();
  sv.time = layout.time;
  sv.meta = read_variable_meta(ncid, varid, sv.name);
  if (sv.meta.long_name.empty()) sv.meta.long_name = text_attribute_or_empty(ncid, varid, "description");
  sv.value_attributes = read_value_attributes(ncid, varid);
  return sv;
}

// WRF's base potential temperature t0 (module_model_constants: T = theta - t0). Not the
// T00 variable, which is the base state's sea-level temperature (290 K by default).
constexpr double kWrfTheta0 = 300.0;

// theta = T + 300 K, read from T: offered in T's place by default.
ScannedVariable potential_temperature(ScannedVariable& t) {
  ScannedVariable theta = t;
  theta.name = kWrfThetaName;
  theta.meta.name = kWrfThetaName;
  theta.meta.source_variable = t.name;
  theta.meta.value_offset = kWrfTheta0;
  theta.meta.units = "K";
  theta.meta.long_name = "potential temperature (T + 300 K)";
  theta.meta.standard_name = "air_potential_temperature";
  t.not_by_default =
      "is WRF's perturbation potential temperature (theta - 300 K): 'theta' (T + 300 K) is "
      "converted instead";
  return theta;
}

// Inserts theta before T when T is a field on the grid in K and the file has no theta.
void offer_potential_temperature(std::vector<ScannedVariable>& variables, int ncid,
                                 const std::string& file) {
  int varid = -1;
  if (nc_inq_varid(ncid, kWrfThetaName, &varid) == NC_NOERR) return;
  const auto t = std::find_if(variables.begin(), variables.end(),
                              [](const ScannedVariable& v) { return v.name == "T"; });
  if (t == variables.end() || t->klass != VariableClass::kGrid3D) return;
  if (t->meta.units != "K") {
    spdlog::info("{}: WRF variable 'T' has units '{}', not K: no potential temperature is "
                 "derived from it",
                 file, t->meta.units);
    return;
  }
  ScannedVariable theta = potential_temperature(*t);
  variables.insert(t, std::move(theta));
}

}  // namespace

std::vector<ScannedVariable> scan_wrf_variables(int ncid, const std::string& file) {
  const WrfLayout layout = read_wrf_layout(ncid, file);
  spdlog::info("{}: WRF output, {} grid of {} x {} x {} mass points (XLAT/XLONG within {:.3g} {} "
               "of it)",
               file, layout.mapping ? layout.mapping->name : std::string("latitude/longitude"),
               layout.x.size(), layout.y.size(), layout.z.size(), layout.max_deviation,
               layout.mapping ? "m" : "degrees");
  std::vector<ScannedVariable> out;
  const int nvars = variable_count(ncid);
  for (int v = 0; v < nvars; ++v) out.push_back(scan_one(ncid, v, layout, file));
  offer_potential_temperature(out, ncid, file);
  return out;
}

}  // namespace strielad::ingest
