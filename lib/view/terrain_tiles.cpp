// SPDX-License-Identifier: Apache-2.0
#include "view/terrain_tiles.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "lod/frustum.h"

namespace strielad::view {
namespace {

// Heights of the DEM at every (col, row) of two index lists, each a lattice of constant
// step except maybe its first and last entries: read as up to nine strided windows.
std::vector<float> read_grid(const geo::DemSource& dem, const std::vector<std::size_t>& cols,
                             const std::vector<std::size_t>& rows) {
  // Split an index list into runs of constant step.
  const auto runs = [](const std::vector<std::size_t>& v) {
    std::vector<std::pair<std::size_t, std::size_t>> out;  // first index in v, count
    std::size_t i = 0;
    while (i < v.size()) {
      std::size_t j = i + 1;
      if (j < v.size() && v[j] > v[i]) {
        const std::size_t step = v[j] - v[i];
        while (j + 1 < v.size() && v[j + 1] - v[j] == step) ++j;
        ++j;
      }
      out.emplace_back(i, j - i);
      i = j;
    }
    return out;
  };
  std::vector<float> out(cols.size() * rows.size(), NAN);
  for (const auto& [ci, cn] : runs(cols)) {
    for (const auto& [ri, rn] : runs(rows)) {
      const std::size_t cstep = cn > 1 ? cols[ci + 1] - cols[ci] : 1;
      const std::size_t rstep = rn > 1 ? rows[ri + 1] - rows[ri] : 1;
      // One stride for both axes per read: equal steps read together, else row by row.
      if (cstep == rstep || rn == 1 || cn == 1) {
        const std::size_t s = cn > 1 ? cstep : rstep;
        const auto v = dem.read({cols[ci], rows[ri], cn, rn, std::max<std::size_t>(s, 1)});
        for (std::size_t r = 0; r < rn; ++r) {
          for (std::size_t c = 0; c < cn; ++c) out[(ri + r) * cols.size() + ci + c] = v[r * cn + c];
        }
      } else {
        for (std::size_t r = 0; r < rn; ++r) {
          const auto v = dem.read({cols[ci], rows[ri + r], cn, 1, cstep});
          for (std::size_t c = 0; c < cn; ++c) out[(ri + r) * cols.size() + ci + c] = v[c];
        }
      }
    }
  }
  return out;
}

double box_distance(const lod::WorldBox& box, const Vec3& p) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({box.lo[a] - p[a], 0.0, p[a] - box.hi[a]});
    d2 += d * d;
  }
  return std::sqrt(d2);
}

// Sea: a sample without a value, or below sea level (a DEM with bathymetry: ETOPO,
// GEBCO). Land below sea level (the Dead Sea's shores, polders) is taken for sea too: a
// height alone does not tell them apart.
bool is_water(float metres) { return !(metres >= 0.0f); }

constexpr float kFarOutside = 3.0e38f;

// `lon` moved by whole turns into [reference - 180, reference + 180].
double near_longitude(double lon, double reference) {
  while (lon < reference - 180) lon += 360;
  while (lon > reference + 180) lon -= 360;
  return lon;
}

// A DEM on a longitude/latitude grid that goes all the way round: longitude affine in
// the column (the same step on every row), latitude independent of it, and at least one
// full turn of columns. Its columns per turn, the longitude of column 0 and the step.
struct GlobalColumns {
  std::size_t per_turn = 0;  // 0: not such a DEM
  double lon0 = 0, step = 0;
};

GlobalColumns global_columns(const geo::DemSource& dem) {
  const std::size_t w = dem.width(), h = dem.height();
  if (w < 4) return {};
  const std::vector<double> probe_cols{0.0, 1.0, double(w / 3), double(w / 2), double(w - 1)};
  const std::vector<double> probe_rows{0.0, double(h / 2), double(h - 1)};
  std::vector<double> cs, rs;
  for (const double r : probe_rows) {
    for (const double c : probe_cols) {
      cs.push_back(c);
      rs.push_back(r);
    }
  }
  std::vector<geo::LonLat> ll(cs.size());
  dem.georeference(cs, rs, ll);
  const double step = near_longitude(ll[1].lon - ll[0].lon, 0.0);
  if (!(std::fabs(step) > 0) || !std::isfinite(step)) return {};
  const double turn = 360.0 / std::fabs(step);
  const auto per_turn = static_cast<std::size_t>(std::llround(turn));
  if (std::fabs(turn - double(per_turn)) > 1e-4 * turn || per_turn > w || per_turn < 4) return {};
  const double tolerance = 1e-3 * std::fabs(step);
  for (std::size_t r = 0; r < probe_rows.size(); ++r) {
    const auto* row = &ll[r * probe_cols.size()];
    for (std::size_t c = 0; c < probe_cols.size(); ++c) {
      const double expected = ll[0].lon + probe_cols[c] * step;
      if (std::fabs(near_longitude(row[c].lon - expected, 0.0)) > tolerance ||
          std::fabs(row[c].lat - row[0].lat) > tolerance) {
        return {};
      }
    }
  }
  return {per_turn, ll[0].lon, step};
}

