// SPDX-License-Identifier: Apache-2.0
#include "convert/geometry_plan.h"

#include <fmt/ranges.h>

#include <vector>

#include "core/error.h"
#include "geo/horizontal_orientation.h"
#include "ingest/slab_reader.h"

namespace strielad::build {

namespace {

using format::VerticalGeometry;

// +1 when column (0, 0)'s height grows with k at time step 0, -1 when it falls.
int up_per_level(const ingest::InputCatalog& catalog, const ingest::ScanOptions& scan,
                 const ingest::VerticalGeometrySource& source) {
  if (catalog.z.size() < 2) return 1;
  const std::size_t plane = catalog.x.size() * catalog.y.size();
  std::vector<double> two(2 * plane);
  ingest::SlabReader reader(catalog, scan);
  reader.read_vertical_geometry(0, 0, 2, two);
  const double d = two[plane] - two[0];
  if (!(d != 0)) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{} ({}): column (0, 0) has the same value {} on levels 0 and 1 at time "
                     "step 0; levels must differ",
                     fmt::join(source.sources, " + "), source.formula, two[0]);
  }
  const bool pressure = source.quantity == ingest::VerticalGeometrySource::Quantity::kPressure;
  return (d > 0) != pressure ? 1 : -1;
}

// +1 when the z axis's values go up with k (a height growing, a pressure or a "positive:
// down" coordinate falling), -1 otherwise.
int up_along_axis(const Axis& z) {
  if (z.size() < 2) return 1;
  const bool down = z.kind == AxisKind::kPressure || z.positive == "down";
  return z.descending() != down ? -1 : 1;
}

}  // namespace

int horizontal_sign(const ingest::InputCatalog& catalog) {
  if (catalog.curvilinear) return catalog.curvilinear->orientation;
  return geo::horizontal_orientation(catalog.x, catalog.y, catalog.grid_mapping);
}

format::HorizontalCoordinates curvilinear_coordinates(const ingest::InputCatalog& catalog) {
  format::HorizontalCoordinates c;
  c.nx = static_cast<std::uint32_t>(catalog.x.size());
  c.ny = static_cast<std::uint32_t>(catalog.y.size());
  if (catalog.curvilinear) {
    c.lon = catalog.curvilinear->lon;
    c.lat = catalog.curvilinear->lat;
  }
  return c;
}

std::optional<format::GridGeometry> plan_geometry(const ingest::InputCatalog& catalog,
                                                  const ingest::ScanOptions& scan,
                                                  const format::CodecSpec& codec) {
  if (!catalog.vertical_geometry && !catalog.surface && !catalog.curvilinear) return std::nullopt;
  format::GridGeometry g;
  if (const auto& c = catalog.curvilinear) {
    g.horizontal.kind = format::HorizontalGeometry::Kind::kCurvilinear;
    g.horizontal.lon_variable = c->lon_variable;
    g.horizontal.lat_variable = c->lat_variable;
    g.horizontal.coordinates_checksum = format::coordinates_checksum(curvilinear_coordinates(catalog));
  }
  int up = 1;
  if (const auto& source = catalog.vertical_geometry) {
    VerticalGeometry& v = g.vertical;
    v.kind = VerticalGeometry::Kind::kField;
    const bool pressure = source->quantity == ingest::VerticalGeometrySource::Quantity::kPressure;
    v.quantity = pressure ? VerticalGeometry::Quantity::kPressure : VerticalGeometry::Quantity::kHeight;
    v.units = std::string(format::vertical_quantity_units(v.quantity));
    v.formula = source->formula;
    v.terms = source->terms;
    v.sources = source->sources;
    v.varies_in_time = source->varies_in_time;
    v.dtype = DType::kFloat32;
    v.codec = codec;
    v.codec.predictor = format::kPredictorLorenzo3;
    v.codec.fpzip = false;
    v.codec.zfp = std::nullopt;
    up = up_per_level(catalog, scan, *source);
  } else if (catalog.curvilinear) {
    up = up_along_axis(catalog.z);
  }
  if (catalog.surface) g.surface = format::SurfaceGeometry{catalog.surface->variable, "m"};
  g.orientation = horizontal_sign(catalog) * up;
  return g;
}

}  // namespace strielad::build
