// SPDX-License-Identifier: Apache-2.0
// The world frame the viewer renders in and the level-of-detail cut measures in: a
// right-handed frame in kilometres, x east, y north, z up, origin at the domain's
// horizontal centre and height 0 (sea level or ground, as the height axis says).
//
// Horizontal placement, by what the store's x and y are (HorizontalMap):
// - kGeographic, longitude/latitude axes: an equirectangular plane tangent at the domain
//   centre (lon0, lat0): x = (lon - lon0) * K * cos(lat0), y = (lat - lat0) * K with
//   K = 111.195 km per degree (R = 6371.0088 km, the IUGG mean radius, as the "metric"
//   output frame of formats/scene.md). lon0/lat0 are the midpoints of the axes' ranges.
//   Each axis maps by itself.
// - kMapped, map-projection axes with a grid mapping (a rotated pole in degrees, a
//   projected grid in m or km; Manifest::grid_mapping): the same plane on TRUE longitude
//   and latitude, reached through the mapping's PROJ pipeline (geo/grid_projection.h),
//   tangent at the true position of the centre of the axes' ranges (as the "metric"
//   output frame, in km). x and y do not map separately: a grid line is a curve in the
//   world. Longitudes are taken the short way round from lon0; a grid whose image folds
//   or tears (it crosses the meridian opposite its centre, or encloses a pole) is refused.
// - kCurvilinear, a curvilinear grid (index axes placed by the store's 2-D longitudes and
//   latitudes, format/curvilinear_lonlat.h; the constructor's horizontal_coordinates, from
//   Store::horizontal_coordinates): the same plane, tangent at the true position of
//   the grid's centre index. The plane is affine in longitude and latitude, so positions
//   between columns are the bilinear interpolation of the columns' plane positions
//   (lod/curvilinear_plane.h) and a cell's edges are straight. A grid that folds or
//   crosses the meridian opposite its centre is refused, as on mapped frames.
// - kMetric, a Cartesian grid in m or km without a grid mapping: kilometres from the
//   range midpoints. It has no place on the Earth: on_earth() is false, and terrain,
//   flight tracks and the true sun cannot be placed on it.
// Vertical, the same on every frame and separable:
// - height (m or km; no units means metres): z = height_km * vertical_exaggeration.
// - pressure (Pa, hPa, mbar, kPa, bar, atm): the ICAO standard atmosphere height of the
//   pressure (geo/standard_atmosphere.h), then as height.
// - terrain-following levels (a store with a grid geometry, formats/store.md "Grid geometry
//   (version 5)"): a table of one representative height in metres per level-0 z sample,
//   strictly monotonic (VerticalMap::kLevelHeights). z maps piecewise-linearly between the
//   table's heights in the axis's value (a model-level index, a hybrid coordinate ...),
//   linearly continued beyond the ends. A geometry of `levels` gives the table itself
//   (pressures through the standard atmosphere); a per-sample geometry field needs the
//   caller's table (the constructor's level_heights_m, e.g. the field's column at the
//   domain's centre: view/level_heights.h), as the field's own heights vary from column to
//   column and only the vertices placed by it (view/height_placement.h) are exact.
// Descending axes (latitude north to south, height top down, pressure) map the same way:
// world coordinates do not depend on storage order.
//
// The globe (FrameShape::kGlobe, or kAuto on a wide or global domain; frames on the Earth
// only): world = WGS84 earth-centred, earth-fixed kilometres (lod/wgs84_globe.h: origin at
// the Earth's centre, x towards 0 N 0 E, y towards 0 N 90 E, z towards the north pole) of
// the true longitude and latitude of the plane's position, at the height vertical_to_world
// (exaggerated) above the ellipsoid. "Up" is the ellipsoid normal (up_at), not z. The
// plane stays the frame's intermediate: geographic_bounds, lon0 and lat0 keep their
// meaning; the 2-D geographic_to_world and world_to_geographic (plane x/y) refuse on a
// globe: place_geographic and geographic_of place in 3-D on either shape.
//
// Thread safety: const members may be called from any thread (a mapped frame runs PROJ
// through a per-thread GridProjection).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "format/geometry_file_format.h"
#include "format/manifest.h"
#include "lod/curvilinear_plane.h"
#include "lod/geometry.h"
#include "octree/octree_layout.h"

