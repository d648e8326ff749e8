// SPDX-License-Identifier: Apache-2.0
#include "ingest/cf_attributes.h"

#include <netcdf.h>

#include <cstdint>

#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"

namespace strielad::ingest {

bool has_attribute(int grpid, int varid, std::string_view name) {
  return attribute_type(grpid, varid, name).has_value();
}

std::optional<int> attribute_type(int grpid, int varid, std::string_view name) {
  const std::string n(name);
  nc_type type = NC_NAT;
  if (nc_inq_atttype(grpid, varid, n.c_str(), &type) != NC_NOERR) return std::nullopt;
  return type;
}

std::optional<std::string> text_attribute(int grpid, int varid, std::string_view name) {
  const std::string n(name);
  nc_type type = NC_NAT;
  std::size_t len = 0;
  if (nc_inq_att(grpid, varid, n.c_str(), &type, &len) != NC_NOERR) return std::nullopt;
  std::string out;
  if (type == NC_CHAR) {
    out.assign(len, '\0');
    if (len > 0) nc_check(nc_get_att_text(grpid, varid, n.c_str(), out.data()), n);
  } else if (type == NC_STRING) {
    std::vector<char*> values(len, nullptr);
    if (len > 0) nc_check(nc_get_att_string(grpid, varid, n.c_str(), values.data()), n);
    for (std::size_t i = 0; i < len; ++i) {
      if (i > 0) out += ' ';
      if (values[i] != nullptr) out += values[i];
    }
    if (len > 0) nc_free_string(len, values.data());
  } else {
    return std::nullopt;
  }
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

std::string text_attribute_or_empty(int grpid, int varid, std::string_view name) {
  return text_attribute(grpid, varid, name).value_or(std::string());
}

std::vector<long double> numeric_attribute(int grpid, int varid, std::string_view name) {
  const std::string n(name);
  nc_type type = NC_NAT;
  std::size_t len = 0;
  if (nc_inq_att(grpid, varid, n.c_str(), &type, &len) != NC_NOERR) return {};
  if (!is_numeric_type(type) || len == 0) return {};
  std::vector<long double> out(len);
  if (type == NC_UINT64) {
    std::vector<unsigned long long> v(len);
    nc_check(nc_get_att_ulonglong(grpid, varid, n.c_str(), v.data()), n);
    for (std::size_t i = 0; i < len; ++i) out[i] = static_cast<long double>(v[i]);
  } else if (is_integer_type(type)) {
    std::vector<long long> v(len);
    nc_check(nc_get_att_longlong(grpid, varid, n.c_str(), v.data()), n);
    for (std::size_t i = 0; i < len; ++i) out[i] = static_cast<long double>(v[i]);
  } else {
    std::vector<double> v(len);
    nc_check(nc_get_att_double(grpid, varid, n.c_str(), v.data()), n);
    for (std::size_t i = 0; i < len; ++i) out[i] = v[i];
  }
  return out;
}

std::vector<std::string> split_words(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' ||
                               text[i] == ',')) {
      ++i;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\n' &&
           text[j] != ',') {
      ++j;
    }
    if (j > i) out.emplace_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

}  // namespace strielad::ingest
