// SPDX-License-Identifier: Apache-2.0
#include "grid/units.h"

#include <cctype>
#include <string>

namespace strielad {
namespace {

std::string lower_trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::optional<double> metres_per_length_unit(std::string_view units) {
  const std::string u = lower_trimmed(units);
  for (std::string_view m : {"m", "meter", "meters", "metre", "metres"}) {
    if (u == m) return 1.0;
  }
  for (std::string_view km : {"km", "kilometer", "kilometers", "kilometre", "kilometres"}) {
    if (u == km) return 1000.0;
  }
  return std::nullopt;
}

std::optional<double> pascals_per_pressure_unit(std::string_view units) {
  const std::string u = lower_trimmed(units);
  for (std::string_view pa : {"pa", "pascal", "pascals"}) {
    if (u == pa) return 1.0;
  }
  for (std::string_view hpa :
       {"hpa", "hectopascal", "hectopascals", "mbar", "millibar", "millibars", "mb"}) {
    if (u == hpa) return 100.0;
  }
  if (u == "kpa") return 1000.0;
  if (u == "bar" || u == "bars") return 1e5;
  if (u == "atm") return 101325.0;
  return std::nullopt;
}

bool is_degree_units(std::string_view units) {
  const std::string u = lower_trimmed(units);
  for (std::string_view d : {"degrees", "degree", "deg", "degrees_east", "degree_east",
                             "degrees_north", "degree_north"}) {
    if (u == d) return true;
  }
  return false;
}

}  // namespace strielad