namespace strielad::lod {

// Atmospheric domains are flat: the paper's grid spans about 700 x 780 km horizontally
// and 21 km vertically, so at true scale its whole depth is 3% of its width and clouds
// are slivers in any view that shows the domain. Ten times lifts the 0-12 km cloud layer
// to about a sixth of the width, still flat enough that horizontal structure reads
// as a map. One number for all data sets so that views and camera paths compare.
inline constexpr double kDefaultVerticalExaggeration = 10.0;

// Kilometres per degree of latitude (and of longitude at the equator).
inline constexpr double kKmPerDegree = 6371.0088 * std::numbers::pi / 180.0;

// The shape of the world: the tangent plane (above), or the WGS84 globe (below).
enum class FrameShape { kPlane, kGlobe, kAuto };

// kAuto chooses the globe for a frame on the Earth whose longitude or latitude extent
// exceeds this many degrees (every global data set does); smaller domains keep the plane.
// At 30 degrees the tangent plane misplaces the domain's corners by about 1% of its width
// (cos of 15 degrees off the tangent point), and the curvature shows in a view.
inline constexpr double kGlobeMinExtentDeg = 30.0;

struct WorldFrameOptions {
  double vertical_exaggeration = kDefaultVerticalExaggeration;  // finite, > 0
  FrameShape shape = FrameShape::kPlane;
};

enum class HorizontalMap { kGeographic, kMapped, kMetric, kCurvilinear };
enum class VerticalMap { kHeight, kPressure, kLevelHeights };

// True longitude/latitude extent of a domain (degrees): longitudes continuous about the
// domain's centre (lon_lo may be < -180 or lon_hi > 180), lon_lo <= lon_hi.
struct GeographicBounds {
  double lon_lo = 0, lon_hi = 0, lat_lo = 0, lat_hi = 0;
};

class WorldFrame {
 public:
  // \error kUnsupported naming the axis for axes without a world position: x/y neither
  // longitude/latitude, nor mapped by a grid mapping, nor in length units; a vertical
  // axis that is neither height nor pressure (model levels, depth, unknown) and has no
  // level heights, or has units it cannot convert; a store whose geometry is a per-sample
  // field given no level_heights_m; a grid mapping PROJ rejects, that leaves a sample without a
  // geographic position, or whose image folds or crosses the meridian opposite the
  // domain's centre (naming the sample); a curvilinear store given no
  // horizontal_coordinates (or coordinates of another size), or whose columns fold or
  // cross the meridian opposite the centre on the plane.
  // \error kInvalidInput for empty, non-finite or non-monotonic axis values (as
  // check_axis_values) and for a pressure axis with a value <= 0.
  // \error kInvalidArgument for a vertical exaggeration that is not finite and > 0, and for
  // level_heights_m not one finite, strictly monotonic value per z sample.
  // `level_heights_m`: one representative height in metres per level-0 z sample, strictly
  // monotonic: the vertical map of a terrain-following store (VerticalMap::kLevelHeights).
  // Empty: the axis's own map, or the manifest's geometry `levels`.
  // `horizontal_coordinates`: a curvilinear store's GEOMETRY coordinates
  // (Store::horizontal_coordinates); ignored for other stores.
  explicit WorldFrame(
      const format::Manifest& manifest, WorldFrameOptions options = {},
      std::vector<double> level_heights_m = {},
      std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates = nullptr);
  // The same frame at another vertical exaggeration, without redoing the horizontal
  // placement (a mapped frame's sample table is shared).
  // \error kInvalidArgument for an exaggeration that is not finite and > 0.
  WorldFrame with_exaggeration(double vertical_exaggeration) const;

  // Axis coordinates (x, y, z of the manifest, in the axes' own units) to world km.
  // Pressures <= 0 give NaN in z (callers check them: camera_path.h does); on a mapped
  // frame, a position the mapping cannot place gives NaN in x and y.
  Vec3 to_world(const Vec3& axis) const;
  // World km back to axis coordinates (the exact inverse up to rounding); NaN in x and y
  // on a mapped frame where the world point has no latitude (beyond the poles) or the
  // mapping no inverse.
  Vec3 to_axis(const Vec3& world) const;
  // Whether the world is the WGS84 globe (ECEF km) rather than the tangent plane.
  bool globe() const { return globe_; }
  // The local up direction (unit) at world position `world`: +z on the plane, the
  // ellipsoid normal on the globe.
  Vec3 up_at(const Vec3& world) const;
  // True longitude/latitude (degrees) at world height `world_height` (km, exaggerated, as
  // vertical_to_world gives) to world km on either shape. \error as geographic_to_world.
  Vec3 place_geographic(double lon, double lat, double world_height) const;
  // The inverse: {longitude continuous about lon0, latitude, world height}.
  // \error as geographic_to_world.
  Vec3 geographic_of(const Vec3& world) const;
  // The vertical map alone (every frame's z maps by itself; on the globe, the height
  // above the ellipsoid).
  double vertical_to_world(double z) const;
  double world_to_vertical(double world_z) const;

