// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_grid.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "geo/cf_grid_mapping.h"
#include "geo/grid_projection.h"

namespace strielad::ingest {
namespace {

constexpr std::string_view kSupportedGrids =
    "regular_ll, regular_gg, rotated_ll, lambert, polar_stereographic, mercator";

double key_value(double value, const char* key, std::string_view what) {
  if (!std::isfinite(value)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: GRIB key '{}' is missing", what, key);
  }
  return value;
}

// -180 < lon <= 180.
double normalized_longitude(double lon) {
  lon = std::fmod(lon, 360.0);
  if (lon > 180.0) lon -= 360.0;
  if (lon <= -180.0) lon += 360.0;
  return lon;
}

// n values from `first` to `last`, both exact.
std::vector<double> spaced(double first, double last, long n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) {
    v[static_cast<std::size_t>(i)] =
        i == n - 1 ? last
                   : first + (last - first) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  return v;
}

// `n` values evenly from `first` to `last`, as ecCodes places longitudes. GRIB keys round
// positions to micro-degrees (GRIB 1: milli-degrees) and increments too, so increments
// times n - 1 need not reach `last` exactly; when they miss it by more than that rounding,
// the message contradicts itself, and a note says so (ecCodes places latitudes by the
// increment and then snaps the last one; the difference is within one such miss).
std::vector<double> along(double first, double last, double increment, long n, long edition,
                          const char* axis, std::vector<std::string>& notes) {
  if (std::isfinite(increment) && increment != 0) {
    const double resolution = edition == 1 ? 1e-3 : 1e-6;
    const double reach =
        first + (last >= first ? 1 : -1) * std::abs(increment) * static_cast<double>(n - 1);
    const double off = std::abs(reach - last);
    if (off > resolution * static_cast<double>(n)) {
      notes.push_back(fmt::format(
          "GRIB {} axis: {} points from {} to {} are {} apart, but the message's increment is {} "
          "({:.6g} degrees short or beyond at the end); placed evenly from first to last",
          axis, n, first, last, (last - first) / static_cast<double>(n - 1), std::abs(increment),
          off));
    }
  }
  return spaced(first, last, n);
}

// Longitudes along i: towards the east unless iScansNegatively, so `last` is moved by
// whole turns to lie on that side of `first`.
std::vector<double> longitudes_along_i(const GribGridKeys& k, std::string_view what,
                                       std::vector<std::string>& notes) {
  const double first = key_value(k.lon_first, "longitudeOfFirstGridPointInDegrees", what);
  double last = key_value(k.lon_last, "longitudeOfLastGridPointInDegrees", what);
  if (!k.i_scans_negatively) {
    while (last <= first) last += 360.0;
    while (last - first > 360.0) last -= 360.0;
  } else {
    while (last >= first) last -= 360.0;
    while (first - last > 360.0) last += 360.0;
  }
  return along(first, last, k.di_degrees, k.ni, k.edition, "longitude", notes);
}

std::vector<double> latitudes_along_j(const GribGridKeys& k, std::string_view what,
                                      std::vector<std::string>& notes) {
  const double first = key_value(k.lat_first, "latitudeOfFirstGridPointInDegrees", what);
  const double last = key_value(k.lat_last, "latitudeOfLastGridPointInDegrees", what);
  if ((last > first) != k.j_scans_positively) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: GRIB latitudes run from {} to {} but jScansPositively is {}", what, first,
                     last, k.j_scans_positively ? 1 : 0);
  }
  return along(first, last, k.dj_degrees, k.nj, k.edition, "latitude", notes);
}

// The nj Gaussian latitudes from the first grid point on, in scanning order.
std::vector<double> gaussian_latitudes_along_j(const GribGridKeys& k, std::string_view what) {
  const double first = key_value(k.lat_first, "latitudeOfFirstGridPointInDegrees", what);
  std::vector<double> all = k.gaussian_latitudes;
  if (k.j_scans_positively) {
    std::sort(all.begin(), all.end());
  } else {
    std::sort(all.begin(), all.end(), std::greater<>());
  }
  const auto start = std::min_element(all.begin(), all.end(), [&](double a, double b) {
    return std::abs(a - first) < std::abs(b - first);
  });
  // GRIB 2 writes latitudes in micro-degrees, GRIB 1 in milli-degrees.
  if (start == all.end() || std::abs(*start - first) > 1e-3 ||
      all.end() - start < static_cast<std::ptrdiff_t>(k.nj)) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the first latitude {} and Nj = {} do not fit the grid's {} Gaussian "
                     "latitudes",
                     what, first, k.nj, all.size());
  }
  return {start, start + k.nj};
}

