// SPDX-License-Identifier: Apache-2.0
// Mesh output frames beyond the dataset's axis coordinates (formats/scene.md, "Output
// frames"). Every frame but `axis` places a vertex by its true position: longitude and
// latitude from the grid's axes (through the grid mapping's PROJ pipeline on a
// projected or rotated-pole grid: geo/grid_projection.h; on a curvilinear grid from its
// columns' stored coordinates, bilinear between them) and a height in metres from the
// vertical placement below.
// - kLonLat: true longitude and latitude in degrees, height in metres. On a mapped grid
//   longitudes are continuous about the domain's centre (they tear only at the meridian
//   opposite it, inside domains that enclose a pole).
// - kLocalMetric: metres on the plane tangent at the domain's centre (equirectangular:
//   x = R cos(lat0) (lon - lon0), y = R (lat - lat0), z = height; R = 6371008.8 m, the
//   IUGG mean Earth radius). Distances are exact along meridians and the centre
//   parallel; elsewhere east-west distances are off by cos(lat)/cos(lat0) - 1.
// - kEcef: geocentric WGS84 metres (a = 6378137 m, f = 1/298.257223563), heights taken
//   as ellipsoidal heights; a longitude and the same longitude a turn on land on the same
//   bits.
// Normals are transformed as gradients (by the inverse transpose of the map's Jacobian)
// and renormalized; triangle orientation is kept outward.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "format/curvilinear_lonlat.h"
#include "extract/mesh.h"
#include "format/manifest.h"
#include "geo/grid_projection.h"

namespace strielad {

class Store;

enum class OutputFrame { kAxis, kLonLat, kLocalMetric, kEcef };

// "axis", "lonlat", "metric" or "ecef"; throws kInvalidArgument listing them.
OutputFrame parse_output_frame(std::string_view name);
std::string_view output_frame_name(OutputFrame frame);

// How a vertex gets its height in metres.
struct VerticalPlacement {
  enum class Kind {
    kHeightAxis,          // the z axis is a height (m or km)
    kHeightVariable,      // a variable of the store holds geopotential or height per sample
    kStandardAtmosphere,  // the z axis is a pressure: the ICAO standard atmosphere's height
    // The store's grid geometry (terrain-following levels): a height or pressure per
    // sample carried as the attribute format::geometry_field_name() (a pressure placed by
    // the standard atmosphere), or a height or pressure per level of the z axis.
    kGeometry,
  };
  Kind kind = Kind::kHeightAxis;
  std::string variable;       // kHeightVariable: the store variable (carried as an attribute)
  double metres_per_unit = 1; // axis units (height axis) or variable units to metres
  std::string description;    // one line for logs and output metadata
  // kGeometry: the attribute (a per-sample field), or empty for per-level values.
  std::string attribute;
  bool pressure = false;         // kGeometry: the values are pressures in Pa
  std::vector<double> levels;    // kGeometry per level: one height (m) or pressure (Pa) per z
  int vertical_sign = 1;         // kGeometry: sign of d(height) / d(z axis value)
};

// The variables a vertical placement would use, in order of preference: `zg`, `gh`,
// `geopotential_height`, `hgt`, `z`, `phi`, `geopotential` (by name or standard_name
// geopotential_height / geopotential / height / altitude), with units m, gpm, km, dam
// or m2 s-2 (geopotential: divided by g0 = 9.80665 m s-2).
// The placement of store `m`: its grid geometry when it records a vertical one (an error
// with `height_var`: the geometry places heights); else the height axis; else
// `height_var` when given (an error
// naming it when the store does not have it or its units are not a height or a
// geopotential); else the first variable above; else, on a pressure axis, the standard
// atmosphere.
// \error kUnsupported naming the axis for a vertical axis with none of these (model levels
// without a height variable, depth, unknown axes).
VerticalPlacement choose_vertical_placement(const format::Manifest& m,
                                            std::optional<std::string> height_var = std::nullopt);

// Moves meshes of one store from axis coordinates into a frame. Not shared between
// threads (it holds a PROJ object): make one per thread.
class FrameTransform {
 public:
  // A curvilinear store (index axes) is placed by its GEOMETRY coordinates
  // (Store::horizontal_coordinates), bilinear between columns (format/curvilinear_lonlat.h).
  // \error kUnsupported when the frame needs a place on the Earth the store's grid does
  // not have (a Cartesian grid without a grid mapping: only `axis`, and `metric` when its
  // axes are metres, work), naming the axes; for a curvilinear store without
  // `coordinates`, naming GEOMETRY.
  FrameTransform(const format::Manifest& manifest, OutputFrame frame, VerticalPlacement vertical,
                 std::shared_ptr<const format::HorizontalCoordinates> coordinates = nullptr);
  // The store's manifest, and its GEOMETRY coordinates when its grid is curvilinear (read
  // then, and only then).
  FrameTransform(const Store& store, OutputFrame frame, VerticalPlacement vertical);