lod::WorldBox exaggerated(lod::WorldBox box, double e) {
  box.lo[2] *= e;
  box.hi[2] *= e;
  return box;
}

// A globe tile's ECEF box, its heights (at most top_km as placed) drawn `ratio` times
// as high: each vertex moves by at most top_km |ratio - 1| along its ellipsoid normal.
lod::WorldBox redrawn_on_globe(lod::WorldBox box, double top_km, double ratio) {
  const double reach = top_km * std::fabs(ratio - 1.0);
  for (int a = 0; a < 3; ++a) {
    box.lo[a] -= reach;
    box.hi[a] += reach;
  }
  return box;
}

// The DEM's samples inside the store's axis box (each sample's true lon/lat through the
// frame's inverse map), found on a lattice of at most 512 x 512 samples: their column and
// row range, and the lattice step (the caller widens the range by one step).
struct DemOverlap {
  std::size_t c0 = 0, c1 = 0, r0 = 0, r1 = 0;
  std::size_t step = 1;
};

// \error kInvalidInput when no lattice sample falls inside the store's axis box.
DemOverlap dem_overlap(const geo::DemSource& dem, const lod::WorldFrame& frame,
                       const lod::GeographicBounds& bounds) {
  const auto axes = frame.axis_ranges();
  const std::size_t w = dem.width(), h = dem.height();
  const std::size_t step = std::max<std::size_t>(1, (std::max(w, h) + 511) / 512);
  std::vector<double> cs, rs;
  for (std::size_t r = 0; r < h; r += step) {
    for (std::size_t c = 0; c < w; c += step) {
      cs.push_back(double(c));
      rs.push_back(double(r));
    }
  }
  std::vector<geo::LonLat> ll(cs.size());
  dem.georeference(cs, rs, ll);
  std::size_t c0 = w, c1 = 0, r0 = h, r1 = 0;
  double dem_lon_min = INFINITY, dem_lon_max = -INFINITY, dem_lat_min = INFINITY, dem_lat_max = -INFINITY;
  const double o = frame.lon0();
  for (std::size_t i = 0; i < ll.size(); ++i) {
    const double lon = o + std::remainder(ll[i].lon - o, 360.0);
    dem_lon_min = std::min(dem_lon_min, lon);
    dem_lon_max = std::max(dem_lon_max, lon);
    dem_lat_min = std::min(dem_lat_min, ll[i].lat);
    dem_lat_max = std::max(dem_lat_max, ll[i].lat);
    const auto a = frame.geographic_to_axis(ll[i].lon, ll[i].lat);
    if (a[0] >= axes[0] && a[0] <= axes[1] && a[1] >= axes[2] && a[1] <= axes[3]) {
      const auto c = static_cast<std::size_t>(cs[i]), r = static_cast<std::size_t>(rs[i]);
      c0 = std::min(c0, c);
      c1 = std::max(c1, c);
      r0 = std::min(r0, r);
      r1 = std::max(r1, r);
    }
  }
  if (c0 > c1 || r0 > r1) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the DEM (lon {:.2f} to {:.2f}, lat {:.2f} to {:.2f}) does not overlap "
                     "the store (lon {:.2f} to {:.2f}, lat {:.2f} to {:.2f})",
                     dem.describe(), dem_lon_min, dem_lon_max, dem_lat_min, dem_lat_max,
                     bounds.lon_lo, bounds.lon_hi, bounds.lat_lo, bounds.lat_hi);
  }
  return {c0, c1, r0, r1, step};
}