  // A unit normal at axis position `axis` (axis coordinates) to the world frame: the
  // inverse transpose of the map's Jacobian, renormalized; straight up when it vanishes.
  Vec3 normal_to_world(const Vec3& axis, const Vec3& normal) const;
  // True when the map reverses orientation (an odd number of decreasing axis maps, e.g.
  // a pressure axis, or a horizontal Jacobian of negative determinant).
  bool mirrored() const { return mirrored_; }

  // Whether the frame has a place on the Earth (geographic, mapped and curvilinear frames).
  bool on_earth() const { return horizontal_ != HorizontalMap::kMetric; }
  // Why not, naming the axes, for the errors of callers that need it ("axes 'x' (m) and
  // 'y' (m) are Cartesian coordinates without a grid_mapping ..."); "" when on_earth().
  const std::string& no_earth_reason() const { return no_earth_reason_; }
  // True longitude/latitude (degrees) to world x/y km, the longitude taken the short way
  // round from lon0. \error kUnsupported with no_earth_reason() when !on_earth(), and on
  // a globe (where a position needs its height: place_geographic).
  std::array<double, 2> geographic_to_world(double lon, double lat) const;
  // World x/y km to true longitude/latitude (longitude continuous about lon0; latitude
  // beyond +-90 where the plane is beyond the poles). \error as geographic_to_world.
  std::array<double, 2> world_to_geographic(double x, double y) const;
  // True longitude/latitude to the store's axis x/y (NaN where the mapping has none).
  // \error as geographic_to_world.
  std::array<double, 2> geographic_to_axis(double lon, double lat) const;
  // The true position of the plane's tangent point (degrees). \error as geographic_to_world.
  double lon0() const;
  double lat0() const;
  // The true longitude/latitude box of the domain (the world box's corners through the
  // plane). \error as geographic_to_world.
  GeographicBounds geographic_bounds() const;

  // World x/y of level-0 sample (i, j) (precomputed; on a mapped frame through PROJ).
  std::array<double, 2> sample_world_xy(std::size_t i, std::size_t j) const;
  // World z of level-0 sample `k` of the vertical axis.
  double sample_world_z(std::size_t k) const { return z_samples_[k]; }
  Dims3 dims() const { return dims_; }
  // The smallest and largest axis values of x and y: {x lo, x hi, y lo, y hi}.
  const std::array<double, 4>& axis_ranges() const { return axis_ranges_; }
  // The box that holds every point of the grid: on a mapped frame the box of the
  // boundary's image, padded as node_world_boxes pads; on a globe an ECEF box.
  const WorldBox& domain() const { return domain_; }
  // The box of the level-0 index box `box` (inclusive sample indices) as
  // node_world_boxes computes it.
  WorldBox index_box_world(const IndexBox& box) const;

  HorizontalMap horizontal() const { return horizontal_; }
  // Whether x and y map together (mapped and curvilinear frames): a grid line is a curve
  // or a polyline in the world, and the domain is the axes' box in axis x/y, not a box of
  // the world.
  bool bends_grid_lines() const {
    return horizontal_ == HorizontalMap::kMapped || horizontal_ == HorizontalMap::kCurvilinear;
  }
  VerticalMap vertical() const { return vertical_; }
  double vertical_exaggeration() const { return exaggeration_; }
  // Kilometres per axis unit of x or y when they are lengths (Cartesian or projected:
  // map coordinates, not distances on the ground); 0 for degrees (longitude/latitude,
  // a rotated pole) and for a curvilinear grid's index axes.
  double axis_length_km(int axis) const { return axis_km_[axis]; }
  // Metres (height) or pascals (pressure) per unit of the vertical axis; with level
  // heights, the mean metres per unit over the axis (negative where heights fall as the
  // axis's value grows, as on model levels counted from the top).
  double vertical_unit() const { return vertical_unit_; }
  // kLevelHeights: the table's heights in metres, one per z sample; empty otherwise.
  const std::vector<double>& level_heights_m() const { return level_heights_m_; }
  // "longitude/latitude axes", "grid mapping 'rotated_pole' (rotated_latitude_longitude)
  // through PROJ, centred at 50.75 N, 18.00 E", "Cartesian axes 'x' and 'y' (m) ...".
  std::string describe_horizontal() const;

 private:
  struct Mapped;  // a mapped frame's pipeline and sample table (shared by copies)