// The Earth's figure as CF grid-mapping attributes.
nlohmann::json earth_attributes(const GribGridKeys& k, std::string_view what) {
  switch (k.shape_of_the_earth) {
    case 0:
      return {{"earth_radius", 6367470.0}};
    case 1:
      return {{"earth_radius", key_value(k.radius, "radius", what)}};
    case 2:
      return {{"semi_major_axis", 6378160.0}, {"semi_minor_axis", 6356775.0}};
    case 3:
    case 7:
      return {{"semi_major_axis", key_value(k.major_axis, "earthMajorAxisInMetres", what)},
              {"semi_minor_axis", key_value(k.minor_axis, "earthMinorAxisInMetres", what)}};
    case 4:
      return {{"semi_major_axis", 6378137.0}, {"inverse_flattening", 298.257222101}};
    case 5:
      return {{"semi_major_axis", 6378137.0}, {"inverse_flattening", 298.257223563}};
    case 6:
      return {{"earth_radius", 6371229.0}};
    case 8:
      return {{"earth_radius", 6371200.0}};
    default:
      throw make_error(ErrorCode::kUnsupported,
                       "{}: GRIB shapeOfTheEarth {} is not supported (codes 0 to 8 are)", what,
                       k.shape_of_the_earth);
  }
}

Axis geographic_axis(bool longitude, std::vector<double> values) {
  Axis a;
  a.name = longitude ? "longitude" : "latitude";
  a.standard_name = a.name;
  a.kind = longitude ? AxisKind::kLongitude : AxisKind::kLatitude;
  a.units = longitude ? "degrees_east" : "degrees_north";
  a.values = std::move(values);
  return a;
}

Axis rotated_axis(bool longitude, std::vector<double> values) {
  Axis a;
  a.name = longitude ? "rlon" : "rlat";
  a.standard_name = longitude ? "grid_longitude" : "grid_latitude";
  a.units = "degrees";
  a.values = std::move(values);
  return a;
}

Axis projection_axis(bool x, double first, double step, long n) {
  Axis a;
  a.name = x ? "x" : "y";
  a.standard_name = x ? "projection_x_coordinate" : "projection_y_coordinate";
  a.units = "m";
  a.values.resize(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i)
    a.values[static_cast<std::size_t>(i)] = first + step * static_cast<double>(i);
  return a;
}

GridMapping projected_mapping(const GribGridKeys& k, std::string_view what) {
  GridMapping m;
  m.variable = "grib_grid";
  nlohmann::json attrs = earth_attributes(k, what);
  if (k.grid_type == "lambert") {
    if (k.projection_centre & 64) {
      throw make_error(ErrorCode::kUnsupported, "{}: bipolar Lambert projections are not supported",
                       what);
    }
    m.name = "lambert_conformal_conic";
    const double latin1 = key_value(k.latin1, "Latin1InDegrees", what);
    const double latin2 = key_value(k.latin2, "Latin2InDegrees", what);
    attrs["standard_parallel"] =
        latin1 == latin2 ? nlohmann::json(latin1) : nlohmann::json::array({latin1, latin2});
    attrs["longitude_of_central_meridian"] =
        normalized_longitude(key_value(k.lov, "LoVInDegrees", what));
    attrs["latitude_of_projection_origin"] = key_value(k.lad, "LaDInDegrees", what);
  } else if (k.grid_type == "polar_stereographic") {
    m.name = "polar_stereographic";
    const bool south = (k.projection_centre & 128) != 0;
    attrs["straight_vertical_longitude_from_pole"] =
        normalized_longitude(key_value(k.lov, "orientationOfTheGridInDegrees", what));
    attrs["latitude_of_projection_origin"] = south ? -90.0 : 90.0;
    // GRIB 1 polar stereographic grids are true at 60 degrees.
    attrs["standard_parallel"] = std::isfinite(k.lad) ? k.lad : (south ? -60.0 : 60.0);
  } else {  // mercator
    m.name = "mercator";
    attrs["standard_parallel"] = key_value(k.lad, "LaDInDegrees", what);
    attrs["longitude_of_projection_origin"] = 0.0;
  }
  attrs["false_easting"] = 0.0;
  attrs["false_northing"] = 0.0;
  attrs["grid_mapping_name"] = m.name;
  m.attributes = std::move(attrs);
  return m;
}