// The column extent of a DEM whose columns go round: the quadtree's columns count on
// past the DEM's last one (column c is the DEM's c mod per_turn), so that the extent runs
// continuously from the store's western edge to its eastern one (widened by `margin`
// degrees), wherever the DEM's own columns start, and never comes within 1.5 columns of
// the turn around the frame's central longitude `o`, where placed longitudes jump by 360
// degrees (on the plane; `whole_turn`: on the globe under a store round the Earth, where
// nothing jumps, one whole turn, its last column the first one again). Returns the first
// and last column.
std::pair<std::size_t, std::size_t> round_the_globe_columns(const GlobalColumns& global,
                                                            const lod::GeographicBounds& bounds,
                                                            double o, double margin,
                                                            bool whole_turn) {
  const double a = std::fabs(global.step);
  const double west = whole_turn ? o - 180 : std::max(bounds.lon_lo - margin, o - 180 + 1.5 * a);
  const double east = std::min(bounds.lon_hi + margin, o + 180 - 1.5 * a);
  const double lon0 = near_longitude(global.lon0, o);
  const double ca = (west - lon0) / global.step, cb = (east - lon0) / global.step;
  const auto turn = static_cast<long long>(global.per_turn);
  auto first = static_cast<long long>(std::floor(std::min(ca, cb)));
  auto last = static_cast<long long>(std::ceil(std::max(ca, cb)));
  if (whole_turn) {
    first = static_cast<long long>(std::floor(global.step > 0 ? ca : ca - double(turn)));
    last = first + turn;
  }
  if (first < 0) {
    const long long shift = (-first + turn - 1) / turn * turn;
    first += shift;
    last += shift;
  }
  return {static_cast<std::size_t>(first), static_cast<std::size_t>(last)};
}

// A tile's sample indices (columns or rows) with one more `stride` before the first and
// after the last, where [first, last] holds them (else the end sample is repeated).
std::vector<std::size_t> with_ring(const std::vector<std::size_t>& samples, std::size_t stride,
                                   std::size_t first, std::size_t last) {
  std::vector<std::size_t> out{samples.front() >= first + stride ? samples.front() - stride
                                                                 : samples.front()};
  out.insert(out.end(), samples.begin(), samples.end());
  out.push_back(std::min(samples.back() + stride, last));
  return out;
}

// The terrain's gradient (dz/dx, dz/dy) at lattice point i by central differences in the
// world frame: the plane through the neighbours in both directions (one-sided where the
// ring around the tile was clamped). `wc`: the lattice's row length.
// The same on the globe, from each sample's longitude/latitude and height (km): its
// neighbours placed on the plane tangent at the sample itself.
std::array<double, 2> local_gradient(const std::vector<geo::LonLat>& ll,
                                     const std::vector<float>& heights_m, std::size_t i,
                                     std::size_t wc) {
  const double k = lod::kKmPerDegree, cos_lat = std::cos(ll[i].lat * std::numbers::pi / 180.0);
  const auto at = [&](std::size_t j) {
    const float h = heights_m[j];
    return Vec3{std::remainder(ll[j].lon - ll[i].lon, 360.0) * k * cos_lat,
                (ll[j].lat - ll[i].lat) * k, is_water(h) ? 0.0 : h * 1e-3};
  };
  const Vec3 a = sub(at(i + 1), at(i - 1)), b = sub(at(i + wc), at(i - wc));
  const Vec3 n = cross(a, b);
  if (!(std::fabs(n[2]) > 1e-12)) return {0.0, 0.0};
  return {-n[0] / n[2], -n[1] / n[2]};
}

std::array<double, 2> surface_gradient(const std::vector<Vec3>& p, std::size_t i,
                                       std::size_t wc) {
  const auto& pl = p[i - 1];
  const auto& pr = p[i + 1];
  const auto& pd = p[i - wc];
  const auto& pu = p[i + wc];
  const Vec3 a = sub(pr, pl), b = sub(pu, pd);
  const Vec3 n = cross(a, b);
  double gx = 0, gy = 0;
  if (std::fabs(n[2]) > 1e-12) {
    gx = -n[0] / n[2];
    gy = -n[1] / n[2];
  }
  return {gx, gy};
}