  // Parts of the constructor.
  // The plane (the constructor but the shape).
  void place(const format::Manifest& manifest, std::vector<double> level_heights_m,
             const std::shared_ptr<const format::HorizontalCoordinates>& coordinates);
  void place_horizontal(const format::Manifest& manifest);
  // Also samples z and sets the domain's z range.
  void place_vertical(const format::Manifest& manifest, std::vector<double> level_heights_m);
  void place_level_heights(const Axis& z, std::vector<double> heights_m);
  void place_mapped(const format::Manifest& manifest, bool z_negative);
  void place_curvilinear(const format::Manifest& manifest, bool z_negative,
                         const std::shared_ptr<const format::HorizontalCoordinates>& coordinates);

  // The plane's maps (the whole frame on the plane; the globe's first step).
  Vec3 plane_to_world(const Vec3& axis) const;
  Vec3 plane_to_axis(const Vec3& plane) const;
  Vec3 plane_normal(const Vec3& axis, const Vec3& normal) const;
  WorldBox plane_index_box(const IndexBox& box) const;
  std::array<double, 2> plane_of_geographic(double lon, double lat) const;
  std::array<double, 2> geographic_of_plane(double x, double y) const;
  // The globe's (world_frame_globe.cpp).
  void choose_shape(FrameShape shape);
  Vec3 plane_to_globe(const Vec3& plane) const;
  Vec3 globe_to_plane(const Vec3& world) const;
  Vec3 globe_normal(const Vec3& plane, const Vec3& plane_normal) const;
  WorldBox globe_index_box(const IndexBox& box) const;
  void check_plane(const char* what) const;

  double separable_to_world(int axis, double value) const;
  double separable_to_axis(int axis, double world) const;
  void check_on_earth() const;
  std::array<double, 2> mapped_xy(double x, double y) const;
  WorldBox mapped_index_box(const IndexBox& box) const;

  HorizontalMap horizontal_ = HorizontalMap::kGeographic;
  VerticalMap vertical_ = VerticalMap::kHeight;
  double exaggeration_ = kDefaultVerticalExaggeration;
  std::array<double, 2> origin_{};       // separable frames: axis value of the origin
  std::array<double, 2> km_per_unit_{};  // separable frames: world km per axis unit
  std::array<double, 2> axis_km_{};      // see axis_length_km
  std::array<double, 4> axis_ranges_{};
  double lon0_ = 0, lat0_ = 0;           // frames on the Earth: the tangent point
  double km_per_lon_ = 0;                // K cos(lat0)
  double vertical_unit_ = 1.0;  // metres (height) or pascals (pressure) per axis unit
  bool mirrored_ = false;
  std::string no_earth_reason_;
  std::string axis_names_;      // for describe_horizontal
  Dims3 dims_;
  std::array<std::vector<double>, 2> xy_samples_;  // separable frames
  std::vector<double> z_axis_, z_samples_;
  std::vector<double> level_heights_m_;  // kLevelHeights
  std::shared_ptr<const Mapped> mapped_;
  std::shared_ptr<const CurvilinearPlane> curvilinear_;
  std::string curvilinear_what_;  // "curvilinear grid ('lon' / 'lat')"
  WorldBox domain_;
  WorldBox plane_domain_;  // the domain on the plane (the same as domain_ off the globe)
  bool globe_ = false;
};

// The world box of every octree node, indexed by NodeId: spanned by the node's brick's
// corner samples (OctreeLayout::fine_box) on geographic and Cartesian frames, so a
// child's box lies inside its parent's and neighbours share faces. On a mapped frame the
// horizontal box is the box of the images of every level-0 sample on the brick's
// horizontal boundary, padded per side by twice the estimated bow of the boundary
// curves between samples (h^2 / 8 max|f''|, with f'' from the samples' second
// differences along each grid line): the image of a grid cell's edge is a curve, not the
// chord between its samples. A map without folds sends the brick's interior inside the
// image of its boundary, so every placed vertex of the node's meshes is in its box.
// On a globe the box is that of the ECEF images of the brick's horizontal boundary samples
// at its bottom and top heights, padded for the bulge of the ellipsoid over the brick:
// (a + h_top)(1 - cos alpha) + (a - b) alpha, alpha the largest angle at the Earth's centre
// between the brick's centre sample and a point of its boundary (a boundary sample's angle
// plus the largest step between neighbouring boundary samples, and 0.2 degrees for the
// ellipsoid normal's tilt from the radius), clamped to the sphere of radius a + h_top.
// \error kInvalidArgument when the layout's grid is not the frame's dims.
std::vector<WorldBox> node_world_boxes(const OctreeLayout& layout, const WorldFrame& frame);

}  // namespace strielad::lod