GribGrid projected_grid(const GribGridKeys& k, std::string_view what) {
  const GridMapping mapping = projected_mapping(k, what);
  // The first grid point in projection metres, then the steps the message gives.
  const Axis unit_x = projection_axis(true, 0, 1, 2), unit_y = projection_axis(false, 0, 1, 2);
  const geo::GridProjection projection(geo::cf_grid_mapping_proj(mapping, unit_x, unit_y, what));
  const auto [x0, y0] = projection.to_axis(
      normalized_longitude(key_value(k.lon_first, "longitudeOfFirstGridPointInDegrees", what)),
      key_value(k.lat_first, "latitudeOfFirstGridPointInDegrees", what));
  if (!std::isfinite(x0) || !std::isfinite(y0)) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the first grid point ({}, {}) has no place in the {} projection", what,
                     k.lon_first, k.lat_first, mapping.name);
  }
  const double dx = key_value(k.dx_metres, "DxInMetres", what);
  const double dy = key_value(k.dy_metres, "DyInMetres", what);
  if (!(dx > 0) || !(dy > 0)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: GRIB grid steps Dx = {} m, Dy = {} m", what, dx,
                     dy);
  }
  GribGrid g;
  g.x = projection_axis(true, x0, k.i_scans_negatively ? -dx : dx, k.ni);
  g.y = projection_axis(false, y0, k.j_scans_positively ? dy : -dy, k.nj);
  g.placement = place_horizontal_axes(g.x, g.y, mapping, what);
  return g;
}

void check_layout(const GribGridKeys& k, std::string_view what) {
  if (k.grid_type == "reduced_gg" || k.grid_type == "reduced_ll" ||
      k.grid_type == "reduced_rotated_gg") {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: GRIB grid '{}' has rows of different lengths; regrid it to a regular "
                     "grid first, e.g. `cdo setgridtype,regular IN OUT` (or remapbil)",
                     what, k.grid_type);
  }
  if (k.grid_type == "sh") {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: GRIB grid 'sh' holds spherical harmonics, not grid points; transform "
                     "it first, e.g. `cdo sp2gpl IN OUT`",
                     what);
  }
  if (k.ni < 2 || k.nj < 2) {
    throw make_error(ErrorCode::kInvalidInput, "{}: GRIB grid of {} x {} points (Ni x Nj)", what,
                     k.ni, k.nj);
  }
  if (k.alternative_row_scanning) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: GRIB alternativeRowScanning (boustrophedon rows) is not supported", what);
  }
  if (k.j_points_are_consecutive) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: GRIB jPointsAreConsecutive (columns stored first) is not supported",
                     what);
  }
}

}  // namespace