// Two triangles per cell of the tile's nc x nr vertices.
void add_surface_triangles(TerrainTileMesh& mesh, std::size_t nc, std::size_t nr) {
  const auto index = [nc](std::size_t c, std::size_t r) { return std::uint32_t(r * nc + c); };
  for (std::size_t r = 0; r + 1 < nr; ++r) {
    for (std::size_t c = 0; c + 1 < nc; ++c) {
      const auto a = index(c, r), b = index(c + 1, r), cc = index(c + 1, r + 1), d = index(c, r + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, cc, a, cc, d});
    }
  }
}

// A skirt under one edge of the tile (its vertices in order): each edge vertex copied
// down to the lowest a neighbouring tile's edge can be there, less 50 m: a coarser
// neighbour's edge interpolates every 2nd, 4th ... 64th vertex of this edge (the tiles'
// sample lattices nest), so the crack against it ends at the lowest of those
// interpolations; a finer neighbour's edge runs between this edge's vertices, taken as no
// lower than the lowest of the vertex and its two neighbours. Hanging them no deeper
// keeps them out of sight under the terrain where it ends (a store's edge seen from the
// side).
void add_skirt(TerrainTileMesh& mesh, const std::vector<std::uint32_t>& edge) {
  const auto first = std::uint32_t(mesh.vertices.size() / kTerrainVertexFloats);
  const std::size_t n = edge.size();
  const auto height = [&](std::size_t i) {
    return mesh.vertices[std::size_t(edge[i]) * kTerrainVertexFloats + 2];
  };
  for (std::size_t i = 0; i < n; ++i) {
    float lowest = std::min({height(i), height(i > 0 ? i - 1 : i), height(i + 1 < n ? i + 1 : i)});
    for (std::size_t step = 2; step < 2 * n; step *= 2) {
      const std::size_t a = std::min(i / step * step, n - 1), b = std::min(a + step, n - 1);
      if (a == b) continue;
      const float t = float(i - a) / float(b - a);
      lowest = std::min(lowest, height(a) + t * (height(b) - height(a)));
    }
    const auto* src = &mesh.vertices[std::size_t(edge[i]) * kTerrainVertexFloats];
    std::vector<float> copy(src, src + kTerrainVertexFloats);
    copy[2] = lowest - 0.05f;
    mesh.vertices.insert(mesh.vertices.end(), copy.begin(), copy.end());
  }
  for (std::uint32_t k = 0; k + 1 < n; ++k) {
    mesh.indices.insert(mesh.indices.end(),
                        {edge[k], edge[k + 1], first + k + 1, edge[k], first + k + 1, first + k});
  }
}

// The vertex indices along each edge of the tile's nc x nr vertices: bottom, top, left,
// right.
std::array<std::vector<std::uint32_t>, 4> tile_edges(std::size_t nc, std::size_t nr) {
  const auto index = [nc](std::size_t c, std::size_t r) { return std::uint32_t(r * nc + c); };
  std::vector<std::uint32_t> bottom, top, left, right;
  for (std::size_t c = 0; c < nc; ++c) {
    bottom.push_back(index(c, 0));
    top.push_back(index(c, nr - 1));
  }
  for (std::size_t r = 0; r < nr; ++r) {
    left.push_back(index(0, r));
    right.push_back(index(nc - 1, r));
  }
  return {bottom, top, left, right};
}

}  // namespace

