// SPDX-License-Identifier: Apache-2.0
// The terrain's level-of-detail height field: a quadtree of tiles
// over the part of a DEM (scenery/dem_source.h) that overlaps the store's domain (the DEM
// samples whose true longitude/latitude falls inside the store's axis box, through the
// grid mapping on a mapped grid), each tile kTerrainTileCells x kTerrainTileCells cells
// of the DEM sampled at its level's stride (the finest level takes every sample), placed
// in the store's world frame (lod/world_frame.h) by each sample's true longitude and
// latitude from the DEM's own georeferencing (WorldFrame::geographic_to_world), heights
// in km so that the renderer's vertical exaggeration lifts terrain and clouds alike.
//
// - Selection (every frame, TerrainTiles::update): from the root, a tile in the view
//   frustum is split while its screen-space error, error_km * viewport height /
//   (2 distance tan(fov / 2)), exceeds error_pixels; a tile's error is half its sample
//   spacing in km (the geometric error of a height field sampled at that spacing, taken
//   as proportional to it). A tile is replaced by its children only when all four are
//   loaded: until then the coarser parent is drawn, so a frame never waits and never
//   has holes. Each point of the extent is covered by exactly one selected tile.
// - Loading: missing tiles are requested (coarsest, then nearest first) from one
//   background thread that reads their DEM windows (strided reads) and builds their
//   meshes; requests not wanted any more are dropped. Loaded tiles stay in a cache
//   bounded in bytes (least recently selected out first; the root stays).
// - Cracks between tiles of different levels are hidden by skirts: every tile edge
//   inside the extent hangs a strip down by the tile's height range (the extent's own
//   edges meet no other tile and hang none).
// - Water rule: samples without a value (fill, nodata, sea without data) and samples
//   below sea level (the sea of a DEM with bathymetry, such as ETOPO or GEBCO) are drawn
//   flat at height 0 (sea level) and flagged, so the drawing colours them as water; no
//   triangle is dropped, so the surface stays closed. Land below sea level is drawn as
//   water too (a height alone does not tell it from the sea).
// - Global DEMs: a longitude/latitude grid that goes all the way round (longitude affine
//   in the column, one full turn of columns or more) is read as if its columns repeated
//   every turn, so the extent runs continuously from the store's western edge to its
//   eastern one wherever the DEM's columns start (an ETOPO grid from -180 to 180 under a
//   store from 0 to 357.5 degrees east); the tiles never span the turn, where placed
//   longitudes jump by 360 degrees.
// - Normals come from per-vertex height gradients (central differences over the tile's
//   samples plus a ring of neighbours, so shading is continuous across tile edges); the
//   renderer turns them into normals at the current exaggeration.
// - On the globe (lod/world_frame.h): positions are ECEF km at the frame's exaggeration
//   (placed, as the meshes are: the renderer scales nothing), gradients are east/north
//   in true km per km from each sample's own neighbours, the drawing turns them into
//   normals in the local east/north/up frame, clip coordinates are the store's axis
//   x/y, and tiles hang no skirts (their edges are not straight down on a globe: cracks
//   between tiles of different levels may show as hairlines).
#pragma once

#include <atomic>
#include <compare>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "scenery/dem_source.h"
#include "scenery/drape_image.h"
#include "lod/camera.h"
#include "lod/world_frame.h"

namespace strielad::view {

inline constexpr int kTerrainTileCells = 64;  // 65 x 65 vertices per tile
inline constexpr double kDefaultTerrainErrorPixels = 2.0;
inline constexpr std::size_t kDefaultTerrainCacheBytes = 256ull << 20;
// Per vertex: x, y (world km), height (km, 0 on water), dh/dx, dh/dy (km per km),
// u, v (drape texture; < 0 off the image), water (1 or 0: no value or below sea level),
// clip x, clip y (the coordinates TerrainFrame::clip bounds: world x/y on a geographic
// frame, the store's axis x/y on a mapped one; far outside where the store's axes do
// not reach).
inline constexpr int kTerrainVertexFloats = 10;

struct TerrainTileKey {
  int level = 0, x = 0, y = 0;
  friend auto operator<=>(const TerrainTileKey&, const TerrainTileKey&) = default;
};

// DEM samples of a tile: columns and rows (indices into the DEM), the last one of each
// clamped to the extent's edge.
struct TerrainTileSamples {
  std::vector<std::size_t> cols, rows;
};

struct TerrainTileMesh {
  TerrainTileKey key;
  std::uint64_t serial = 0;           // unique per load in the process (GPU caches key on it)
  std::vector<float> vertices;        // kTerrainVertexFloats per vertex
  std::vector<std::uint32_t> indices; // triangles, skirts included
  std::size_t surface_triangles = 0;  // without the skirts
  lod::WorldBox box;                  // world km, z = height km (exaggeration 1)
  double top_km = 0;                  // on the globe: the highest vertex's height as placed
  geo::DrapePatch drape;              // empty without a drape image
  double load_ms = 0;
  std::size_t bytes() const {
    return vertices.size() * sizeof(float) + indices.size() * sizeof(std::uint32_t) +
           drape.rgba.size() + sizeof(*this);
  }
  std::size_t triangles() const { return indices.size() / 3; }
};

// What the renderer draws of the terrain in one frame.
struct TerrainFrame {
  std::vector<std::shared_ptr<const TerrainTileMesh>> tiles;
  // The box in clip coordinates (x and y; kTerrainVertexFloats) the terrain is cut to:
  // the store's domain. World km on a geographic frame; on a mapped frame the store's
  // axis box (rlon/rlat, projected x/y), whose image in the world is a curved shape.
  lod::WorldBox clip;
  // On the globe: positions are ECEF with their heights placed at the frame's
  // exaggeration, which is gradient_scale, and drawn at globe_ratio times it
  // (render/wgs84_glsl.h globe_redrawn).
  bool globe = false;
  double gradient_scale = 1.0;
  double globe_ratio = 1.0;
  std::size_t triangles() const {
    std::size_t n = 0;
    for (const auto& t : tiles) n += t->triangles();
    return n;
  }
};

struct TerrainOptions {
  double error_pixels = kDefaultTerrainErrorPixels;  // > 0
  std::size_t cache_bytes = kDefaultTerrainCacheBytes;
  bool cull = true;  // frustum culling (tests turn it off to see the whole cover)
  // The store's longitude axis goes round the Earth (Axis::periodic). On the globe a DEM
  // that goes round is then drawn all the way round, its longitudes unclipped; else the
  // extent keeps 1.5 columns off the turn opposite the frame's centre, as on the plane.
  bool round_the_earth = false;
};

struct TerrainStatus {
  std::size_t selected = 0;         // tiles of the last selection
  std::size_t triangles = 0;
  std::size_t cached = 0;           // tiles loaded and kept
  std::size_t cache_bytes = 0;
  std::size_t loads = 0;            // tiles loaded so far
  double load_ms = 0;               // their total load time (background thread)
  std::size_t pending = 0;          // requested, not yet loaded
  bool complete = false;            // the last selection needed nothing missing
  std::string error;                // the last load error (the tile is left out)
};

class TerrainTiles {
 public:
  // \error kUnsupported when the frame has no place on the Earth (a Cartesian grid
  // without a grid mapping: WorldFrame::no_earth_reason); kInvalidInput when the DEM does
  // not overlap the store's extent (naming both extents).
  TerrainTiles(std::shared_ptr<const geo::DemSource> dem, const lod::WorldFrame& frame,
               TerrainOptions options = {}, std::shared_ptr<const geo::DrapeImage> drape = nullptr);
  ~TerrainTiles();
  TerrainTiles(const TerrainTiles&) = delete;
  TerrainTiles& operator=(const TerrainTiles&) = delete;

