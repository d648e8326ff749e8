// SPDX-License-Identifier: Apache-2.0
// The only translation unit of the library that instantiates OpenVDB templates.
#include "vdb/level_grid_openvdb.h"

#include <openvdb/io/File.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/error.h"
#include "core/file_io.h"
#include "format/geometry_field.h"
#include "extract/geographic_conditions.h"
#include "extract/node_extraction.h"
#include "grid/longitude_turns.h"
#include "store/level_samples.h"

namespace strielad::vdb {
namespace {

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

void add_axis_metadata(openvdb::GridBase& grid, const char* key, const Axis& axis) {
  const std::string prefix = std::string("strielad:") + key;
  grid.insertMeta(prefix + "_name", openvdb::StringMetadata(axis.name));
  grid.insertMeta(prefix + "_units", openvdb::StringMetadata(axis.units));
  grid.insertMeta(prefix + "_first", openvdb::DoubleMetadata(axis.values.front()));
  grid.insertMeta(prefix + "_last", openvdb::DoubleMetadata(axis.values.back()));
}

// Voxel (i, j, k) is sample (i, j, k) of the level: scaled by the level's stride so that
// levels overlay in level-0 index space.
void set_level_transform(openvdb::GridBase& grid, const LevelShape& shape) {
  openvdb::math::Mat4d scale(openvdb::math::Mat4d::identity());
  scale.preScale(openvdb::Vec3d(double(shape.stride[0]), double(shape.stride[1]),
                                double(shape.stride[2])));
  grid.setTransform(openvdb::math::Transform::createLinearTransform(scale));
}

// Where the grid sits: time step and value, level, axes.
void add_place_metadata(openvdb::GridBase& grid, const format::Manifest& m, std::uint32_t step,
                        std::uint32_t level) {
  grid.insertMeta("strielad:step", openvdb::Int64Metadata(step));
  grid.insertMeta("strielad:time", openvdb::DoubleMetadata(m.time.values.at(step)));
  grid.insertMeta("strielad:time_units", openvdb::StringMetadata(m.time.units));
  grid.insertMeta("strielad:level", openvdb::Int64Metadata(level));
  add_axis_metadata(grid, "x", m.x);
  add_axis_metadata(grid, "y", m.y);
  add_axis_metadata(grid, "z", m.z);
}

// Name, units and long name of variable index `variable`, the grid geometry's field
// (index variables.size(), format/geometry_field.h) included.
struct GridVariable {
  std::string name, units, long_name;
};
GridVariable grid_variable(const format::Manifest& m, std::uint32_t variable) {
  if (variable < m.variables.size()) {
    const auto& v = m.variables[variable];
    return {v.name, v.units, v.long_name};
  }
  if (const auto field = format::geometry_field_variable(m); field && *field == variable) {
    return {format::geometry_field_name(m), m.geometry->vertical.units,
            fmt::format("grid geometry: {} of every sample", format::vertical_quantity_name(
                                                               m.geometry->vertical.quantity))};
  }
  throw make_error(ErrorCode::kNotFound, "variable index {} is not in the store", variable);
}

}  // namespace

openvdb::FloatGrid::Ptr build_level_grid(const Store& store, std::uint32_t step,
                                         std::uint32_t variable, std::uint32_t level,
                                         const LevelGridOptions& options,
                                         LevelGridSummary* summary_out) {
  initialize_openvdb();
  const OctreeLayout& layout = store.octree();
  if (level >= layout.level_count()) {
    throw make_error(ErrorCode::kNotFound, "{}: level {} does not exist (the octree has {} levels)",
                     store.path().string(), level, layout.level_count());
  }
  const GridVariable var = grid_variable(store.manifest(), variable);
  const float background = static_cast<float>(options.background);
  auto grid = openvdb::FloatGrid::create(background);
  grid->setName(var.name);
  const LevelShape& shape = layout.level(level);
  set_level_transform(*grid, shape);

  LevelGridSummary summary;
  summary.min = INFINITY;
  summary.max = -INFINITY;
  auto accessor = grid->getAccessor();
  // Empty bricks and constant ones equal to the background add no active voxel: not read.
  const auto wanted = [background](const format::IndexEntry& entry) {
    return !(entry.kind == format::BrickKind::kEmpty ||
             (entry.kind == format::BrickKind::kConstant &&
              static_cast<float>(entry.constant) == background));
  };
  const LevelBrickCounts counts = for_each_level_brick(store, step, variable, level, [&](const Brick& b) {
    if (b.kind == format::BrickKind::kConstant) {
      const openvdb::CoordBBox box(
          openvdb::Coord(int(b.box.lo[0]), int(b.box.lo[1]), int(b.box.lo[2])),
          openvdb::Coord(int(b.box.hi[0]), int(b.box.hi[1]), int(b.box.hi[2])));
      grid->tree().fill(box, static_cast<float>(b.constant), true);
      summary.min = std::min(summary.min, b.constant);
      summary.max = std::max(summary.max, b.constant);
      return;
    }
    for (std::size_t z = 0; z < b.dims[2]; ++z)
      for (std::size_t y = 0; y < b.dims[1]; ++y)
        for (std::size_t x = 0; x < b.dims[0]; ++x) {
          const double v = b.sample((z * b.dims[1] + y) * b.dims[0] + x);
          if (std::isnan(v) || static_cast<float>(v) == background) continue;
          accessor.setValue(openvdb::Coord(int(b.box.lo[0] + x), int(b.box.lo[1] + y),
                                           int(b.box.lo[2] + z)),
                            static_cast<float>(v));
          summary.min = std::min(summary.min, v);
          summary.max = std::max(summary.max, v);
        }
  }, wanted);
  summary.bricks_read = counts.bricks_read;
  summary.bricks_skipped = counts.bricks_skipped;
  grid->pruneGrid();
  summary.active_voxels = grid->activeVoxelCount();
  if (summary.active_voxels == 0) summary.min = summary.max = 0;
  grid->setGridClass(summary.min >= 0 ? openvdb::GRID_FOG_VOLUME : openvdb::GRID_UNKNOWN);
  const auto& m = store.manifest();
  grid->insertMeta("strielad:variable", openvdb::StringMetadata(var.name));
  grid->insertMeta("strielad:units", openvdb::StringMetadata(var.units));
  grid->insertMeta("strielad:long_name", openvdb::StringMetadata(var.long_name));
  add_place_metadata(*grid, m, step, level);
  if (summary_out) *summary_out = summary;
  return grid;
}

namespace {

// Every limit holds at sample value v of each limit's brick (NaN = missing: outside).
bool inside_limits(const std::vector<const Brick*>& bricks, const ResolvedSubVolume& sv,
                   std::size_t i) {
  for (std::size_t k = 0; k < sv.limits.size(); ++k) {
    const double v = bricks[k]->sample(i);
    if (!(v >= sv.limits[k].min && v <= sv.limits[k].max)) return false;
  }
  return true;
}

// The sub-volume with its geographic height range (terrain-following levels) as a limit
// on the geometry's height field: per sample the two are the same test.
ResolvedSubVolume height_as_limit(const ResolvedSubVolume& sv, const format::Manifest& m) {
  ResolvedSubVolume out = sv;
  if (sv.geometry_height) {
    out.limits.push_back(ResolvedLimit{*format::geometry_field_variable(m), sv.geometry_height->lo,
                                       sv.geometry_height->hi});
  }
  return out;
}

void write_grids(const openvdb::GridCPtrVec& grids, const std::filesystem::path& out) {
  const auto temp = temporary_sibling(out);
  try {
    openvdb::io::File file(temp.string());
    file.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
    file.write(grids);
    file.close();
  } catch (const openvdb::Exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw make_error(ErrorCode::kIo, "{}: cannot write VDB file: {}", out.string(), e.what());
  }
  std::filesystem::rename(temp, out);
}

}  // namespace

std::vector<SubVolumeGridSummary> write_subvolume_vdb(const Store& store,
                                                      const ResolvedScene& scene,
                                                      std::uint32_t level,
                                                      const std::filesystem::path& out) {
  initialize_openvdb();
  const OctreeLayout& layout = store.octree();
  if (level >= layout.level_count()) {
    throw make_error(ErrorCode::kNotFound, "{}: level {} does not exist (the octree has {} levels)",
                     store.path().string(), level, layout.level_count());
  }
  const LevelShape& shape = layout.level(level);
  const auto& m = store.manifest();
  const std::uint32_t step = scene.time;
  openvdb::GridCPtrVec grids;
  std::vector<SubVolumeGridSummary> summaries;
  for (const ResolvedSubVolume& given : scene.subvolumes) {
    const ResolvedSubVolume sv = height_as_limit(given, m);
    SubVolumeGridSummary summary;
    summary.subvolume_id = sv.id;
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(sv.name.empty() ? fmt::format("subvolume-{}", sv.id) : sv.name);
    set_level_transform(*grid, shape);
    auto accessor = grid->getAccessor();
    for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
      const NodeKey key = layout.key(n);
      const IndexBox box = layout.level_box(key);
      // Skip from the index alone: a limit's range misses the node's, or no valid data.
      bool skip = false;
      for (const ResolvedLimit& limit : sv.limits) {
        skip = skip || limit_excludes_node(store.node_entry(step, limit.variable, n), limit);
      }
      // Domain box per axis, as sample index ranges of this level.
      std::array<std::array<std::size_t, 2>, 3> range{};
      const std::array<const Axis*, 3> axes{&m.x, &m.y, &m.z};
      for (int a = 0; a < 3 && !skip; ++a) {
        range[a] = {box.hi[a] + 1, box.lo[a]};  // empty until a sample fits
        // A longitude range holds a sample at any whole turn (grid/longitude_turns.h).
        const bool turns = a == 0 && m.x.kind == AxisKind::kLongitude &&
                           std::isfinite(sv.box[0].lo) && std::isfinite(sv.box[0].hi);
        for (std::size_t c = box.lo[a]; c <= box.hi[a]; ++c) {
          const double coord = axes[a]->values[layout.fine_index(level, a, c)];
          const bool inside = turns ? !longitude_turns(sv.box[0].lo, sv.box[0].hi, coord, coord).empty()
                                    : coord >= sv.box[a].lo && coord <= sv.box[a].hi;
          if (inside) {
            range[a][0] = std::min(range[a][0], c);
            range[a][1] = std::max(range[a][1], c);
          }
        }
        skip = range[a][0] > range[a][1];
      }
      // A geographic box on a mapped grid: its conditions at the node's horizontal samples.
      std::vector<std::vector<double>> geographic;
      if (!skip && sv.geographic) {
        std::array<std::vector<std::size_t>, 2> fine;
        for (int a = 0; a < 2; ++a) {
          for (std::size_t c = box.lo[a]; c <= box.hi[a]; ++c) fine[a].push_back(layout.fine_index(level, a, c));
        }
        geographic = geographic_conditions(*sv.geographic, *GeoLocation::of(store), fine[0], fine[1]);
      }
      if (skip) {
        ++summary.nodes_skipped;
        continue;
      }
      std::vector<Brick> bricks;
      bricks.reserve(sv.limits.size());
      for (const ResolvedLimit& limit : sv.limits) {
        bricks.push_back(store.read_brick(step, limit.variable, n));
        ++summary.bricks_read;
      }
      std::vector<const Brick*> ptrs;
      for (const Brick& b : bricks) ptrs.push_back(&b);
      const std::size_t nx = box.extent(0), ny = box.extent(1);
      for (std::size_t z = range[2][0]; z <= range[2][1]; ++z)
        for (std::size_t y = range[1][0]; y <= range[1][1]; ++y)
          for (std::size_t x = range[0][0]; x <= range[0][1]; ++x) {
            const std::size_t i =
                ((z - box.lo[2]) * ny + (y - box.lo[1])) * nx + (x - box.lo[0]);
            const std::size_t h = (y - box.lo[1]) * nx + (x - box.lo[0]);
            const bool in_geographic = std::all_of(geographic.begin(), geographic.end(),
                                                   [h](const auto& c) { return c[h] >= 0; });
            if (in_geographic && inside_limits(ptrs, sv, i)) {
              accessor.setValue(openvdb::Coord(int(x), int(y), int(z)), 1.0f);
            }
          }
    }
    grid->pruneGrid();
    summary.active_voxels = grid->activeVoxelCount();
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->insertMeta("strielad:subvolume_id", openvdb::Int64Metadata(sv.id));
    add_place_metadata(*grid, m, step, level);
    grids.push_back(grid);
    summaries.push_back(summary);
  }
  write_grids(grids, out);
  return summaries;
}

LevelGridSummary write_level_vdb(const Store& store, std::uint32_t step, std::uint32_t variable,
                                 std::uint32_t level, const std::filesystem::path& out,
                                 const LevelGridOptions& options) {
  LevelGridSummary summary;
  auto grid = build_level_grid(store, step, variable, level, options, &summary);
  write_grids(openvdb::GridCPtrVec{grid}, out);
  return summary;
}

}  // namespace strielad::vdb