TerrainTiles::TerrainTiles(std::shared_ptr<const geo::DemSource> dem, const lod::WorldFrame& frame,
                           TerrainOptions options, std::shared_ptr<const geo::DrapeImage> drape)
    : dem_(std::move(dem)), drape_(std::move(drape)), frame_(frame), options_(options) {
  if (!frame.on_earth()) {
    throw make_error(ErrorCode::kUnsupported, "terrain {}: cannot be placed: {}",
                     dem_->describe(), frame.no_earth_reason());
  }
  if (!(options_.error_pixels > 0)) {
    throw make_error(ErrorCode::kInvalidArgument, "terrain error {} pixels: must be > 0",
                     options_.error_pixels);
  }
  const auto& d = frame.domain();
  const auto axes = frame.axis_ranges();
  globe_ = frame.globe();
  mapped_ = frame.bends_grid_lines() || globe_;
  // Clip coordinates: world x/y on a geographic frame (the domain is its world box), the
  // store's own axis x/y on a mapped one (the domain is their box, a curved shape in the
  // world).
  clip_ = d;
  if (mapped_) clip_ = {{axes[0], axes[2], 0}, {axes[1], axes[3], 0}};
  const bool whole_turn = globe_ && options_.round_the_earth;
  if (whole_turn) {  // every longitude lies in the store
    clip_.lo[0] = -std::numeric_limits<float>::max();
    clip_.hi[0] = std::numeric_limits<float>::max();
  }
  const auto bounds = frame.geographic_bounds();
  const std::size_t w = dem_->width(), h = dem_->height();
  const auto overlap = dem_overlap(*dem_, frame, bounds);
  const std::size_t step = overlap.step;
  col0_ = overlap.c0 >= step ? overlap.c0 - step : 0;
  row0_ = overlap.r0 >= step ? overlap.r0 - step : 0;
  col1_ = std::min(w - 1, overlap.c1 + step);
  row1_ = std::min(h - 1, overlap.r1 + step);
  if (const auto global = global_columns(*dem_); global.per_turn > 0) {
    const double margin = double(step) * std::fabs(global.step);
    wrap_columns_ = global.per_turn;
    std::tie(col0_, col1_) =
        round_the_globe_columns(global, bounds, frame.lon0(), margin, whole_turn);
  }
  const std::size_t cells = std::max(col1_ - col0_, row1_ - row0_);
  while ((std::size_t{kTerrainTileCells} << finest_level_) < cells) ++finest_level_;
  spdlog::info("terrain {}: {} x {} samples ({}{}), {} x {} over the store, {} levels of {}-cell "
               "tiles",
               dem_->describe(), w, h, dem_->georeferencing(),
               wrap_columns_ ? fmt::format(", {} columns round the globe", wrap_columns_) : "",
               col1_ - col0_ + 1, row1_ - row0_ + 1, finest_level_ + 1, kTerrainTileCells);
  worker_ = std::jthread([this](std::stop_token stop) { worker_loop(stop); });
}

TerrainTiles::~TerrainTiles() {
  worker_.request_stop();
  wake_.notify_all();
}

bool TerrainTiles::exists(const TerrainTileKey& k) const {
  if (k.level < 0 || k.level > finest_level_ || k.x < 0 || k.y < 0) return false;
  const std::size_t span = std::size_t{kTerrainTileCells} * stride(k.level);
  return col0_ + std::size_t(k.x) * span < col1_ && row0_ + std::size_t(k.y) * span < row1_;
}

std::vector<TerrainTileKey> TerrainTiles::children(const TerrainTileKey& k) const {
  std::vector<TerrainTileKey> out;
  if (k.level >= finest_level_) return out;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const TerrainTileKey c{k.level + 1, 2 * k.x + dx, 2 * k.y + dy};
      if (exists(c)) out.push_back(c);
    }
  }
  return out;
}

TerrainTileSamples TerrainTiles::samples(const TerrainTileKey& k) const {
  TerrainTileSamples s;
  const std::size_t st = stride(k.level), span = std::size_t{kTerrainTileCells} * st;
  const auto axis = [&](std::size_t first, std::size_t last_of_extent, int index) {
    std::vector<std::size_t> v;
    const std::size_t begin = first + std::size_t(index) * span;
    const std::size_t end = std::min(begin + span, last_of_extent);
    for (std::size_t i = begin; i < end; i += st) v.push_back(i);
    v.push_back(end);
    return v;
  };
  s.cols = axis(col0_, col1_, k.x);
  s.rows = axis(row0_, row1_, k.y);
  return s;
}

Vec3 TerrainTiles::place(const geo::LonLat& ll) const {
  if (globe_) return frame_.place_geographic(ll.lon, ll.lat, 0.0);
  const auto xy = frame_.geographic_to_world(ll.lon, ll.lat);
  return {xy[0], xy[1], 0.0};
}

std::array<float, 2> TerrainTiles::clip_coordinates(const geo::LonLat& ll,
                                                    const Vec3& world) const {
  if (!mapped_) return {float(world[0]), float(world[1])};
  const auto a = frame_.geographic_to_axis(ll.lon, ll.lat);
  // No place in the store's axes: far outside every clip box (NaN would compare
  // unpredictably on the GPU).
  if (!std::isfinite(a[0]) || !std::isfinite(a[1])) return {kFarOutside, kFarOutside};
  return {float(a[0]), float(a[1])};
}

std::size_t TerrainTiles::dem_column(std::size_t column) const {
  return wrap_columns_ ? column % wrap_columns_ : column;
}