  OutputFrame frame() const { return frame_; }
  // Whether the map from axis coordinates is affine (the axis frame; lonlat and metric of
  // a longitude/latitude grid on a height axis): straight lattice lines stay straight, so
  // merged face rectangles stay exact (ExtractRequest::merge_face_squares).
  bool affine() const;
  const VerticalPlacement& vertical() const { return vertical_; }
  // Whether apply replaces every normal by the placed surface's own (heights from a
  // field): the meshes need none in axis coordinates (ExtractRequest::axis_normals).
  bool replaces_normals() const { return frame_ != OutputFrame::kAxis && placed_surface(); }

  // Positions and normals of `mesh`, from axis coordinates into the frame. With a height
  // variable or a geometry field the mesh must carry it as an attribute (by its name).
  // \error kInvalidArgument naming the variable when the mesh lacks that attribute.
  void apply(Mesh& mesh) const;

  // True longitude, latitude (degrees) and height (metres) of one axis position; a
  // height variable's value `height` (in its units) when the placement uses one.
  std::array<double, 3> lon_lat_height(const std::array<double, 3>& axis,
                                       double height = 0) const;

 private:
  // A position in the frame and the Jacobian columns (d/dx, d/dy, d/dz) of the map there.
  struct MappedPoint {
    std::array<double, 3> p, cx, cy, cz;
  };
  // Axis position q (and the height variable's value hv there) through the map.
  MappedPoint map_point(const std::array<double, 3>& q, double hv) const;
  // map_point's position alone (the same bits), without the Jacobian.
  std::array<double, 3> position(const std::array<double, 3>& q, double hv) const;
  std::array<double, 3> cartesian_position(const std::array<double, 3>& q, double hv) const;
  const std::vector<float>* placing_heights(const Mesh& mesh) const;
  // A mapped or curvilinear grid's longitude (continuous about lon0_) and latitude at
  // axis (x, y), its Jacobian there and, where the frame's Jacobian is the same at every
  // height of the column (column_normals), the terms that carry a normal through it:
  // computed once per column of vertices (the same bits of x and y) while the column
  // stays in the cache, with the same bits as computing them per vertex.
  struct Column {
    std::uint64_t x = 0, y = 0;  // the bits of x and y
    bool used = false, has_jacobian = false, has_normal_terms = false;
    std::array<double, 2> lonlat{};
    std::array<double, 4> jacobian{};
    // transform_normal's cross products of the frame's Jacobian columns, and its
    // determinant.
    std::array<std::array<double, 3>, 3> normal_terms{};
    double det = 0;
    // The last normals carried through (by their bits; a face's vertices along a column
    // share one), kNormalMemo slots used in turn.
    std::array<std::array<std::array<float, 3>, 2>, 4> normal_memo{};
    std::uint8_t memo_used = 0, memo_next = 0;
  };
  static constexpr int kColumnBits = 12;
  Column& column(double x, double y) const;
  const std::array<double, 4>& column_jacobian(double x, double y) const;
  // Whether vertices are mapped column by column: a mapped or curvilinear grid placed in
  // lonlat or metric on its height axis, normals transformed (not replaced).
  bool column_normals() const;
  // The heights of vertices `first`.. of `mesh` (longitude and latitude kept).
  void place_heights(Mesh& mesh, const std::vector<float>* heights, std::size_t first) const;
  // apply for column_normals: positions and normals through the column's cached terms.
  void apply_by_columns(Mesh& mesh) const;
  // Whether heights come from a mesh attribute; whether normals are the placed surface's.
  bool placed_by_attribute() const;
  bool placed_surface() const;
  double level_value(double z) const;  // kGeometry per level
  // The height in metres at axis value z (a height variable's or geometry field's value
  // `height` there, when the placement uses one).
  double height_m(double z, double height) const;

  OutputFrame frame_;
  VerticalPlacement vertical_;
  const format::Manifest* manifest_;
  geo::GridProjection projection_;
  std::optional<CurvilinearLonLat> curvilinear_;  // a curvilinear grid's columns
  bool geographic_ = false;  // x, y are longitude and latitude (directly or by a mapping)
  double lon0_ = 0, lat0_ = 0;  // the domain's centre
  double z_unit_ = 1;           // axis units to metres or pascals
  double jacobian_step_ = 0;    // central-difference step of the mapping (axis units)
  // A Cartesian grid (neither geographic nor mapped): metres per axis unit, the centre.
  std::array<double, 2> cartesian_scale_{1, 1}, cartesian_centre_{0, 0};
  // apply's per-vertex sums of face normals (scratch, kept between meshes).
  mutable std::vector<std::array<double, 3>> normal_sums_;
  mutable std::vector<Column> columns_;  // kColumnBits-bit direct-mapped cache
};

// One-shot form for tests and single meshes: the store's vertical placement by default.
void transform_mesh(Mesh& mesh, const format::Manifest& manifest, OutputFrame frame);

}  // namespace strielad
