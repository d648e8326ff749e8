// SPDX-License-Identifier: Apache-2.0
#include "view/default_exaggeration.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace strielad::view {
namespace {

// E before rounding; NaN when the extent has no usable size.
double raw_exaggeration(const DomainExtent& e) {
  const double horizontal = std::sqrt(e.width_km * e.length_km);
  if (!std::isfinite(horizontal) || !std::isfinite(e.depth_km) || !(horizontal > 0) ||
      !(e.depth_km > 0)) {
    return NAN;
  }
  return kExaggeratedDepthShare * horizontal / e.depth_km;
}

// The nearest (by ratio) of 1, 2, 5 times a power of ten.
double round_1_2_5(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  double best = decade;
  for (const double m : std::array{1.0, 2.0, 5.0, 10.0}) {
    if (std::fabs(std::log(value / (m * decade))) < std::fabs(std::log(value / best))) {
      best = m * decade;
    }
  }
  return best;
}

}  // namespace

DomainExtent domain_extent(const lod::WorldFrame& frame) {
  const auto& d = frame.domain();
  return {d.hi[0] - d.lo[0], d.hi[1] - d.lo[1],
          (d.hi[2] - d.lo[2]) / frame.vertical_exaggeration()};
}

double default_vertical_exaggeration(const DomainExtent& extent) {
  const double raw = raw_exaggeration(extent);
  if (std::isnan(raw)) return lod::kDefaultVerticalExaggeration;
  return std::clamp(round_1_2_5(raw), kMinDefaultExaggeration, kMaxDefaultExaggeration);
}

std::string describe_default_exaggeration(const DomainExtent& extent) {
  const double raw = raw_exaggeration(extent);
  const double chosen = default_vertical_exaggeration(extent);
  if (std::isnan(raw)) {
    return fmt::format("{:g} for a {:.0f} x {:.0f} km domain {:.3g} km deep (no horizontal "
                       "size or no depth: the fixed default)",
                       chosen, extent.width_km, extent.length_km, extent.depth_km);
  }
  return fmt::format("{:g} for a {:.0f} x {:.0f} km domain {:.3g} km deep ({} x horizontal "
                     "size / depth = {:.3g}, rounded to 1-2-5{})",
                     chosen, extent.width_km, extent.length_km, extent.depth_km,
                     kExaggeratedDepthShare, raw,
                     round_1_2_5(raw) != chosen
                         ? fmt::format(", within {:g}..{:g}", kMinDefaultExaggeration,
                                       kMaxDefaultExaggeration)
                         : std::string());
}

}  // namespace strielad::view