std::vector<std::size_t> TerrainTiles::dem_columns(std::vector<std::size_t> columns) const {
  for (auto& c : columns) c = dem_column(c);
  return columns;
}

std::shared_ptr<const TerrainTileMesh> TerrainTiles::load_tile(const TerrainTileKey& key) const {
  const auto start = std::chrono::steady_clock::now();
  const auto s = samples(key);
  const std::size_t nc = s.cols.size(), nr = s.rows.size();
  // A ring of one sample (at the tile's stride) around it for the gradients.
  const std::size_t st = stride(key.level);
  // Columns that go round stay within the extent (beyond it longitudes may jump).
  const std::size_t first_col = wrap_columns_ ? col0_ : 0;
  const std::size_t last_col = wrap_columns_ ? col1_ : dem_->width() - 1;
  const auto cols = with_ring(s.cols, st, first_col, last_col);
  const auto rows = with_ring(s.rows, st, 0, dem_->height() - 1);
  const std::size_t wc = cols.size(), wr = rows.size();
  const auto heights = read_grid(*dem_, dem_columns(cols), rows);
  std::vector<double> cd(wc * wr), rd(wc * wr);
  for (std::size_t r = 0; r < wr; ++r) {
    for (std::size_t c = 0; c < wc; ++c) {
      cd[r * wc + c] = double(dem_column(cols[c]));
      rd[r * wc + c] = double(rows[r]);
    }
  }
  std::vector<geo::LonLat> ll(wc * wr);
  dem_->georeference(cd, rd, ll);
  std::vector<Vec3> p(wc * wr);
  double top_km = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Water (no value, or below sea level) lies flat at sea level.
    const double km = is_water(heights[i]) ? 0.0 : heights[i] * 1e-3;
    if (globe_) {
      top_km = std::max(top_km, km * frame_.vertical_exaggeration());
      p[i] = frame_.place_geographic(ll[i].lon, ll[i].lat, km * frame_.vertical_exaggeration());
    } else {
      p[i] = place(ll[i]);
      p[i][2] = km;
    }
  }
  auto mesh = std::make_shared<TerrainTileMesh>();
  mesh->key = key;
  // Unique across every TerrainTiles: a renderer that draws the tiles of one after
  // another's must not take a new tile for a cached one.
  static std::atomic<std::uint64_t> serials{0};
  mesh->serial = ++serials;
  // Drape: texture coordinates for the tile's own vertices.
  std::vector<geo::LonLat> inner;
  inner.reserve(nc * nr);
  for (std::size_t r = 0; r < nr; ++r) {
    for (std::size_t c = 0; c < nc; ++c) inner.push_back(ll[(r + 1) * wc + c + 1]);
  }
  std::vector<float> u(nc * nr, -1.0f), v(nc * nr, -1.0f);
  if (drape_) mesh->drape = drape_->read(inner, u, v);
  lod::WorldBox box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  mesh->vertices.reserve((nc * nr + 2 * (nc + nr)) * kTerrainVertexFloats);
  for (std::size_t r = 0; r < nr; ++r) {
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t i = (r + 1) * wc + (c + 1);
      const auto [gx, gy] = globe_ ? local_gradient(ll, heights, i, wc) : surface_gradient(p, i, wc);
      const bool water = is_water(heights[i]);
      const float x = float(p[i][0]), y = float(p[i][1]), z = float(p[i][2]);
      const auto clip = clip_coordinates(ll[i], p[i]);
      mesh->vertices.insert(mesh->vertices.end(),
                            {x, y, z, float(gx), float(gy), u[r * nc + c], v[r * nc + c],
                             water ? 1.0f : 0.0f, clip[0], clip[1]});
      for (int a2 = 0; a2 < 3; ++a2) {
        box.lo[a2] = std::min(box.lo[a2], p[i][a2]);
        box.hi[a2] = std::max(box.hi[a2], p[i][a2]);
      }
    }
  }
  mesh->box = box;
  mesh->top_km = top_km;
  add_surface_triangles(*mesh, nc, nr);
  mesh->surface_triangles = mesh->indices.size() / 3;
  const auto [bottom, top, left, right] = tile_edges(nc, nr);
  // Only edges inside the extent can meet a tile of another level; the extent's own
  // edges get no skirt (a curtain there would show where the DEM ends at the store's
  // edge, as at the poles of a global DEM).
  if (!globe_) {
    if (s.rows.front() != row0_) add_skirt(*mesh, bottom);
    if (s.rows.back() != row1_) add_skirt(*mesh, top);
    if (s.cols.front() != col0_) add_skirt(*mesh, left);
    if (s.cols.back() != col1_) add_skirt(*mesh, right);
  }
  mesh->load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return mesh;
}