GribGridKeys read_grib_grid_keys(const GribHandle& m, std::string_view what) {
  GribGridKeys k;
  const auto value = [&](const char* key) {
    return m.double_key(key).value_or(GribGridKeys::kAbsent);
  };
  k.edition = m.long_key("edition", 2);
  k.grid_type = m.string_key("gridType");
  const bool projected = k.grid_type == "lambert" || k.grid_type == "polar_stereographic";
  k.ni = m.long_key(projected ? "Nx" : "Ni");
  k.nj = m.long_key(projected ? "Ny" : "Nj");
  k.i_scans_negatively = m.long_key("iScansNegatively") != 0;
  k.j_scans_positively = m.long_key("jScansPositively") != 0;
  k.j_points_are_consecutive = m.long_key("jPointsAreConsecutive") != 0;
  k.alternative_row_scanning = m.long_key("alternativeRowScanning") != 0;
  k.lat_first = value("latitudeOfFirstGridPointInDegrees");
  k.lon_first = value("longitudeOfFirstGridPointInDegrees");
  k.lat_last = value("latitudeOfLastGridPointInDegrees");
  k.lon_last = value("longitudeOfLastGridPointInDegrees");
  k.di_degrees = value("iDirectionIncrementInDegrees");
  k.dj_degrees = value("jDirectionIncrementInDegrees");
  if (k.grid_type == "regular_gg")
    k.gaussian_latitudes = m.double_array_key("distinctLatitudes", what);
  k.south_pole_lat = value("latitudeOfSouthernPoleInDegrees");
  k.south_pole_lon = value("longitudeOfSouthernPoleInDegrees");
  k.rotation_angle = m.double_key("angleOfRotationInDegrees").value_or(0.0);
  k.lad = value("LaDInDegrees");
  k.lov = value(k.grid_type == "lambert" ? "LoVInDegrees" : "orientationOfTheGridInDegrees");
  k.latin1 = value("Latin1InDegrees");
  k.latin2 = value("Latin2InDegrees");
  k.dx_metres = value(k.grid_type == "mercator" ? "DiInMetres" : "DxInMetres");
  k.dy_metres = value(k.grid_type == "mercator" ? "DjInMetres" : "DyInMetres");
  k.projection_centre = m.long_key("projectionCentreFlag");
  if (k.edition == 1) {
    k.shape_of_the_earth = m.long_key("earthIsOblate") != 0 ? 2 : 0;
  } else {
    k.shape_of_the_earth = m.long_key("shapeOfTheEarth");
    k.radius = value("radius");
    k.major_axis = value("earthMajorAxisInMetres");
    k.minor_axis = value("earthMinorAxisInMetres");
  }
  take_eccodes_log();  // absent keys are expected; their complaints are not errors
  return k;
}

GribGrid grib_grid(const GribGridKeys& k, std::string_view what) {
  check_layout(k, what);
  GribGrid g;
  std::vector<std::string> notes;
  if (k.grid_type == "regular_ll" || k.grid_type == "regular_gg") {
    g.x = geographic_axis(true, longitudes_along_i(k, what, notes));
    g.y = geographic_axis(false, k.grid_type == "regular_gg" ? gaussian_latitudes_along_j(k, what)
                                                             : latitudes_along_j(k, what, notes));
    g.placement = place_horizontal_axes(g.x, g.y, std::nullopt, what);
    g.placement.notes.insert(g.placement.notes.end(), notes.begin(), notes.end());
    return g;
  }
  if (k.grid_type == "rotated_ll") {
    if (k.rotation_angle != 0) {
      throw make_error(ErrorCode::kUnsupported,
                       "{}: GRIB rotated grid with angleOfRotationInDegrees = {} (only 0 is "
                       "supported)",
                       what, k.rotation_angle);
    }
    GridMapping mapping;
    mapping.variable = "grib_grid";
    mapping.name = "rotated_latitude_longitude";
    mapping.attributes = {
        {"grid_mapping_name", mapping.name},
        {"grid_north_pole_latitude",
         -key_value(k.south_pole_lat, "latitudeOfSouthernPoleInDegrees", what)},
        {"grid_north_pole_longitude",
         normalized_longitude(
             key_value(k.south_pole_lon, "longitudeOfSouthernPoleInDegrees", what) + 180.0)},
        {"north_pole_grid_longitude", 0.0}};
    g.x = rotated_axis(true, longitudes_along_i(k, what, notes));
    g.y = rotated_axis(false, latitudes_along_j(k, what, notes));
    g.placement = place_horizontal_axes(g.x, g.y, mapping, what);
    g.placement.notes.insert(g.placement.notes.end(), notes.begin(), notes.end());
    return g;
  }
  if (k.grid_type == "lambert" || k.grid_type == "polar_stereographic" ||
      k.grid_type == "mercator") {
    return projected_grid(k, what);
  }
  throw make_error(ErrorCode::kUnsupported,
                   "{}: GRIB grid type '{}' is not supported (supported: {})", what, k.grid_type,
                   kSupportedGrids);
}

}  // namespace strielad::ingest
