// SPDX-License-Identifier: Apache-2.0
#include "convert/lossy_option.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "core/error.h"
#include "ingest/box_reader.h"

namespace strielad::build {
namespace {

LossyRequest parse_item(std::string_view item) {
  const auto bad = [&](std::string_view why) {
    return make_error(ErrorCode::kInvalidArgument,
                      "--lossy '{}': {} (expected VAR=abs:TOL or VAR=rel:FRACTION)", item, why);
  };
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos || eq == 0) throw bad("no variable name before '='");
  const std::string_view spec = item.substr(eq + 1);
  const std::size_t colon = spec.find(':');
  if (colon == std::string_view::npos) throw bad("no mode: write abs: or rel: before the tolerance");
  LossyRequest r;
  r.variable = std::string(item.substr(0, eq));
  const std::string_view name = spec.substr(0, colon);
  const std::optional<format::LossyMode> mode = format::lossy_mode_from_name(name);
  if (!mode) throw bad(fmt::format("mode '{}' is not one of abs, rel", name));
  r.mode = *mode;
  const std::string_view number = spec.substr(colon + 1);
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), r.value);
  if (ec != std::errc() || end != number.data() + number.size()) {
    throw bad(fmt::format("tolerance '{}' is not a number", number));
  }
  if (!(r.value > 0) || !std::isfinite(r.value)) {
    throw bad(fmt::format("tolerance {} must be positive and finite", number));
  }
  return r;
}

// (min, max) of the variable's valid samples over every step; NaN when none is valid.
std::pair<double, double> variable_range(const ingest::InputCatalog& catalog,
                                         const ingest::ScanOptions& scan, std::size_t v) {
  const Dims3 d = catalog.dims();
  const std::array<std::size_t, 3> dims{d.x, d.y, d.z};
  constexpr std::size_t kPlanesPerRead = 8;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<double> buffer;
  for (std::size_t t = 0; t < catalog.time.values.size(); ++t) {
    BoxReader reader(catalog, scan, v, t);
    for (std::size_t z = 0; z < dims[2]; z += kPlanesPerRead) {
      const IndexBox box{{0, 0, z}, {dims[0] - 1, dims[1] - 1, std::min(dims[2], z + kPlanesPerRead) - 1}};
      buffer.resize(box.count());
      reader.read(box, std::span<double>(buffer));
      for (const double x : buffer) {
        if (std::isnan(x)) continue;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
  }
  if (lo > hi) return {std::nan(""), std::nan("")};
  return {lo, hi};
}

}  // namespace

std::vector<LossyRequest> parse_lossy(std::string_view text) {
  std::vector<LossyRequest> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = text.substr(start, comma - start);
    if (item.empty()) {
      throw make_error(ErrorCode::kInvalidArgument, "--lossy '{}': an empty item", text);
    }
    out.push_back(parse_item(item));
    start = comma + 1;
  }
  return out;
}

std::vector<format::LossySpec> resolve_lossy(const ingest::InputCatalog& catalog,
                                             const ingest::ScanOptions& scan,
                                             const std::vector<LossyRequest>& requests) {
  std::vector<format::LossySpec> specs;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const LossyRequest& r = requests[i];
    std::size_t v = 0;
    std::string names;
    while (v < catalog.variables.size() && catalog.variables[v].name != r.variable) {
      names += (v ? ", " : "") + catalog.variables[v].name;
      ++v;
    }
    if (v == catalog.variables.size()) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "--lossy names variable '{}', which is not converted (converted: {})",
                       r.variable, names);
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (requests[j].variable == r.variable) {
        throw make_error(ErrorCode::kInvalidArgument, "--lossy names variable '{}' twice",
                         r.variable);
      }
    }
    format::LossySpec s{r.mode, r.value, r.value};
    if (r.mode == format::LossyMode::kRelative) {
      const auto [lo, hi] = variable_range(catalog, scan, v);
      s.tolerance = r.value * (hi - lo);
      if (!(s.tolerance > 0) || !std::isfinite(s.tolerance)) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "--lossy {}=rel:{}: the variable's range [{}, {}] gives no positive "
                         "tolerance (use abs:)",
                         r.variable, r.value, lo, hi);
      }
    }
    specs.push_back(s);
  }
  return specs;
}

}  // namespace strielad::build