lod::WorldBox TerrainTiles::estimated_box(const TerrainTileKey& key, const lod::WorldBox* parent) const {
  lod::WorldBox box;
  {
    std::lock_guard lock(mutex_);
    if (const auto it = cache_.find(key); it != cache_.end()) return it->second.mesh->box;
    if (const auto it = box_memo_.find(key); it != box_memo_.end()) box = it->second;
  }
  if (box.lo == box.hi) {
    // The horizontal box from eight samples along each edge.
    const auto s = samples(key);
    std::vector<double> cs, rs;
    for (int i = 0; i <= 8; ++i) {
      const double c = double(s.cols.front()) + (double(s.cols.back()) - double(s.cols.front())) * i / 8.0;
      const double r = double(s.rows.front()) + (double(s.rows.back()) - double(s.rows.front())) * i / 8.0;
      for (const auto& [x, y] : {std::pair{c, double(s.rows.front())}, std::pair{c, double(s.rows.back())},
                                 std::pair{double(s.cols.front()), r}, std::pair{double(s.cols.back()), r}}) {
        cs.push_back(x);
        rs.push_back(y);
      }
    }
    if (wrap_columns_) {
      for (auto& c : cs) c = std::fmod(c, double(wrap_columns_));
    }
    std::vector<geo::LonLat> ll(cs.size());
    dem_->georeference(cs, rs, ll);
    box = {{INFINITY, INFINITY, 0}, {-INFINITY, -INFINITY, 0}};
    for (const auto& l : ll) {
      const auto p = place(l);
      for (int a = 0; a < 2; ++a) {
        box.lo[a] = std::min(box.lo[a], p[a]);
        box.hi[a] = std::max(box.hi[a], p[a]);
      }
    }
    std::lock_guard lock(mutex_);
    box_memo_[key] = box;
  }
  // Heights: the parent's range (or 0-5 km before anything is known).
  box.lo[2] = parent ? parent->lo[2] : 0.0;
  box.hi[2] = parent ? parent->hi[2] : 5.0;
  return box;
}