  // Selects the tiles for `camera` (world frame at `exaggeration`) on a viewport
  // `viewport_height` pixels high, requests the missing ones, never waits. On the globe
  // the tiles keep the exaggeration they were placed at (the frame's), and the frame
  // says how much higher `exaggeration` draws them.
  // \error kInvalidArgument when `exaggeration` is not finite and > 0.
  std::shared_ptr<const TerrainFrame> update(const lod::Camera& camera, double exaggeration,
                                             int viewport_height);
  // Whether the last update's selection is final (every tile it wants is loaded).
  bool complete() const;
  TerrainStatus status() const;
  void set_error_pixels(double pixels);

  // The quadtree (for tests and the panel).
  int finest_level() const { return finest_level_; }
  // DEM sample extent covered: first and last column and row (inclusive). Columns of a
  // global DEM may count on past its last one (wrap_columns()).
  std::array<std::size_t, 4> extent() const { return {col0_, row0_, col1_, row1_}; }
  // DEM columns per turn of longitude when the quadtree's columns go round (column c
  // is the DEM's c mod wrap_columns()); 0 when they do not.
  std::size_t wrap_columns() const { return wrap_columns_; }
  bool exists(const TerrainTileKey& key) const;
  std::vector<TerrainTileKey> children(const TerrainTileKey& key) const;
  TerrainTileSamples samples(const TerrainTileKey& key) const;
  // Builds a tile's mesh now, on the calling thread.
  std::shared_ptr<const TerrainTileMesh> load_tile(const TerrainTileKey& key) const;

 private:
  struct Entry {
    std::shared_ptr<const TerrainTileMesh> mesh;
    std::uint64_t last_used = 0;
  };
  std::size_t stride(int level) const { return std::size_t{1} << (finest_level_ - level); }
  lod::WorldBox estimated_box(const TerrainTileKey& key, const lod::WorldBox* parent) const;
  Vec3 place(const geo::LonLat& ll) const;
  std::array<float, 2> clip_coordinates(const geo::LonLat& ll, const Vec3& world) const;
  std::size_t dem_column(std::size_t column) const;
  std::vector<std::size_t> dem_columns(std::vector<std::size_t> columns) const;
  void worker_loop(std::stop_token stop);
  void evict();

  std::shared_ptr<const geo::DemSource> dem_;
  std::shared_ptr<const geo::DrapeImage> drape_;
  lod::WorldFrame frame_;  // a copy: x/y do not depend on the exaggeration
  TerrainOptions options_;
  std::size_t col0_ = 0, row0_ = 0, col1_ = 0, row1_ = 0;
  std::size_t wrap_columns_ = 0;
  int finest_level_ = 0;
  lod::WorldBox clip_;
  bool mapped_ = false;  // the frame bends grid lines: clip coordinates are axis x/y
  bool globe_ = false;   // positions in ECEF at the frame's exaggeration

  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  std::map<TerrainTileKey, Entry> cache_;
  std::size_t cache_bytes_ = 0;
  std::deque<TerrainTileKey> queue_;         // wanted, in order
  std::set<TerrainTileKey> in_flight_;
  std::uint64_t frame_counter_ = 0;
  bool complete_ = false;
  std::size_t loads_ = 0;
  double load_ms_ = 0;
  std::size_t selected_ = 0, triangles_ = 0;
  std::string error_;
  std::set<TerrainTileKey> failed_;
  mutable std::map<TerrainTileKey, lod::WorldBox> box_memo_;
  std::jthread worker_;
};

}  // namespace strielad::view
