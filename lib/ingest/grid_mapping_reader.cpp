// SPDX-License-Identifier: Apache-2.0
#include "ingest/grid_mapping_reader.h"

#include <netcdf.h>

#include <vector>

#include "core/error.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"

namespace strielad::ingest {
namespace {

// The mapping variable's names in a grid_mapping attribute: "name", or the extended
// form "name1: coord coord name2: coord ...".
std::vector<std::string> mapping_names(std::string_view text) {
  std::vector<std::string> names;
  const auto words = split_words(text);
  const bool extended = !words.empty() && words.front().back() == ':';
  for (const std::string& w : words) {
    if (!extended) {
      names.push_back(w);
    } else if (w.back() == ':') {
      names.push_back(w.substr(0, w.size() - 1));
    }
  }
  return names;
}

nlohmann::json attribute_json(int grpid, int varid, const std::string& name) {
  const auto type = attribute_type(grpid, varid, name);
  if (type && (*type == NC_CHAR || *type == NC_STRING)) {
    return text_attribute_or_empty(grpid, varid, name);
  }
  const std::vector<long double> values = numeric_attribute(grpid, varid, name);
  if (values.size() == 1) return static_cast<double>(values[0]);
  nlohmann::json array = nlohmann::json::array();
  for (long double v : values) array.push_back(static_cast<double>(v));
  return array;
}

}  // namespace

std::optional<GridMapping> read_grid_mapping(int grpid, int varid, std::string_view what) {
  const std::string text = text_attribute_or_empty(grpid, varid, "grid_mapping");
  const std::vector<std::string> names = mapping_names(text);
  if (names.empty()) return std::nullopt;
  if (names.size() > 1) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: grid_mapping '{}' names {} mappings; one grid mapping per variable is "
                     "supported",
                     what, text, names.size());
  }
  GridMapping m;
  m.variable = names[0];
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int mapping_id = -1;
    if (nc_inq_varid(*g, m.variable.c_str(), &mapping_id) != NC_NOERR) continue;
    int natts = 0;
    nc_check(nc_inq_varnatts(*g, mapping_id, &natts), what);
    for (int a = 0; a < natts; ++a) {
      char name[NC_MAX_NAME + 1] = {};
      nc_check(nc_inq_attname(*g, mapping_id, a, name), what);
      m.attributes[name] = attribute_json(*g, mapping_id, name);
    }
    const auto it = m.attributes.find("grid_mapping_name");
    if (it == m.attributes.end() || !it->is_string() || it->get<std::string>().empty()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping variable '{}' has no grid_mapping_name attribute", what,
                       m.variable);
    }
    m.name = it->get<std::string>();
    return m;
  }
  throw make_error(ErrorCode::kInvalidInput,
                   "{}: grid_mapping names '{}', which is not a variable of the file", what,
                   m.variable);
}

}  // namespace strielad::ingest