std::shared_ptr<const TerrainFrame> TerrainTiles::update(const lod::Camera& camera,
                                                         double exaggeration, int viewport_height) {
  auto frame = std::make_shared<TerrainFrame>();
  frame->clip = clip_;
  frame->globe = globe_;
  if (!std::isfinite(exaggeration) || !(exaggeration > 0)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "terrain: vertical exaggeration {} must be finite and > 0", exaggeration);
  }
  double redraw = 1.0;  // on the globe: how much higher than placed the tiles are drawn
  if (globe_) {
    frame->gradient_scale = frame_.vertical_exaggeration();
    frame->globe_ratio = redraw = exaggeration / frame_.vertical_exaggeration();
    exaggeration = 1.0;  // the tiles carry the globe's
  }
  const lod::Frustum frustum = lod::view_frustum(camera);
  const double pixels_per_radian =
      double(std::max(viewport_height, 1)) / (2.0 * std::tan(camera.fov_y_deg * std::numbers::pi / 360.0));
  std::vector<std::pair<double, TerrainTileKey>> wanted;  // (priority, key)
  bool complete = true;
  std::lock_guard lock(mutex_);
  const std::uint64_t now = ++frame_counter_;
  const auto loaded = [&](const TerrainTileKey& k) -> const Entry* {
    const auto it = cache_.find(k);
    return it == cache_.end() ? nullptr : &it->second;
  };
  std::vector<TerrainTileKey> stack{TerrainTileKey{}};
  while (!stack.empty()) {
    const TerrainTileKey key = stack.back();
    stack.pop_back();
    Entry* entry = const_cast<Entry*>(loaded(key));
    if (!entry) {
      if (!failed_.contains(key)) {
        wanted.emplace_back(-1e30, key);
        complete = false;
      }
      continue;
    }
    entry->last_used = now;
    const lod::WorldBox box = globe_ ? redrawn_on_globe(entry->mesh->box, entry->mesh->top_km, redraw)
                                     : exaggerated(entry->mesh->box, exaggeration);
    if (options_.cull && !frustum.may_intersect(box)) continue;
    const double distance = std::max(box_distance(box, camera.eye), camera.near_km);
    const auto s = samples(key);
    const double cells = double(std::max<std::size_t>(1, std::max(s.cols.size(), s.rows.size()) - 1));
    const double spacing = std::max(entry->mesh->box.hi[0] - entry->mesh->box.lo[0],
                                    entry->mesh->box.hi[1] - entry->mesh->box.lo[1]) / cells;
    const double error_px = 0.5 * spacing / distance * pixels_per_radian;
    const auto kids = children(key);
    bool split = !kids.empty() && error_px > options_.error_pixels;
    if (split) {
      bool all = true;
      for (const auto& c : kids) {
        // A child that has arrived is in use while it waits for its siblings: evicting
        // it would let a tight cache bound reload it forever (the split never happens).
        if (Entry* child = const_cast<Entry*>(loaded(c))) child->last_used = now;
        if (!loaded(c) && !failed_.contains(c)) {
          all = false;
          wanted.emplace_back(double(c.level) * 1e7 + distance, c);
        }
        if (failed_.contains(c)) split = false;
      }
      if (!all) {
        complete = false;
        split = false;
      }
    }
    if (split) {
      for (const auto& c : kids) stack.push_back(c);
    } else {
      frame->tiles.push_back(entry->mesh);
    }
  }
  std::sort(wanted.begin(), wanted.end());
  queue_.clear();
  for (const auto& [priority, key] : wanted) {
    if (!in_flight_.contains(key)) queue_.push_back(key);
  }
  if (!queue_.empty()) wake_.notify_all();
  complete_ = complete && in_flight_.empty() && queue_.empty();
  selected_ = frame->tiles.size();
  triangles_ = frame->triangles();
  evict();
  return frame;
}

void TerrainTiles::evict() {
  if (cache_bytes_ <= options_.cache_bytes) return;
  std::vector<std::pair<std::uint64_t, TerrainTileKey>> order;
  for (const auto& [k, e] : cache_) {
    if (k.level > 0 && e.last_used < frame_counter_) order.emplace_back(e.last_used, k);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [used, k] : order) {
    if (cache_bytes_ <= options_.cache_bytes) break;
    const auto it = cache_.find(k);
    cache_bytes_ -= it->second.mesh->bytes();
    cache_.erase(it);
  }
}

void TerrainTiles::worker_loop(std::stop_token stop) {
  while (!stop.stop_requested()) {
    TerrainTileKey key;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, stop, [&] { return !queue_.empty(); });
      if (stop.stop_requested()) return;
      key = queue_.front();
      queue_.pop_front();
      if (cache_.contains(key)) continue;
      in_flight_.insert(key);
    }
    std::shared_ptr<const TerrainTileMesh> mesh;
    std::string error;
    try {
      mesh = load_tile(key);
    } catch (const std::exception& e) {
      error = e.what();
    }
    std::lock_guard lock(mutex_);
    in_flight_.erase(key);
    if (mesh) {
      cache_bytes_ += mesh->bytes();
      cache_[key] = Entry{mesh, frame_counter_};
      ++loads_;
      load_ms_ += mesh->load_ms;
    } else {
      failed_.insert(key);
      error_ = error;
      spdlog::warn("terrain tile {}/{}/{}: {}", key.level, key.x, key.y, error);
    }
  }
}

bool TerrainTiles::complete() const {
  std::lock_guard lock(mutex_);
  return complete_;
}

TerrainStatus TerrainTiles::status() const {
  std::lock_guard lock(mutex_);
  TerrainStatus s;
  s.selected = selected_;
  s.triangles = triangles_;
  s.cached = cache_.size();
  s.cache_bytes = cache_bytes_;
  s.loads = loads_;
  s.load_ms = load_ms_;
  s.pending = queue_.size() + in_flight_.size();
  s.complete = complete_;
  s.error = error_;
  return s;
}

void TerrainTiles::set_error_pixels(double pixels) {
  if (pixels > 0) {
    std::lock_guard lock(mutex_);
    options_.error_pixels = pixels;
  }
}

}  // namespace strielad::view
